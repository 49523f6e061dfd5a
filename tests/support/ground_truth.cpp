// Ground truth by brute force over all-hits ray casting: every pair of primitives at every pixel.

#include "ground_truth.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "exact/ray_caster.h"

namespace vissort::test {
namespace {

constexpr uint32_t kNoPrimitive = std::numeric_limits<uint32_t>::max();

// One primitive's robust hits at one pixel, and the snap slack of the triangles hit nearest and
// farthest.
struct PixelSpan {
    uint32_t primitive;
    double nearest, farthest;
    double nearest_slack, farthest_slack;
};

// The snap slack of cpu_oracle.h's rule 6 for triangle t seen through view: max(|dd/dx|,
// |dd/dy|) / 256, from the slopes of the triangle's plane in depth per pixel, here measured
// where the rays through three screen points meet that plane (d is affine in screen space for
// both projections: camera.h). Independent of the oracles' set-up code. Infinite for a plane
// seen edge-on.
double snapSlackOf(const TrianglePositions& positions, const ViewProjection& view, std::size_t t) {
    const Vec3 a = positions.corner(3 * t), b = positions.corner(3 * t + 1),
               c = positions.corner(3 * t + 2);
    const Vec3 normal = cross(b - a, c - a);
    const auto depthAt = [&](double sx, double sy, double& depth) {
        Vec3 origin, direction;
        view.pixelRay(sx, sy, origin, direction);
        const double along = dot(normal, direction);
        if (along == 0)
            return false;
        depth = view.depthOf(origin + direction * (dot(normal, a - origin) / along));
        return std::isfinite(depth);
    };
    const double cx = 0.5 * view.width, cy = 0.5 * view.height;
    double d0 = 0, dx = 0, dy = 0;
    if (!depthAt(cx, cy, d0) || !depthAt(cx + 1, cy, dx) || !depthAt(cx, cy + 1, dy))
        return std::numeric_limits<double>::infinity();
    return std::max(std::abs(dx - d0), std::abs(dy - d0)) / 256;
}

// Whether front lies in front of behind at a pixel by more than the margin the oracles promise
// to see (cpu_oracle.h, rule 7): kFrontMargin plus the two triangles' snap slack.
bool inFront(const PixelSpan& front, const PixelSpan& behind) {
    return front.nearest + kFrontMargin + front.nearest_slack + behind.farthest_slack <
           behind.farthest;
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

// Calls visit(px, py, spans) for every pixel with the robust spans of each primitive there.
template <class Visit>
void forEachPixel(const TrianglePositions& positions, const ViewProjection& view,
                  std::span<const PrimitiveRange> primitives, Visit&& visit) {
    const std::vector<uint32_t> primitive_of =
        primitiveOfTriangles(positions.triangleCount(), primitives);
    const detail::AllHits hits = detail::castAllHits(positions, view);
    std::vector<double> slack(positions.triangleCount());
    for (std::size_t t = 0; t < slack.size(); ++t)
        slack[t] = snapSlackOf(positions, view, t);
    std::vector<PixelSpan> spans;
    for (std::size_t pixel = 0; pixel < hits.pixelCount(); ++pixel) {
        spans.clear();
        for (uint64_t h = hits.firstHit(pixel); h < hits.endHit(pixel); ++h) {
            const uint32_t p = primitive_of[hits.triangles[h]];
            if (p == kNoPrimitive || !hits.robust[h])
                continue;
            const double d = hits.depths[h], e = slack[hits.triangles[h]];
            auto it = std::find_if(spans.begin(), spans.end(),
                                   [p](const PixelSpan& s) { return s.primitive == p; });
            if (it == spans.end()) {
                spans.push_back({p, d, d, e, e});
            } else {
                if (d < it->nearest) {
                    it->nearest = d;
                    it->nearest_slack = e;
                }
                if (d > it->farthest) {
                    it->farthest = d;
                    it->farthest_slack = e;
                }
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
                             if (front.primitive == behind.primitive || !inFront(front, behind))
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
                             if (front.primitive != behind.primitive && inFront(front, behind))
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
