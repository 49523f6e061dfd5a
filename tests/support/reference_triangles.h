#pragma once
// Whether two closed triangles share a point, by CGAL's exact do_intersect: the ground truth of
// the collision tests and of the built-in scenes' "no two triangles meet" checks. A degenerate
// triangle is what it is: the segment between its extreme corners, or a point.

#include <array>

#include "vissort/geometry.h"

namespace vissort::test {

bool closedTrianglesMeet(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);

/// Whether the corners are exactly collinear (the triangle is a segment or a point).
bool isDegenerateTriangle(const std::array<Vec3, 3>& t);

} // namespace vissort::test
