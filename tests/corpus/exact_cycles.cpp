#include "exact_cycles.h"

#include <algorithm>

#include "tarjan_scc.h"
#include "vissort/exact_oracle.h"

namespace vissort::test {

std::vector<std::vector<uint32_t>> exactOcclusionGraph(PositionsView positions,
                                                       const ViewProjection& view,
                                                       std::span<const PrimitiveRange> primitives,
                                                       float tolerance) {
    ExactOracle oracle(0);
    oracle.bind(positions, view, primitives);

    // The fragments regrouped by pixel (counting sort), each with its primitive.
    struct PixelFragment {
        uint32_t primitive;
        double nearest, farthest;
    };
    const std::size_t pixels = std::size_t(view.width) * view.height;
    std::vector<uint64_t> start(pixels + 1, 0);
    for (uint32_t p = 0; p < oracle.primitiveCount(); ++p)
        for (const ExactOracle::Fragment& f : oracle.fragments(p))
            ++start[f.pixel + 1];
    for (std::size_t i = 0; i < pixels; ++i)
        start[i + 1] += start[i];
    std::vector<PixelFragment> by_pixel(start[pixels]);
    std::vector<uint64_t> next(start.begin(), start.end() - 1);
    for (uint32_t p = 0; p < oracle.primitiveCount(); ++p)
        for (const ExactOracle::Fragment& f : oracle.fragments(p))
            // The oracle's own values for a tolerance >= 0: drawn farther and queried nearer by
            // the triangles' snap slack (exact_oracle.h).
            by_pixel[next[f.pixel]++] = {p, f.nearest + f.nearest_slack,
                                         f.farthest - f.farthest_slack};

    // a -> b when b.farthest > a.nearest + tolerance at one pixel: sorted by nearest, the a of a
    // given b are a prefix. The same sum as the oracle's (a double plus the float tolerance).
    std::vector<uint64_t> edges;
    const auto compact = [&] {
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    };
    std::vector<PixelFragment> here;
    for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
        if (start[pixel + 1] - start[pixel] < 2)
            continue;
        here.assign(by_pixel.begin() + long(start[pixel]),
                    by_pixel.begin() + long(start[pixel + 1]));
        std::sort(here.begin(), here.end(), [](const PixelFragment& x, const PixelFragment& y) {
            return x.nearest < y.nearest;
        });
        for (const PixelFragment& b : here)
            for (const PixelFragment& a : here) {
                if (!(b.farthest > a.nearest + tolerance))
                    break;
                if (a.primitive != b.primitive)
                    edges.push_back(uint64_t(a.primitive) << 32 | b.primitive);
            }
        if (edges.size() > (1u << 24))
            compact();
    }
    compact();
    std::vector<std::vector<uint32_t>> graph(primitives.size());
    for (uint64_t edge : edges) // sorted: each list ascends
        graph[edge >> 32].push_back(uint32_t(edge));
    return graph;
}

std::vector<std::vector<uint32_t>> exactCycles(PositionsView positions, const ViewProjection& view,
                                               std::span<const PrimitiveRange> primitives,
                                               float tolerance) {
    return cyclicComponents(exactOcclusionGraph(positions, view, primitives, tolerance));
}

} // namespace vissort::test
