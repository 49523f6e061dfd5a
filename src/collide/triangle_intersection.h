#pragma once
// The exact test of the narrow phase: do two closed triangles share a point? Decided by exact
// orientation predicates on the float corners, so touching (a shared vertex, an edge on a face,
// coplanar overlap) always counts and near misses never do. Degenerate triangles (zero area:
// segments or points) are tested as what they are. Internal.

#include <array>
#include <cstdint>

#include "vissort/geometry.h"

namespace vissort::detail {

/// A triangle's corners: corner[c][axis].
using TriangleCorners = std::array<std::array<float, 3>, 3>;

inline TriangleCorners cornersOf(PositionsView positions, uint32_t triangle) {
    TriangleCorners t;
    for (int c = 0; c < 3; ++c) {
        const std::size_t i = 3 * std::size_t(triangle) + std::size_t(c);
        t[c] = {positions.x[i], positions.y[i], positions.z[i]};
    }
    return t;
}

/// True when the closed triangles a and b share at least one point. Exact for every finite
/// input, degenerate triangles included.
bool trianglesIntersect(const TriangleCorners& a, const TriangleCorners& b);

} // namespace vissort::detail
