#pragma once
// The exact fragment model (docs/robustness.md, "The exact model"): whether the ray of a pixel
// centre meets a triangle, and which of two triangles it meets first, decided exactly on the
// float corners and the doubles of the ray. Every oracle's "behind" is defined by it. Internal.
//
// Pixel (px, py) is sampled by the line L = O + t D of PixelRays::centre (the doubles taken as
// exact values). For a triangle (A, B, C):
//  - Q = det[B - A, C - A, D]: zero for a degenerate triangle or one that L meets edge-on, which
//    then has no fragment;
//  - L meets the closed triangle when det[A - O, B - O, D], det[B - O, C - O, D] and
//    det[C - O, A - O, D] are all >= 0 or all <= 0 (edges and corners count);
//  - the hit is at t = N / Q, N = det[A - O, B - O, C - O], and counts when its eye-space distance
//    z = zO + t zD (zO = -(r . O + r3), zD = -(r . D), r and r3 the view matrix's third row) is
//    at least near, and for an orthographic view at most far;
//  - of two fragments the one with the smaller t is in front; equal t is a tie.
// Each sign is first computed in double with a bound on its rounding error; only when the bound
// does not settle it is the expression evaluated in exact rational arithmetic (GMP).

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "geometry/pixel_rays.h"
#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::detail {

/// A triangle's corners as stored: floats, which the model reads exactly.
struct TriangleCorners {
    float p[3][3]; // p[corner][axis]

    static TriangleCorners of(PositionsView positions, std::size_t triangle);

    /// The same three corners in any order: one plane, so a tie at every ray both meet.
    /// Duplicated faces are common in real files.
    bool sameCornersAs(const TriangleCorners& other) const;

    /// The corners in ascending (x, y, z) order, as one key: equal exactly for copies (the same
    /// corners in any order). Finite corners only (a NaN breaks the order).
    std::array<float, 9> sortedKey() const;
};

/// A double and a bound on its distance from the exact value it stands for.
struct BoundedValue {
    double value = 0, error = 0;

    /// +1 or -1 when the bound settles the sign, 0 when it cannot.
    int certainSign() const { return value > error ? 1 : value < -error ? -1 : 0; }
};

/// What one triangle's fragment at one ray is, in double: t = n / q, both with error bounds.
/// Enough to order fragments at a pixel without recomputing the determinants per comparison.
struct RayHit {
    BoundedValue n, q;
    /// The approximate hit parameter t (larger is farther).
    double parameter() const { return n.value / q.value; }
};

class ExactFragments {
public:
    explicit ExactFragments(const ViewProjection& view);
    ExactFragments(const ExactFragments& other);
    ExactFragments& operator=(const ExactFragments&) = delete;

    const PixelRays& rays() const { return rays_; }

    /// Whether triangle has a fragment at ray (the model above). A triangle with a non-finite
    /// corner has none.
    bool covers(const PixelRay& ray, const TriangleCorners& triangle) const;

    /// The hit's determinants in double, for compare(): call only where covers() holds.
    RayHit hit(const PixelRay& ray, const TriangleCorners& triangle) const;

    /// The exact sign of t(a) - t(b): -1 when a is in front, +1 when b is, 0 for a tie. Both
    /// must cover ray; ha and hb are their hit(ray, ...).
    int compare(const PixelRay& ray, const TriangleCorners& a, const RayHit& ha,
                const TriangleCorners& b, const RayHit& hb) const;
    int compare(const PixelRay& ray, const TriangleCorners& a, const TriangleCorners& b) const {
        return compare(ray, a, hit(ray, a), b, hit(ray, b));
    }

    /// The exact sign of triangle's Q at ray: which way it faces the rays (0 when seen edge-on).
    int facing(const PixelRay& ray, const TriangleCorners& triangle) const;

    /// How often the exact arithmetic ran since construction (the double bounds could not
    /// decide): for tests and statistics. Safe to call from several threads at once, as is
    /// every other member.
    uint64_t exactEvaluations() const { return exact_evaluations_.load(); }

private:
    bool coversExactly(const PixelRay& ray, const TriangleCorners& triangle) const;
    int compareExactly(const PixelRay& ray, const TriangleCorners& a,
                       const TriangleCorners& b) const;

    PixelRays rays_;
    bool orthographic_;
    double near_, far_;
    double row_[4]; // the view matrix's third row: eye-space z = row . (x, y, z, 1)
    mutable std::atomic<uint64_t> exact_evaluations_{0};
};

} // namespace vissort::detail
