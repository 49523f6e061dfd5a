#pragma once
// Exact signs of the orientation determinants on float coordinates: a floating-point filter in
// double, and an exact expansion sum when the filter cannot decide (exact_predicates.cpp).
// Internal.

namespace vissort::detail {

/// Sign (-1, 0, +1) of det[b - a, c - a, d - a]: positive when d lies on the side of the plane
/// (a, b, c) that (b - a) x (c - a) points to. Exact for every finite float input.
int orient3d(const float a[3], const float b[3], const float c[3], const float d[3]);

/// Sign (-1, 0, +1) of det[b - a, c - a] in 2D: positive when a, b, c turn counter-clockwise.
/// Exact for every finite float input.
int orient2d(const float a[2], const float b[2], const float c[2]);

} // namespace vissort::detail
