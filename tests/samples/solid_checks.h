#pragma once
// Brute-force checks of the CAD-like generated scenes (plant, powerplant), independent of the
// generators: every object a closed mesh wound outwards, and the distances between objects,
// triangle by triangle (Ericson, "Real-Time Collision Detection", 5.1.5 and 5.1.9).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "vissort/scene.h"

namespace vissort::test {

using Triangle = std::array<Vec3, 3>;

Triangle triangleOf(const Scene& scene, std::size_t triangle);
/// Whether the ray from o along d hits t at a distance > 0, from either side (Moeller-Trumbore).
bool rayHits(const Vec3& o, const Vec3& d, const Triangle& t);
/// The bounds of triangles [first, first + count).
Bounds boundsOf(const Scene& scene, uint32_t first, uint32_t count);
/// Distance between boxes: a lower bound of the distance between anything inside them.
double boxDistance(const Bounds& a, const Bounds& b);
/// The point of triangle abc closest to p.
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);
/// Distance between two closed triangles, exact up to rounding also for parallel and coplanar
/// ones: 0 when an edge of one passes through the other, else the least distance between two
/// edges or between a corner and the other triangle.
double triangleDistance(const Triangle& a, const Triangle& b);

/// An object's mesh: after welding identical corners, the directed edges not matched by exactly
/// one reverse edge (0 for a closed, consistently wound mesh), the smallest triangle area and
/// the enclosed volume (positive when wound outwards; divergence theorem).
struct MeshCheck {
    std::size_t unmatched_edges = 0;
    double smallest_area = 0;
    double volume = 0;
};
MeshCheck checkMesh(const Scene& scene, const SceneObject& object);

/// The distances between the objects of a scene closer than `reach`: the closest any two come,
/// the triangle pairs measured, and "A and B" for each pair of objects closer than `minimum`.
struct GapCheck {
    double closest = 1e300;
    std::size_t pairs_checked = 0;
    std::vector<std::string> too_close;
};
GapCheck checkGaps(const Scene& scene, double minimum, double reach);

} // namespace vissort::test
