// Ground truth by brute force over the exact fragments: every pair of primitives at every pixel.

#include "ground_truth.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <unordered_set>

#include "tarjan_scc.h"

namespace vissort::test {
namespace {

constexpr uint32_t kNoPrimitive = std::numeric_limits<uint32_t>::max();

// One primitive's fragments at one pixel: the ranks of its nearest and farthest, and their
// approximate depths. a is in front of b there iff a.nearest_rank < b.farthest_rank.
struct PixelSpan {
    uint32_t primitive;
    uint32_t nearest_rank, farthest_rank;
    double nearest_depth, farthest_depth;
};

bool inFront(const PixelSpan& front, const PixelSpan& behind) {
    return front.primitive != behind.primitive && front.nearest_rank < behind.farthest_rank;
}

std::vector<uint32_t> primitiveOfTriangles(std::size_t triangle_count,
                                           std::span<const PrimitiveRange> primitives) {
    std::vector<uint32_t> primitive_of(triangle_count, kNoPrimitive);
    for (uint32_t p = 0; p < primitives.size(); ++p) {
        const PrimitiveRange& range = primitives[p];
        assert(uint64_t(range.first_triangle) + range.triangle_count <= triangle_count);
        for (uint32_t t = 0; t < range.triangle_count; ++t)
            primitive_of[range.first_triangle + t] = p;
    }
    return primitive_of;
}

// Calls visit(px, py, spans) for every pixel with the spans of each primitive there.
template <class Visit>
void forEachPixel(const ExactFragments& fragments, std::size_t triangle_count,
                  std::span<const PrimitiveRange> primitives, Visit&& visit) {
    const std::vector<uint32_t> primitive_of = primitiveOfTriangles(triangle_count, primitives);
    std::vector<uint32_t> span_of(primitives.size(), kNoPrimitive); // kNoPrimitive between pixels
    std::vector<PixelSpan> spans;
    for (std::size_t pixel = 0; pixel < fragments.pixelCount(); ++pixel) {
        spans.clear();
        // Fragments come nearest first: the first of a primitive is its nearest, the last its
        // farthest.
        for (uint64_t f = fragments.firstFragment(pixel); f < fragments.endFragment(pixel); ++f) {
            const uint32_t p = primitive_of[fragments.triangles[f]];
            if (p == kNoPrimitive)
                continue;
            const uint32_t rank = fragments.ranks[f];
            const double d = fragments.depths[f];
            if (span_of[p] == kNoPrimitive) {
                span_of[p] = uint32_t(spans.size());
                spans.push_back({p, rank, rank, d, d});
            } else {
                spans[span_of[p]].farthest_rank = rank;
                spans[span_of[p]].farthest_depth = d;
            }
        }
        for (const PixelSpan& span : spans)
            span_of[span.primitive] = kNoPrimitive;
        visit(uint32_t(pixel % fragments.width), uint32_t(pixel / fragments.width),
              std::span<const PixelSpan>(spans));
    }
}

bool isPermutation(std::span<const uint32_t> order, std::size_t n) {
    if (order.size() != n)
        return false;
    std::vector<bool> seen(n, false);
    for (uint32_t id : order) {
        if (id >= n || seen[id])
            return false;
        seen[id] = true;
    }
    return true;
}

} // namespace

OrderCheck checkVisibilityOrder(const TrianglePositions& positions, const ViewProjection& view,
                                std::span<const PrimitiveRange> primitives,
                                std::span<const uint32_t> order,
                                const std::vector<std::vector<uint32_t>>& cycles,
                                std::size_t max_violations_kept) {
    if (!isPermutation(order, primitives.size()))
        return {};
    return checkVisibilityOrder(exactFragments(positions, view), positions.triangleCount(),
                                primitives, order, cycles, max_violations_kept);
}

OrderCheck checkVisibilityOrder(const ExactFragments& fragments, std::size_t triangle_count,
                                std::span<const PrimitiveRange> primitives,
                                std::span<const uint32_t> order,
                                const std::vector<std::vector<uint32_t>>& cycles,
                                std::size_t max_violations_kept) {
    OrderCheck check;
    const std::size_t n = primitives.size();
    check.valid_permutation = isPermutation(order, n);
    if (!check.valid_permutation)
        return check;

    std::vector<uint32_t> position(n);
    for (uint32_t i = 0; i < n; ++i)
        position[order[i]] = i;
    // A primitive could be listed in more than one declared cycle; keep all its cycle ids.
    std::vector<std::vector<uint32_t>> cycles_of(n);
    for (uint32_t c = 0; c < cycles.size(); ++c) {
        for (uint32_t p : cycles[c]) {
            assert(p < n);
            cycles_of[p].push_back(c);
        }
    }
    const auto inOneCycle = [&](uint32_t a, uint32_t b) {
        for (uint32_t c : cycles_of[a]) {
            if (std::find(cycles_of[b].begin(), cycles_of[b].end(), c) != cycles_of[b].end())
                return true;
        }
        return false;
    };

    forEachPixel(fragments, triangle_count, primitives,
                 [&](uint32_t px, uint32_t py, std::span<const PixelSpan> spans) {
                     check.max_depth_complexity =
                         std::max(check.max_depth_complexity, uint32_t(spans.size()));
                     for (const PixelSpan& front : spans) {
                         for (const PixelSpan& behind : spans) {
                             if (!inFront(front, behind))
                                 continue;
                             ++check.pairs_checked;
                             if (position[behind.primitive] > position[front.primitive] ||
                                 inOneCycle(front.primitive, behind.primitive))
                                 continue;
                             ++check.violation_count;
                             if (check.violations.size() < max_violations_kept) {
                                 check.violations.push_back({px, py, front.primitive,
                                                             behind.primitive, front.nearest_depth,
                                                             behind.farthest_depth});
                             }
                         }
                     }
                 });
    return check;
}

std::vector<std::vector<uint32_t>> occlusionGraph(const TrianglePositions& positions,
                                                  const ViewProjection& view,
                                                  std::span<const PrimitiveRange> primitives) {
    return occlusionGraph(exactFragments(positions, view), positions.triangleCount(), primitives);
}

std::vector<std::vector<uint32_t>> occlusionGraph(const ExactFragments& fragments,
                                                  std::size_t triangle_count,
                                                  std::span<const PrimitiveRange> primitives) {
    // The edges seen so far: a bit matrix up to kMaxMatrixPrimitives (32 MiB), a hash set above.
    constexpr std::size_t kMaxMatrixPrimitives = 16384;
    const std::size_t n = primitives.size();
    const bool use_matrix = n <= kMaxMatrixPrimitives;
    std::vector<uint64_t> matrix(use_matrix ? (n * n + 63) / 64 : 0);
    std::unordered_set<uint64_t> edges;
    forEachPixel(fragments, triangle_count, primitives,
                 [&](uint32_t, uint32_t, std::span<const PixelSpan> spans) {
                     for (const PixelSpan& front : spans) {
                         for (const PixelSpan& behind : spans) {
                             if (!inFront(front, behind))
                                 continue;
                             if (use_matrix) {
                                 const std::size_t bit = front.primitive * n + behind.primitive;
                                 matrix[bit / 64] |= uint64_t(1) << (bit % 64);
                             } else {
                                 edges.insert(uint64_t(front.primitive) << 32 | behind.primitive);
                             }
                         }
                     }
                 });
    std::vector<std::vector<uint32_t>> graph(n);
    if (use_matrix) {
        for (std::size_t a = 0; a < n; ++a) {
            for (std::size_t b = 0; b < n; ++b) {
                const std::size_t bit = a * n + b;
                if (matrix[bit / 64] >> (bit % 64) & 1)
                    graph[a].push_back(uint32_t(b));
            }
        }
        return graph;
    }
    for (uint64_t edge : edges)
        graph[edge >> 32].push_back(uint32_t(edge));
    for (std::vector<uint32_t>& successors : graph)
        std::sort(successors.begin(), successors.end());
    return graph;
}

std::vector<std::vector<uint32_t>> occlusionCycles(const TrianglePositions& positions,
                                                   const ViewProjection& view,
                                                   std::span<const PrimitiveRange> primitives) {
    return cyclicComponents(occlusionGraph(positions, view, primitives));
}

} // namespace vissort::test
