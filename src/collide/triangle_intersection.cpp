// The exact triangle-triangle intersection test: closed triangles, decided by signs of exact
// orientation predicates (exact_predicates.h) and by comparisons of the float coordinates
// themselves, never by a computed intersection point, so it is exact for every finite input.
//
// This work is based on: Olivier Devillers and Philippe Guigue. Faster Triangle-Triangle
// Intersection Tests. INRIA research report RR-4488, 2002 (the orientation-only formulation and
// the early exit on the planes' sides), and Tomas Moller. A Fast Triangle-Triangle Intersection
// Test. Journal of Graphics Tools 2(2), 1997 (the case split: separated by a plane, crossing
// planes, coplanar). Degenerate triangles follow the same recipe on segments and points.
//
// Why the case split is complete:
// - Two non-degenerate triangles in distinct planes meet in a convex subset of the planes'
//   common line L. A triangle's part of L is a segment whose endpoints lie on its boundary, and
//   an endpoint of the common part is an endpoint of one of the two triangles' parts. So they
//   meet iff an edge of one meets the other triangle, and an edge with both ends strictly on
//   one side of the other's plane cannot.
// - Two coplanar triangles meet iff two of their edges meet, or one holds a corner of the
//   other (their boundaries are disjoint then, so one contains the other).
// - A triangle whose corners are exactly collinear is the segment between its two extreme
//   corners, or a point.
// A projection that drops an axis along which a plane is not parallel is injective on that
// plane, so a 2D test in it is exact; that axis is one where the projected orient2d of a
// non-degenerate triangle of the plane is non-zero.

#include "collide/triangle_intersection.h"

#include <algorithm>
#include <cmath>

#include "geometry/exact_predicates.h"

namespace vissort::detail {
namespace {

using Point = std::array<float, 3>;
using Point2 = std::array<float, 2>;

// No projection axis has been looked for yet (distinct from -1, "degenerate").
constexpr int kAxisUnknown = 3;

// The 2D coordinates left after dropping axis drop, in cyclic order.
inline Point2 project(const Point& p, int drop) {
    constexpr int kKept[3][2] = {{1, 2}, {2, 0}, {0, 1}};
    return {p[kKept[drop][0]], p[kKept[drop][1]]};
}

inline bool sameStrictSide(const int s[3]) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

// Signs that are not both positive and negative somewhere (zeros go with either).
inline bool notMixed(int s0, int s1, int s2) {
    return !((s0 > 0 || s1 > 0 || s2 > 0) && (s0 < 0 || s1 < 0 || s2 < 0));
}

// An axis whose dropping keeps triangle (p, q, r) non-degenerate (so the projection is
// injective on its plane), or -1 when p, q, r are collinear: then every projection has zero
// area, because the cross product's components are those projected areas. The largest normal
// component in double is almost always the right first guess; the exact sign confirms it.
int projectionAxis(const Point& p, const Point& q, const Point& r) {
    const double ux = double(q[0]) - p[0], uy = double(q[1]) - p[1], uz = double(q[2]) - p[2];
    const double vx = double(r[0]) - p[0], vy = double(r[1]) - p[1], vz = double(r[2]) - p[2];
    const double n[3] = {std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz),
                         std::fabs(ux * vy - uy * vx)};
    const int first = n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
    for (int i = 0; i < 3; ++i) {
        const int axis = (first + i) % 3;
        const Point2 p2 = project(p, axis), q2 = project(q, axis), r2 = project(r, axis);
        if (orient2d(p2.data(), q2.data(), r2.data()) != 0)
            return axis;
    }
    return -1;
}

int projectionAxis(const TriangleCorners& t) {
    return projectionAxis(t[0], t[1], t[2]);
}

// The axis along which p and q differ most (any axis where they differ orders the points of
// line pq injectively). p != q.
template <std::size_t kDims>
int longestAxis(const std::array<float, kDims>& p, const std::array<float, kDims>& q) {
    int axis = 0;
    double extent = std::fabs(double(q[0]) - p[0]);
    for (std::size_t k = 1; k < kDims; ++k) {
        const double e = std::fabs(double(q[k]) - p[k]);
        if (e > extent) {
            extent = e;
            axis = int(k);
        }
    }
    return axis;
}

// Closed intervals [p, q] and [r, s] along axis k (endpoints in any order) overlap.
template <std::size_t kDims>
bool intervalsOverlap(const std::array<float, kDims>& p, const std::array<float, kDims>& q,
                      const std::array<float, kDims>& r, const std::array<float, kDims>& s, int k) {
    return std::max(r[k], s[k]) >= std::min(p[k], q[k]) &&
           std::max(p[k], q[k]) >= std::min(r[k], s[k]);
}

// ---- 2D, in an injective projection --------------------------------------------------------

// Point in the closed non-degenerate triangle t.
bool pointInTriangle2d(const Point2& p, const Point2 t[3]) {
    const int s0 = orient2d(t[0].data(), t[1].data(), p.data());
    const int s1 = orient2d(t[1].data(), t[2].data(), p.data());
    if (s0 * s1 < 0)
        return false;
    const int s2 = orient2d(t[2].data(), t[0].data(), p.data());
    return notMixed(s0, s1, s2);
}

// Closed segments pq and rs meet; p != q, r != s. If r and s are not both on line pq and the
// segments straddle each other's lines, those lines are distinct and cross at one point that
// lies on both segments. If both are on it, the four points are collinear.
bool segmentsMeet2d(const Point2& p, const Point2& q, const Point2& r, const Point2& s) {
    const int o_r = orient2d(p.data(), q.data(), r.data());
    const int o_s = orient2d(p.data(), q.data(), s.data());
    if (o_r * o_s > 0)
        return false;
    if (o_r == 0 && o_s == 0)
        return intervalsOverlap(p, q, r, s, longestAxis(p, q));
    const int o_p = orient2d(r.data(), s.data(), p.data());
    const int o_q = orient2d(r.data(), s.data(), q.data());
    return o_p * o_q <= 0;
}

// Closed segment pq (p != q) and closed non-degenerate triangle t: an endpoint inside, or else
// the segment enters through an edge.
bool segmentMeetsTriangle2d(const Point2& p, const Point2& q, const Point2 t[3]) {
    if (pointInTriangle2d(p, t) || pointInTriangle2d(q, t))
        return true;
    for (int i = 0; i < 3; ++i)
        if (segmentsMeet2d(p, q, t[i], t[(i + 1) % 3]))
            return true;
    return false;
}

bool trianglesMeet2d(const Point2 a[3], const Point2 b[3]) {
    if (pointInTriangle2d(a[0], b) || pointInTriangle2d(b[0], a))
        return true;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (segmentsMeet2d(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]))
                return true;
    return false;
}

// ---- 3D --------------------------------------------------------------------------------------

void projectTriangle(const TriangleCorners& t, int axis, Point2 out[3]) {
    for (int c = 0; c < 3; ++c)
        out[c] = project(t[c], axis);
}

// Closed segment pq (p != q) and closed non-degenerate triangle t, given sp, sq: the sides of
// p and q of t's plane (orient3d(t, .)). t_axis: t's projection axis, found on first need.
bool segmentMeetsTriangle(const Point& p, const Point& q, int sp, int sq, const TriangleCorners& t,
                          int& t_axis) {
    if (sp * sq > 0)
        return false;
    if (sp == 0 && sq == 0) {
        if (t_axis == kAxisUnknown)
            t_axis = projectionAxis(t);
        Point2 t2[3];
        projectTriangle(t, t_axis, t2);
        return segmentMeetsTriangle2d(project(p, t_axis), project(q, t_axis), t2);
    }
    // pq crosses the plane at one point; it lies in t iff line pq passes on the same side of
    // (or through) every directed edge of t.
    int e[3];
    orient3dEdgeSides(p.data(), q.data(), t[0].data(), t[1].data(), t[2].data(), e);
    return notMixed(e[0], e[1], e[2]);
}

// The corners of a degenerate (collinear) triangle that bound it, along the axis of its
// largest extent (injective on its line); first == last when all three coincide.
struct Extremes {
    int first = 0, last = 0;
};

Extremes extremesOf(const TriangleCorners& t) {
    int axis = 0;
    double extent = -1;
    for (int k = 0; k < 3; ++k) {
        const float lo = std::min({t[0][k], t[1][k], t[2][k]});
        const float hi = std::max({t[0][k], t[1][k], t[2][k]});
        if (double(hi) - lo > extent) {
            extent = double(hi) - lo;
            axis = k;
        }
    }
    Extremes e;
    if (extent == 0)
        return e;
    for (int c = 1; c < 3; ++c) {
        if (t[c][axis] < t[e.first][axis])
            e.first = c;
        if (t[c][axis] > t[e.last][axis])
            e.last = c;
    }
    return e;
}

// Closed non-degenerate segment pq and point x: collinear, and between them on an injective
// axis.
bool pointOnSegment(const Point& x, const Point& p, const Point& q) {
    if (projectionAxis(p, q, x) >= 0)
        return false;
    const int k = longestAxis(p, q);
    return std::min(p[k], q[k]) <= x[k] && x[k] <= std::max(p[k], q[k]);
}

// Closed non-degenerate segments pq and rs in 3D.
bool segmentsMeet3d(const Point& p, const Point& q, const Point& r, const Point& s) {
    if (orient3d(p.data(), q.data(), r.data(), s.data()) != 0)
        return false;
    int axis = projectionAxis(p, q, r);
    if (axis < 0)
        axis = projectionAxis(p, q, s);
    if (axis < 0)
        return intervalsOverlap(p, q, r, s, longestAxis(p, q));
    return segmentsMeet2d(project(p, axis), project(q, axis), project(r, axis), project(s, axis));
}

// Degenerate d (its corners' sides sd of t's plane) and non-degenerate t.
bool degenerateMeetsTriangle(const TriangleCorners& d, const int sd[3], const TriangleCorners& t,
                             int t_axis) {
    const Extremes e = extremesOf(d);
    if (e.first != e.last)
        return segmentMeetsTriangle(d[e.first], d[e.last], sd[e.first], sd[e.last], t, t_axis);
    if (sd[e.first] != 0)
        return false;
    if (t_axis == kAxisUnknown)
        t_axis = projectionAxis(t);
    Point2 t2[3];
    projectTriangle(t, t_axis, t2);
    return pointInTriangle2d(project(d[e.first], t_axis), t2);
}

bool degeneratesMeet(const TriangleCorners& a, const TriangleCorners& b) {
    const Extremes ea = extremesOf(a), eb = extremesOf(b);
    const Point &p = a[ea.first], &q = a[ea.last], &r = b[eb.first], &s = b[eb.last];
    if (ea.first == ea.last && eb.first == eb.last)
        return p == r;
    if (ea.first == ea.last)
        return pointOnSegment(p, r, s);
    if (eb.first == eb.last)
        return pointOnSegment(r, p, q);
    return segmentsMeet3d(p, q, r, s);
}

// Every corner of one triangle is on the other's plane (sa, sb all zero): coplanar, or one or
// both degenerate.
bool flatPairMeets(const TriangleCorners& a, const TriangleCorners& b, const int sa[3],
                   const int sb[3]) {
    const int axis_a = projectionAxis(a), axis_b = projectionAxis(b);
    if (axis_a >= 0 && axis_b >= 0) {
        // Coplanar: a's projection is injective on the common plane.
        Point2 a2[3], b2[3];
        projectTriangle(a, axis_a, a2);
        projectTriangle(b, axis_a, b2);
        return trianglesMeet2d(a2, b2);
    }
    if (axis_b >= 0)
        return degenerateMeetsTriangle(a, sa, b, axis_b);
    if (axis_a >= 0)
        return degenerateMeetsTriangle(b, sb, a, axis_a);
    return degeneratesMeet(a, b);
}

} // namespace

bool trianglesIntersect(const TriangleCorners& a, const TriangleCorners& b) {
    // Sides of each triangle's plane. A degenerate triangle has no plane: all its signs are 0.
    int sb[3], sa[3];
    orient3dPlaneSides(a[0].data(), a[1].data(), a[2].data(), b[0].data(), b[1].data(), b[2].data(),
                       sb);
    if (sameStrictSide(sb))
        return false;
    orient3dPlaneSides(b[0].data(), b[1].data(), b[2].data(), a[0].data(), a[1].data(), a[2].data(),
                       sa);
    if (sameStrictSide(sa))
        return false;

    const bool b_on_plane_a = sb[0] == 0 && sb[1] == 0 && sb[2] == 0;
    const bool a_on_plane_b = sa[0] == 0 && sa[1] == 0 && sa[2] == 0;
    if (!b_on_plane_a && !a_on_plane_b) {
        // The common case: a non-zero sign on each side proves both non-degenerate, and the
        // planes distinct.
        int axis_a = kAxisUnknown, axis_b = kAxisUnknown;
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            if (segmentMeetsTriangle(a[i], a[j], sa[i], sa[j], b, axis_b))
                return true;
            if (segmentMeetsTriangle(b[i], b[j], sb[i], sb[j], a, axis_a))
                return true;
        }
        return false;
    }
    // b on a's plane but some corner of a off b's: a non-degenerate a would share b's plane, so
    // a is degenerate (and b is not); and the other way round.
    if (!a_on_plane_b)
        return degenerateMeetsTriangle(a, sa, b, kAxisUnknown);
    if (!b_on_plane_a)
        return degenerateMeetsTriangle(b, sb, a, kAxisUnknown);
    return flatPairMeets(a, b, sa, sb);
}

} // namespace vissort::detail
