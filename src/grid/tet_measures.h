#pragma once
// A tetrahedron's signed volume and the flatness rule, shared by the split of cells
// (cell_split.cpp) and the grid's validation (grid_validation.cpp) so that both call the same
// tetrahedra flat. Internal to src/grid/.

#include <algorithm>
#include <cmath>
#include <vector>

#include "vissort/tet_grid.h"

namespace vissort::detail {

/// det[b - a, c - a, d - a]: six times the signed volume of (a, b, c, d), positive when d lies on
/// the side of the plane (a, b, c) that (b - a) x (c - a) points to.
inline double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return dot(cross(b - a, c - a), d - a);
}

/// Six times tet's signed volume.
inline double signedVolume6(const std::vector<Vec3>& points, const Tet& tet) {
    return orient(points[tet[0]], points[tet[1]], points[tet[2]], points[tet[3]]);
}

/// Below this fraction of the cube of its longest edge a tetrahedron counts as flat: a regular
/// one has about 0.118, a sliver that float coordinates still order robustly far more than
/// this. Relative, so that a grid's units do not matter.
inline constexpr double kFlatVolumeRatio = 1e-9;

inline double longestEdge(const std::vector<Vec3>& points, const Tet& tet) {
    double longest = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            longest = std::max(longest, length(points[tet[i]] - points[tet[j]]));
    return longest;
}

/// Whether a tetrahedron names one point twice.
inline bool hasRepeatedCorner(const Tet& tet) {
    return tet[0] == tet[1] || tet[0] == tet[2] || tet[0] == tet[3] || tet[1] == tet[2] ||
           tet[1] == tet[3] || tet[2] == tet[3];
}

/// Whether six times a volume is too small for a tetrahedron whose longest edge is `edge`.
inline bool isFlat(double volume6, double edge) {
    return std::abs(volume6) <= kFlatVolumeRatio * 6 * edge * edge * edge;
}

} // namespace vissort::detail
