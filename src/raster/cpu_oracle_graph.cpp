// CpuOracle's occlusion graph of a stuck set in one pass (cpu_oracle_impl.h, occlusion_oracle.h):
// every member's fragments listed per pixel, a strip of tile rows at a time, and ordered there by
// depth; consecutive depths give the edges.
//
// Why the edges have the true graph's reachability: at a pixel, sort the members' fragments by
// depth. Whenever front -> back is an occlusion (a fragment of front strictly nearer than one of
// back at some pixel), the fragments between those two at that pixel form a chain in which each
// is nearer than or level with the next; an edge between every two consecutive depth levels
// connects front to back through members each of which truly occludes the next. Levels are
// found in two steps: the floats with their error bounds split a pixel's fragments into
// clusters, each certainly nearer than the next (every fragment of one above every error bound
// of the one before); within a cluster, the exact model (DepthArbiter, which caches what holds
// for a whole pair of triangles) decides each pair. So the edges are: every member of a cluster
// to every member of the next, and within a cluster each pair the exact model finds strictly
// ordered.

#include "raster/cpu_oracle_impl.h"

#include <optional>

namespace vissort {
namespace {

// Members beyond this are left to the group tests: each band's seen-edge matrix holds n^2 bits
// (8 MiB here), and a stuck set that large is rare (the ten-times power plant's is 2,420).
constexpr std::size_t kMaxGraphMembers = 8192;

struct Fragment {
    uint32_t pixel; // within the strip: (py - first row) * width + px
    uint32_t item;  // its set-up's entry of occlusionGraph's active items
    uint32_t member;
    float depth, error;
    double nearEnd() const { return double(depth) - double(error); }
    double farEnd() const { return double(depth) + double(error); }
};

} // namespace

bool CpuOracle::Impl::occlusionGraph(std::span<const uint32_t> members,
                                     std::vector<Occlusion>& edges) {
    if (!exactRule() || members.size() > kMaxGraphMembers || width_ == 0 || height_ == 0)
        return false;
    const std::size_t n = members.size();
    // The members' set-ups by their first row: a sweep down the strips keeps the active ones.
    struct Item {
        uint32_t setup, member;
        uint16_t py_min, py_max; // the set-up's, read by the sweep without its cache lines
    };
    std::vector<Item> items;
    for (uint32_t m = 0; m < n; ++m) {
        assert(members[m] < primitive_count_);
        for (uint32_t k = primitive_setups_[members[m]]; k < primitive_setups_[members[m] + 1]; ++k)
            items.push_back({k, m, setups_[k].py_min, setups_[k].py_max});
    }
    std::sort(items.begin(), items.end(),
              [](const Item& a, const Item& b) { return a.py_min < b.py_min; });
    // Bands of strips, one a thread where the oracle has threads (runBands), each with its own
    // edges, deduplicated by its own bit a pair of members, and its own count of the pairs it
    // visits, summed against a budget: a guard against pixels where ties stack (hundreds of
    // copies of a face in as many members), which the group tests handle without squaring. The
    // edges are merged and sorted, and the sum does not depend on the bands, so the answer is
    // the same for every thread count.
    const uint32_t strip_rows = kTileSize;
    const uint32_t strips = (height_ + strip_rows - 1) / strip_rows;
    const uint32_t bands = std::min(bandsFor(items.size()), strips);
    struct BandGraph {
        std::vector<uint64_t> seen;
        std::vector<Occlusion> edges;
        uint64_t pairs = 0;
    };
    const uint64_t budget = 64 * uint64_t(items.size()) + (uint64_t(1) << 24);
    std::vector<BandGraph> band_graphs(bands);
    const auto band = [&](uint32_t b, CpuOracleStats&) {
        BandGraph& graph = band_graphs[b];
        graph.seen.assign((n * n + 63) / 64, 0);
        std::vector<uint64_t>& seen = graph.seen;
        const auto addEdge = [&](uint32_t front, uint32_t back) {
            if (front == back)
                return;
            const std::size_t bit = std::size_t(front) * n + back;
            if ((seen[bit >> 6] >> (bit & 63) & 1) == 0) {
                seen[bit >> 6] |= uint64_t(1) << (bit & 63);
                graph.edges.push_back({front, back});
            }
        };
        std::vector<Item> active;
        std::vector<Fragment> fragments, sorted;
        std::vector<uint32_t> starts;
        std::vector<uint32_t> before, cluster_members; // the previous cluster's members, this one's
        std::vector<std::optional<detail::DepthArbiter::Query>> queries;
        std::size_t next_item = 0;
        const uint32_t strip_first = uint32_t(uint64_t(b) * strips / bands);
        const uint32_t strip_end = uint32_t(uint64_t(b + 1) * strips / bands);
        for (uint32_t y_first = strip_first * strip_rows;
             y_first < std::min(strip_end * strip_rows, height_); y_first += strip_rows) {
            const uint32_t y_end = std::min(y_first + strip_rows, height_);
            while (next_item < items.size() && items[next_item].py_min < y_end)
                active.push_back(items[next_item++]);
            std::erase_if(active, [&](const Item& i) { return i.py_max < y_first; });
            // The strip's fragments: certain pixels, then the band pixels not certain.
            fragments.clear();
            for (const Item& item : active) {
                const StoredSetup& s = setups_[item.setup];
                const float error = errors_[item.setup];
                const uint32_t item_index = uint32_t(&item - active.data());
                const auto add = [&](uint32_t px, uint32_t py) {
                    fragments.push_back({(py - y_first) * width_ + px, item_index, item.member,
                                         fragmentAt(s, px, py), error});
                };
                const uint32_t row_first = std::max<uint32_t>(y_first, s.py_min);
                const uint32_t row_last = std::min<uint32_t>(y_end - 1, s.py_max);
                for (uint32_t py = row_first, x_first, x_last; py <= row_last; ++py)
                    if (certainRowSpan(s, py, x_first, x_last))
                        for (uint32_t px = x_first; px <= x_last; ++px)
                            add(px, py);
                if (s.band_first == 0)
                    continue;
                const uint32_t* const band_first = band_pixels_.data() + s.band_first + 1;
                const uint32_t* const band_end = band_first + band_pixels_[s.band_first];
                for (const uint32_t* at = std::lower_bound(band_first, band_end, y_first << 16);
                     at != band_end && (*at >> 16) < y_end; ++at)
                    if (!certainlyCovers(s, *at & 0xFFFF, *at >> 16))
                        add(*at & 0xFFFF, *at >> 16);
            }
            if (fragments.empty())
                continue;
            // By pixel (a counting sort), then each pixel's by the near end of its depth.
            const std::size_t pixels = std::size_t(y_end - y_first) * width_;
            starts.assign(pixels + 1, 0);
            for (const Fragment& f : fragments)
                ++starts[f.pixel + 1];
            for (std::size_t p = 0; p < pixels; ++p)
                starts[p + 1] += starts[p];
            sorted.resize(fragments.size());
            for (const Fragment& f : fragments)
                sorted[starts[f.pixel]++] = f;
            for (std::size_t p = pixels; p > 0; --p)
                starts[p] = starts[p - 1];
            starts[0] = 0;
            for (std::size_t p = 0; p < pixels; ++p) {
                const auto first = sorted.begin() + starts[p], end = sorted.begin() + starts[p + 1];
                if (end - first < 2)
                    continue;
                // One member's fragments alone (an object's front and back) order nothing.
                const uint32_t first_member = first->member;
                if (std::all_of(first, end,
                                [&](const Fragment& f) { return f.member == first_member; }))
                    continue;
                std::sort(first, end, [](const Fragment& a, const Fragment& b) {
                    return a.nearEnd() < b.nearEnd();
                });
                const uint32_t px = uint32_t(p % width_), py = y_first + uint32_t(p / width_);
                before.clear();
                for (auto c = first; c != end;) {
                    // The cluster: fragments whose error intervals chain from c's.
                    auto c_end = c + 1;
                    double far_end = c->farEnd();
                    while (c_end != end && c_end->nearEnd() <= far_end)
                        far_end = std::max(far_end, (c_end++)->farEnd());
                    cluster_members.clear();
                    for (auto f = c; f != c_end; ++f)
                        if (std::find(cluster_members.begin(), cluster_members.end(), f->member) ==
                            cluster_members.end())
                            cluster_members.push_back(f->member);
                    const uint64_t pairs = uint64_t(before.size()) * cluster_members.size() +
                                           uint64_t(c_end - c) * uint64_t(c_end - c);
                    graph.pairs += pairs;
                    if (graph.pairs > budget)
                        return; // over for the whole graph too: nothing more to find
                    for (uint32_t front : before)
                        for (uint32_t back : cluster_members)
                            addEdge(front, back);
                    if (cluster_members.size() > 1) {
                        // Each pair of distinct members' fragments, by the exact model (whose pair
                        // cache answers touching and coplanar faces without arithmetic), unless the
                        // edge it could give is known already.
                        const std::size_t size = std::size_t(c_end - c);
                        queries.assign(size, std::nullopt);
                        for (std::size_t i = 0; i < size; ++i) {
                            const Fragment& back = c[i];
                            for (std::size_t j = 0; j < size; ++j) {
                                const Fragment& front = c[j];
                                if (front.member == back.member)
                                    continue;
                                const std::size_t bit = std::size_t(front.member) * n + back.member;
                                if (seen[bit >> 6] >> (bit & 63) & 1)
                                    continue; // the edge is known already
                                if (!queries[i])
                                    queries[i] = arbiter_.query(
                                        setups_[active[back.item].setup].triangle(), px, py);
                                if (arbiter_.nearnessCovering(
                                        *queries[i],
                                        setups_[active[front.item].setup].triangle()) ==
                                    detail::DepthArbiter::Nearness::nearer)
                                    addEdge(front.member, back.member);
                            }
                        }
                    }
                    before.swap(cluster_members);
                    c = c_end;
                }
            }
        }
    };
    if (bands <= 1)
        band(0, stats_);
    else
        runBands(bands, band);
    // The bands' edges, each pair once.
    uint64_t pairs = 0;
    for (const BandGraph& graph : band_graphs)
        pairs += graph.pairs;
    if (pairs > budget)
        return false;
    std::vector<uint64_t>& seen = band_graphs[0].seen;
    const std::size_t first_edge = edges.size();
    edges.insert(edges.end(), band_graphs[0].edges.begin(), band_graphs[0].edges.end());
    for (uint32_t b = 1; b < bands; ++b)
        for (const Occlusion& e : band_graphs[b].edges) {
            const std::size_t bit = std::size_t(e.front) * n + e.back;
            if ((seen[bit >> 6] >> (bit & 63) & 1) == 0) {
                seen[bit >> 6] |= uint64_t(1) << (bit & 63);
                edges.push_back(e);
            }
        }
    std::sort(edges.begin() + std::ptrdiff_t(first_edge), edges.end(),
              [](const Occlusion& a, const Occlusion& b) {
                  return a.front != b.front ? a.front < b.front : a.back < b.back;
              });
    return true;
}

} // namespace vissort
