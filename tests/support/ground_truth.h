#pragma once
// Ground truth for visibility-ordering tests, exact and tolerance-free (exact_ground_truth.h):
// primitive a is in front of primitive b at a pixel iff a triangle of a and a triangle of b both
// have fragments there and the one of a is strictly nearer (smaller exact t along the pixel's
// centre ray). Coplanar and touching surfaces meet at exactly equal t, a tie: neither is in
// front. a and b can each be in front of the other at one pixel (a cycle). Triangles outside
// every primitive range are ignored. Independent of every oracle, rasterizer and ray caster.

#include <cstdint>
#include <span>
#include <vector>

#include "exact_ground_truth.h"
#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::test {

/// One pixel where the order puts `behind` before `front` although `front` occludes it there.
struct OrderViolation {
    uint32_t pixel_x, pixel_y;
    uint32_t front, behind; // primitive ids
    double front_depth;     // approximate depth d of front's nearest fragment at the pixel
    double behind_depth;    // approximate depth d of behind's farthest fragment at the pixel
};

struct OrderCheck {
    bool valid_permutation = false;         // order is a permutation of 0..n-1
    std::vector<OrderViolation> violations; // the first max_violations_kept, in pixel order
    uint64_t violation_count = 0;           // (pixel, front, behind) triples violated, all of them
    uint64_t pairs_checked = 0;             // (pixel, front, behind) triples where front occludes
    uint32_t max_depth_complexity = 0;      // most distinct primitives with fragments at one pixel
};

/// Checks that order (primitive ids front to back) respects every occlusion seen through view,
/// except between two primitives of one declared cycle (sets of primitive ids).
/// When order is not a permutation, returns at once with valid_permutation false.
OrderCheck checkVisibilityOrder(const TrianglePositions& positions, const ViewProjection& view,
                                std::span<const PrimitiveRange> primitives,
                                std::span<const uint32_t> order,
                                const std::vector<std::vector<uint32_t>>& cycles,
                                std::size_t max_violations_kept = 20);
/// The same over fragments computed once (exactFragments of positions and the view);
/// triangle_count is positions.triangleCount().
OrderCheck checkVisibilityOrder(const ExactFragments& fragments, std::size_t triangle_count,
                                std::span<const PrimitiveRange> primitives,
                                std::span<const uint32_t> order,
                                const std::vector<std::vector<uint32_t>>& cycles,
                                std::size_t max_violations_kept = 20);

/// The exact occlusion graph over primitives: graph[a] lists, ascending and without duplicates,
/// every b that a is in front of at some pixel.
std::vector<std::vector<uint32_t>> occlusionGraph(const TrianglePositions& positions,
                                                  const ViewProjection& view,
                                                  std::span<const PrimitiveRange> primitives);
std::vector<std::vector<uint32_t>> occlusionGraph(const ExactFragments& fragments,
                                                  std::size_t triangle_count,
                                                  std::span<const PrimitiveRange> primitives);

/// The cycles of the occlusion graph: its strongly connected components of two or more
/// primitives, each ascending, sorted by their first id (tarjan_scc.h's cyclicComponents).
std::vector<std::vector<uint32_t>> occlusionCycles(const TrianglePositions& positions,
                                                   const ViewProjection& view,
                                                   std::span<const PrimitiveRange> primitives);

} // namespace vissort::test
