// Ground truth by brute force over all-hits ray casting: every pair of primitives at every pixel.

#include "ground_truth.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <unordered_set>

#include "exact/ray_caster.h"

namespace vissort::test {
namespace {

constexpr uint32_t kNoPrimitive = std::numeric_limits<uint32_t>::max();

// One primitive's robust hits at one pixel.
struct PixelSpan {
    uint32_t primitive;
    double nearest, farthest;
};

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

// Calls visit(px, py, spans) for every pixel with the robust spans of each primitive there.
template <class Visit>
void forEachPixel(const TrianglePositions& positions, const ViewProjection& view,
                  std::span<const PrimitiveRange> primitives, Visit&& visit) {
    const std::vector<uint32_t> primitive_of =
        primitiveOfTriangles(positions.triangleCount(), primitives);
    const detail::AllHits hits = detail::castAllHits(positions, view);
    std::vector<PixelSpan> spans;
    for (std::size_t pixel = 0; pixel < hits.pixelCount(); ++pixel) {
        spans.clear();
        for (uint64_t h = hits.firstHit(pixel); h < hits.endHit(pixel); ++h) {
            const uint32_t p = primitive_of[hits.triangles[h]];
            if (p == kNoPrimitive || !hits.robust[h])
                continue;
            const double d = hits.depths[h];
            auto it = std::find_if(spans.begin(), spans.end(),
                                   [p](const PixelSpan& s) { return s.primitive == p; });
            if (it == spans.end()) {
                spans.push_back({p, d, d});
            } else {
                it->nearest = std::min(it->nearest, d);
                it->farthest = std::max(it->farthest, d);
            }
        }
        visit(uint32_t(pixel % hits.width), uint32_t(pixel / hits.width),
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

    forEachPixel(positions, view, primitives,
                 [&](uint32_t px, uint32_t py, std::span<const PixelSpan> spans) {
                     check.max_depth_complexity =
                         std::max(check.max_depth_complexity, uint32_t(spans.size()));
                     for (const PixelSpan& front : spans) {
                         for (const PixelSpan& behind : spans) {
                             if (front.primitive == behind.primitive ||
                                 !(front.nearest + kFrontMargin < behind.farthest))
                                 continue;
                             ++check.pairs_checked;
                             if (position[behind.primitive] > position[front.primitive] ||
                                 inOneCycle(front.primitive, behind.primitive))
                                 continue;
                             ++check.violation_count;
                             if (check.violations.size() < max_violations_kept) {
                                 check.violations.push_back({px, py, front.primitive,
                                                             behind.primitive, front.nearest,
                                                             behind.farthest});
                             }
                         }
                     }
                 });
    return check;
}

std::vector<std::vector<uint32_t>> occlusionGraph(const TrianglePositions& positions,
                                                  const ViewProjection& view,
                                                  std::span<const PrimitiveRange> primitives) {
    std::unordered_set<uint64_t> edges;
    forEachPixel(positions, view, primitives,
                 [&](uint32_t, uint32_t, std::span<const PixelSpan> spans) {
                     for (const PixelSpan& front : spans) {
                         for (const PixelSpan& behind : spans) {
                             if (front.primitive != behind.primitive &&
                                 front.nearest + kFrontMargin < behind.farthest)
                                 edges.insert(uint64_t(front.primitive) << 32 | behind.primitive);
                         }
                     }
                 });
    std::vector<std::vector<uint32_t>> graph(primitives.size());
    for (uint64_t edge : edges)
        graph[edge >> 32].push_back(uint32_t(edge));
    for (std::vector<uint32_t>& successors : graph)
        std::sort(successors.begin(), successors.end());
    return graph;
}

} // namespace vissort::test
