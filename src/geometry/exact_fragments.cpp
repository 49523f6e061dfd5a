// The exact fragment model of exact_fragments.h.
//
// This work is based on: Jonathan Richard Shewchuk. Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates. Discrete & Computational Geometry 18(3):305-363, 1997
// (a floating-point evaluation with an error bound, exact arithmetic only where it cannot
// decide); the exact stage is GMP's rational arithmetic rather than expansions, because the
// expressions here are of degree 6 in mixed float and double inputs, and it runs rarely: at
// pixel centres within about 1e-13 of an edge, and at exact or near ties.
//
// Number formats: inputs are IEEE binary32 corners and binary64 ray and view values, all read
// as the exact rationals they are; the filter computes in binary64, round to nearest, and this
// file is compiled with -ffp-contract=off so that every operation rounds on its own, as the
// error bounds assume.

#include "geometry/exact_fragments.h"

#include <algorithm>
#include <cmath>

#include <gmpxx.h>

namespace vissort::detail {
namespace {

constexpr double kEpsilon = 0x1p-53; // the unit roundoff of binary64
// Each bound is inflated by this factor, which absorbs the rounding of the bound's own sums and
// products (a few units of kEpsilon).
constexpr double kInflate = 1.0 + 16 * kEpsilon;
// Below this magnitude a value may have lost bits to underflow, where relative rounding bounds
// no longer hold: such a sign is left to the exact arithmetic.
constexpr double kSmallest = 0x1p-900;

using Bounded = BoundedValue;

Bounded exact(double value) {
    return {value, 0.0};
}

Bounded operator+(const Bounded& a, const Bounded& b) {
    const double v = a.value + b.value;
    return {v, (a.error + b.error + kEpsilon * std::abs(v)) * kInflate};
}

Bounded operator-(const Bounded& a, const Bounded& b) {
    const double v = a.value - b.value;
    return {v, (a.error + b.error + kEpsilon * std::abs(v)) * kInflate};
}

Bounded operator-(const Bounded& a) {
    return {-a.value, a.error};
}

Bounded operator*(const Bounded& a, const Bounded& b) {
    const double v = a.value * b.value;
    return {v, (std::abs(a.value) * b.error + std::abs(b.value) * a.error + a.error * b.error +
                kEpsilon * std::abs(v)) *
                   kInflate};
}

// The sign when the bound settles it, else 0. Non-finite values and values small enough to have
// underflowed settle nothing.
int signOf(const Bounded& b) {
    if (!(std::abs(b.value) >= kSmallest) || !std::isfinite(b.error))
        return 0;
    return b.certainSign();
}

struct BoundedVec {
    Bounded v[3];
};

// a - b per axis, each difference rounded once.
BoundedVec difference(const double a[3], const double b[3]) {
    BoundedVec d;
    for (int i = 0; i < 3; ++i)
        d.v[i] = exact(a[i]) - exact(b[i]);
    return d;
}

BoundedVec exactVec(const double a[3]) {
    return {{exact(a[0]), exact(a[1]), exact(a[2])}};
}

// det[u, v, w] of three columns, by cofactors of the first.
Bounded det3(const BoundedVec& u, const BoundedVec& v, const BoundedVec& w) {
    const Bounded m0 = v.v[1] * w.v[2] - v.v[2] * w.v[1];
    const Bounded m1 = v.v[0] * w.v[2] - v.v[2] * w.v[0];
    const Bounded m2 = v.v[0] * w.v[1] - v.v[1] * w.v[0];
    return u.v[0] * m0 - u.v[1] * m1 + u.v[2] * m2;
}

// The same expressions in exact rational arithmetic.
using Rational = mpq_class;

struct RationalVec {
    Rational v[3];
};

RationalVec rational(const double a[3]) {
    return {{Rational(a[0]), Rational(a[1]), Rational(a[2])}};
}

RationalVec operator-(const RationalVec& a, const RationalVec& b) {
    return {{a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2]}};
}

Rational det3(const RationalVec& u, const RationalVec& v, const RationalVec& w) {
    const Rational m0 = v.v[1] * w.v[2] - v.v[2] * w.v[1];
    const Rational m1 = v.v[0] * w.v[2] - v.v[2] * w.v[0];
    const Rational m2 = v.v[0] * w.v[1] - v.v[1] * w.v[0];
    return u.v[0] * m0 - u.v[1] * m1 + u.v[2] * m2;
}

struct Corners3 {
    double a[3], b[3], c[3];
};

Corners3 cornersOf(const TriangleCorners& t) {
    Corners3 c;
    for (int i = 0; i < 3; ++i) {
        c.a[i] = t.p[0][i];
        c.b[i] = t.p[1][i];
        c.c[i] = t.p[2][i];
    }
    return c;
}

void toArray(const Vec3& v, double out[3]) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

// The determinants of one triangle against one ray, exactly.
struct ExactHit {
    Rational q, n; // t = n / q
    Rational s[3]; // the edge sides
};

bool sameCorner(const float (&u)[3], const float (&v)[3]) {
    return u[0] == v[0] && u[1] == v[1] && u[2] == v[2];
}

// Two corners equal as stored: Q is 0 at every ray, so the triangle has no fragment. Files
// with repeated indices (a fan over a polygon that revisits its corners) have thousands.
bool hasRepeatedCorner(const TriangleCorners& t) {
    return sameCorner(t.p[0], t.p[1]) || sameCorner(t.p[1], t.p[2]) || sameCorner(t.p[2], t.p[0]);
}

// t = n / q exactly, without the edge sides: what ordering two fragments needs.
struct ExactParameter {
    Rational q, n;
};

ExactParameter exactParameter(const PixelRay& ray, const TriangleCorners& t) {
    const Corners3 c = cornersOf(t);
    double o[3], d[3];
    toArray(ray.origin, o);
    toArray(ray.direction, d);
    const RationalVec ro = rational(o);
    const RationalVec ra = rational(c.a), rb = rational(c.b), rc = rational(c.c);
    ExactParameter h;
    h.q = det3(rb - ra, rc - ra, rational(d));
    h.n = det3(ra - ro, rb - ro, rc - ro);
    return h;
}

ExactHit exactHit(const PixelRay& ray, const TriangleCorners& t) {
    const Corners3 c = cornersOf(t);
    double o[3], d[3];
    toArray(ray.origin, o);
    toArray(ray.direction, d);
    const RationalVec ro = rational(o), rd = rational(d);
    const RationalVec ra = rational(c.a), rb = rational(c.b), rc = rational(c.c);
    const RationalVec a = ra - ro, b = rb - ro, cc = rc - ro;
    ExactHit h;
    h.q = det3(rb - ra, rc - ra, rd);
    h.n = det3(a, b, cc);
    h.s[0] = det3(a, b, rd);
    h.s[1] = det3(b, cc, rd);
    h.s[2] = det3(cc, a, rd);
    return h;
}

} // namespace

bool TriangleCorners::sameCornersAs(const TriangleCorners& other) const {
    const auto within = [](const TriangleCorners& a, const TriangleCorners& b) {
        for (const auto& corner : a.p)
            if (!sameCorner(corner, b.p[0]) && !sameCorner(corner, b.p[1]) &&
                !sameCorner(corner, b.p[2]))
                return false;
        return true;
    };
    return within(*this, other) && within(other, *this);
}

std::array<float, 9> TriangleCorners::sortedKey() const {
    std::array<std::array<float, 3>, 3> corners;
    for (int k = 0; k < 3; ++k)
        corners[std::size_t(k)] = {p[k][0], p[k][1], p[k][2]};
    std::sort(corners.begin(), corners.end());
    std::array<float, 9> key;
    for (std::size_t k = 0; k < 9; ++k)
        key[k] = corners[k / 3][k % 3];
    return key;
}

TriangleCorners TriangleCorners::of(PositionsView positions, std::size_t triangle) {
    TriangleCorners t;
    for (int k = 0; k < 3; ++k) {
        const std::size_t i = 3 * triangle + std::size_t(k);
        t.p[k][0] = positions.x[i];
        t.p[k][1] = positions.y[i];
        t.p[k][2] = positions.z[i];
    }
    return t;
}

ExactFragments::ExactFragments(const ViewProjection& view)
    : rays_(view), orthographic_(view.projection == Projection::orthographic), near_(view.near),
      far_(view.far), row_{view.view[2], view.view[6], view.view[10], view.view[14]} {}

ExactFragments::ExactFragments(const ExactFragments& other)
    : rays_(other.rays_), orthographic_(other.orthographic_), near_(other.near_),
      far_(other.far_), row_{other.row_[0], other.row_[1], other.row_[2], other.row_[3]} {}

bool ExactFragments::covers(const PixelRay& ray, const TriangleCorners& triangle) const {
    for (const auto& corner : triangle.p)
        if (!std::isfinite(corner[0]) || !std::isfinite(corner[1]) || !std::isfinite(corner[2]))
            return false; // such a triangle is never drawn
    if (hasRepeatedCorner(triangle))
        return false;
    const Corners3 c = cornersOf(triangle);
    double o[3], dir[3];
    toArray(ray.origin, o);
    toArray(ray.direction, dir);
    const BoundedVec d = exactVec(dir);
    const Bounded q = det3(difference(c.b, c.a), difference(c.c, c.a), d);
    const int q_sign = signOf(q);
    if (q_sign == 0)
        return coversExactly(ray, triangle);
    const BoundedVec a = difference(c.a, o), b = difference(c.b, o), cc = difference(c.c, o);
    const int sides[3] = {signOf(det3(a, b, d)), signOf(det3(b, cc, d)), signOf(det3(cc, a, d))};
    bool settled = true;
    for (int side : sides) {
        if (side == -q_sign)
            return false; // outside that edge: decided whatever the others are
        settled &= side == q_sign;
    }
    if (!settled)
        return coversExactly(ray, triangle);
    // The hit's eye-space distance against near (and far): sign(Q) ((zO - bound) Q + N zD).
    const Bounded n = det3(a, b, cc);
    const Bounded z_origin = -(exact(row_[0]) * exact(o[0]) + exact(row_[1]) * exact(o[1]) +
                               exact(row_[2]) * exact(o[2]) + exact(row_[3]));
    const Bounded z_direction = -(exact(row_[0]) * exact(dir[0]) + exact(row_[1]) * exact(dir[1]) +
                                  exact(row_[2]) * exact(dir[2]));
    const auto beyond = [&](double bound) {
        const Bounded side = (z_origin - exact(bound)) * q + n * z_direction;
        return signOf(side) * q_sign; // +1 beyond the bound, -1 before it, 0 unsettled
    };
    const int past_near = beyond(near_);
    if (past_near == 0)
        return coversExactly(ray, triangle);
    if (past_near < 0)
        return false;
    if (!orthographic_)
        return true;
    const int past_far = beyond(far_);
    if (past_far == 0)
        return coversExactly(ray, triangle);
    return past_far < 0;
}

bool ExactFragments::coversExactly(const PixelRay& ray, const TriangleCorners& triangle) const {
    exact_evaluations_.fetch_add(1, std::memory_order_relaxed);
    const ExactHit h = exactHit(ray, triangle);
    const int q_sign = sgn(h.q);
    if (q_sign == 0)
        return false;
    for (const Rational& side : h.s)
        if (sgn(side) == -q_sign)
            return false;
    double o[3], dir[3];
    toArray(ray.origin, o);
    toArray(ray.direction, dir);
    Rational z_origin = 0, z_direction = 0;
    for (int i = 0; i < 3; ++i) {
        z_origin -= Rational(row_[i]) * Rational(o[i]);
        z_direction -= Rational(row_[i]) * Rational(dir[i]);
    }
    z_origin -= Rational(row_[3]);
    const auto beyond = [&](double bound) {
        const Rational side = (z_origin - Rational(bound)) * h.q + h.n * z_direction;
        return sgn(side) * q_sign;
    };
    if (beyond(near_) < 0)
        return false;
    return !orthographic_ || beyond(far_) <= 0;
}

RayHit ExactFragments::hit(const PixelRay& ray, const TriangleCorners& triangle) const {
    const Corners3 c = cornersOf(triangle);
    double o[3], dir[3];
    toArray(ray.origin, o);
    toArray(ray.direction, dir);
    const BoundedVec a = difference(c.a, o), b = difference(c.b, o), cc = difference(c.c, o);
    RayHit h;
    h.q = det3(difference(c.b, c.a), difference(c.c, c.a), exactVec(dir));
    h.n = det3(a, b, cc);
    return h;
}

int ExactFragments::facing(const PixelRay& ray, const TriangleCorners& triangle) const {
    const int sign = signOf(hit(ray, triangle).q);
    if (sign != 0)
        return sign;
    exact_evaluations_.fetch_add(1, std::memory_order_relaxed);
    return sgn(exactHit(ray, triangle).q);
}

int ExactFragments::compare(const PixelRay& ray, const TriangleCorners& a, const RayHit& ha,
                            const TriangleCorners& b, const RayHit& hb) const {
    // t(a) - t(b) = na / qa - nb / qb has the sign of (na qb - nb qa) qa qb.
    const int qa = signOf(ha.q), qb = signOf(hb.q);
    if (qa != 0 && qb != 0) {
        const int difference = signOf(ha.n * hb.q - hb.n * ha.q);
        if (difference != 0)
            return difference * qa * qb;
    }
    if (a.sameCornersAs(b))
        return 0;
    return compareExactly(ray, a, b);
}

int ExactFragments::compareExactly(const PixelRay& ray, const TriangleCorners& a,
                                   const TriangleCorners& b) const {
    exact_evaluations_.fetch_add(1, std::memory_order_relaxed);
    const ExactParameter ha = exactParameter(ray, a), hb = exactParameter(ray, b);
    return sgn(ha.n * hb.q - hb.n * ha.q) * sgn(ha.q) * sgn(hb.q);
}

} // namespace vissort::detail
