#pragma once
// Ground truth for visibility-ordering tests, from all-hits ray casting through pixel centres
// (independent of every oracle's depth buffer). Only robust hits count (barycentric coordinates
// all > 1e-6): a primitive a is in front of b at a pixel when the nearest robust hit of a is
// nearer than some robust hit of b by more than kFrontMargin plus the snap slack of the two
// triangles hit (cpu_oracle.h, rules 6 and 7: the bound within which the rasterizing oracles
// may not see an occlusion), measured here from the triangles' planes. The margin (4
// tolerances) leaves room for the oracles' own tolerance, so coplanar and touching surfaces
// never count.

#include <cstdint>
#include <span>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"
#include "vissort/geometry_oracle.h"

namespace vissort::test {

inline constexpr double kFrontMargin = 4.0 * kDepthTolerance;

/// One pixel where the order puts `behind` before `front` although `front` occludes it there.
struct OrderViolation {
    uint32_t pixel_x, pixel_y;
    uint32_t front, behind; // primitive ids
    double front_depth;     // nearest robust hit of front at the pixel
    double behind_depth;    // farthest robust hit of behind at the pixel
};

struct OrderCheck {
    bool valid_permutation = false;         // order is a permutation of 0..n-1
    std::vector<OrderViolation> violations; // the first max_violations_kept, in pixel order
    uint64_t violation_count = 0;           // (pixel, front, behind) triples violated, all of them
    uint64_t pairs_checked = 0;             // (pixel, front, behind) triples where front occludes
    uint32_t max_depth_complexity = 0;      // most distinct primitives robustly hit at one pixel
};

/// Checks that order (primitive ids front to back) respects every occlusion seen through view,
/// except between two primitives of one declared cycle (sets of primitive ids).
/// When order is not a permutation, returns at once with valid_permutation false.
OrderCheck checkVisibilityOrder(const TrianglePositions& positions, const ViewProjection& view,
                                std::span<const PrimitiveRange> primitives,
                                std::span<const uint32_t> order,
                                const std::vector<std::vector<uint32_t>>& cycles,
                                std::size_t max_violations_kept = 20);

/// The brute-force occlusion graph over primitives: graph[a] lists, ascending and without
/// duplicates, every b that a is in front of at some pixel (robust hits, kFrontMargin).
std::vector<std::vector<uint32_t>> occlusionGraph(const TrianglePositions& positions,
                                                  const ViewProjection& view,
                                                  std::span<const PrimitiveRange> primitives);

} // namespace vissort::test
