#pragma once
// Clipping of triangles in homogeneous clip space, before the perspective divide.
// This work is based on: Ivan E. Sutherland, Gary W. Hodgman. Reentrant Polygon Clipping. 1974;
// and James F. Blinn, Martin E. Newell. Clipping Using Homogeneous Coordinates. 1978.

#include <array>

namespace vissort::detail {

/// Guard band, in units of w: geometry is clipped to |x| <= G w and |y| <= G w, far outside the
/// screen (|x| <= w), so that snapped screen coordinates stay small (see cpu_rasterizer.h) while
/// almost no triangle gets new vertices on screen.
inline constexpr double kGuardBand = 32.0;

/// Sutherland-Hodgman adds at most one vertex per plane to a convex polygon (3 + 6 = 9); rounding
/// can make a clipped polygon slightly non-convex, so leave room, and drop anything larger.
inline constexpr int kMaxPolygonVertices = 16;

struct ClipVertex {
    double x = 0, y = 0, z = 0, w = 1;
};

/// Clips a triangle to the planes, in this order: z >= 0 (near), z <= w (far), x >= -G w,
/// x <= G w, y >= -G w, y <= G w. A vertex is kept when its signed distance is >= 0.
/// An edge crossing a plane is cut at p + t (q - p), t = dist(p) / (dist(p) - dist(q)), where p is
/// the lexicographically smaller endpoint in (x, y, z, w): the cut does not depend on the edge's
/// direction, so triangles sharing an edge cut it at the same point.
/// Writes the polygon into out, in the triangle's order, and returns its vertex count: 0 when
/// nothing is left (or on non-finite input, or w <= 0 anywhere on the result), else 3 or more.
int clipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                 std::array<ClipVertex, kMaxPolygonVertices>& out);

} // namespace vissort::detail
