#pragma once
// Exact signs of the orientation determinants on float coordinates: a floating-point filter in
// double, and an exact expansion sum when the filter cannot decide (exact_predicates.cpp).
// Internal.

namespace vissort::detail {

/// Sign (-1, 0, +1) of det[b - a, c - a, d - a]: positive when d lies on the side of the plane
/// (a, b, c) that (b - a) x (c - a) points to. Exact for every finite float input.
int orient3d(const float a[3], const float b[3], const float c[3], const float d[3]);

/// sides[i] = orient3d(a, b, c, d_i) for the three corners d_i of a triangle, sharing the work
/// on the plane (a, b, c).
void orient3dPlaneSides(const float a[3], const float b[3], const float c[3], const float* d0,
                        const float* d1, const float* d2, int sides[3]);

/// sides[i] = orient3d(p, q, t_i, t_(i+1 mod 3)): the side of each directed edge of triangle
/// (t0, t1, t2) that line pq passes, sharing the differences from p.
void orient3dEdgeSides(const float p[3], const float q[3], const float* t0, const float* t1,
                       const float* t2, int sides[3]);

/// Sign (-1, 0, +1) of det[b - a, c - a] in 2D: positive when a, b, c turn counter-clockwise.
/// Exact for every finite float input.
int orient2d(const float a[2], const float b[2], const float c[2]);

} // namespace vissort::detail
