// The exact orientation predicates against CGAL's exact ones (Exact_predicates_inexact_
// constructions_kernel: filtered, with an exact fallback) on random and adversarial float
// inputs: near-degenerate by one ulp, exactly degenerate, and magnitudes from 1e-30 to 1e30. The
// adversarial sets are checked to defeat the plain double formula, so agreement means something.

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include "geometry/exact_predicates.h"

namespace vissort {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = std::array<float, 3>;
using P2 = std::array<float, 2>;

int referenceOrient3d(const P3& a, const P3& b, const P3& c, const P3& d) {
    const auto point = [](const P3& p) { return Kernel::Point_3(p[0], p[1], p[2]); };
    return int(CGAL::orientation(point(a), point(b), point(c), point(d)));
}

int referenceOrient2d(const P2& a, const P2& b, const P2& c) {
    const auto point = [](const P2& p) { return Kernel::Point_2(p[0], p[1]); };
    return int(CGAL::orientation(point(a), point(b), point(c)));
}

// The formula the predicates replace: every operation rounded in double.
int naiveOrient3d(const P3& a, const P3& b, const P3& c, const P3& d) {
    const double bx = double(b[0]) - a[0], by = double(b[1]) - a[1], bz = double(b[2]) - a[2];
    const double cx = double(c[0]) - a[0], cy = double(c[1]) - a[1], cz = double(c[2]) - a[2];
    const double dx = double(d[0]) - a[0], dy = double(d[1]) - a[1], dz = double(d[2]) - a[2];
    const double det =
        bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
    return (det > 0) - (det < 0);
}

int naiveOrient2d(const P2& a, const P2& b, const P2& c) {
    const double det = (double(b[0]) - a[0]) * (double(c[1]) - a[1]) -
                       (double(b[1]) - a[1]) * (double(c[0]) - a[0]);
    return (det > 0) - (det < 0);
}

class Inputs {
public:
    explicit Inputs(uint32_t seed) : rng_(seed) {}

    float uniform(float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(rng_);
    }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    // Any finite float, every exponent equally likely.
    float anyFloat() {
        for (;;) {
            const uint32_t bits = uint32_t(rng_());
            float f;
            std::memcpy(&f, &bits, sizeof f);
            if (std::isfinite(f))
                return f;
        }
    }
    // Moves f by k ulps.
    static float ulps(float f, int k) {
        for (; k > 0; --k)
            f = std::nextafter(f, INFINITY);
        for (; k < 0; ++k)
            f = std::nextafter(f, -INFINITY);
        return f;
    }
    P3 point3(float lo, float hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    std::mt19937& rng() { return rng_; }

private:
    std::mt19937 rng_;
};

struct Tally {
    int cases = 0, positive = 0, zero = 0, negative = 0, naive_wrong = 0;
    void add(int expected, int naive) {
        ++cases;
        positive += expected > 0;
        zero += expected == 0;
        negative += expected < 0;
        naive_wrong += naive != expected;
    }
};

// Checks orient3d and its 24 corner permutations' signs against CGAL on one quadruple.
void check3d(const P3& a, const P3& b, const P3& c, const P3& d, Tally& tally) {
    const int expected = referenceOrient3d(a, b, c, d);
    ASSERT_EQ(detail::orient3d(a.data(), b.data(), c.data(), d.data()), expected)
        << a[0] << ' ' << a[1] << ' ' << a[2] << " | " << b[0] << ' ' << b[1] << ' ' << b[2]
        << " | " << c[0] << ' ' << c[1] << ' ' << c[2] << " | " << d[0] << ' ' << d[1] << ' '
        << d[2];
    // Odd permutations flip the sign.
    ASSERT_EQ(detail::orient3d(b.data(), a.data(), c.data(), d.data()), -expected);
    ASSERT_EQ(detail::orient3d(a.data(), c.data(), d.data(), b.data()), expected);
    ASSERT_EQ(detail::orient3d(d.data(), b.data(), c.data(), a.data()), -expected);
    // The batched forms: corners against a plane, and a line against directed edges.
    int sides[3];
    detail::orient3dPlaneSides(a.data(), b.data(), c.data(), d.data(), a.data(), d.data(), sides);
    ASSERT_EQ(sides[0], expected);
    ASSERT_EQ(sides[1], 0);
    ASSERT_EQ(sides[2], expected);
    detail::orient3dEdgeSides(a.data(), b.data(), c.data(), d.data(), c.data(), sides);
    ASSERT_EQ(sides[0], expected);  // orient3d(a, b, c, d)
    ASSERT_EQ(sides[1], -expected); // orient3d(a, b, d, c)
    ASSERT_EQ(sides[2], 0);         // orient3d(a, b, c, c)
    tally.add(expected, naiveOrient3d(a, b, c, d));
}

void check2d(const P2& a, const P2& b, const P2& c, Tally& tally) {
    const int expected = referenceOrient2d(a, b, c);
    ASSERT_EQ(detail::orient2d(a.data(), b.data(), c.data()), expected)
        << a[0] << ' ' << a[1] << " | " << b[0] << ' ' << b[1] << " | " << c[0] << ' ' << c[1];
    ASSERT_EQ(detail::orient2d(b.data(), a.data(), c.data()), -expected);
    ASSERT_EQ(detail::orient2d(b.data(), c.data(), a.data()), expected);
    tally.add(expected, naiveOrient2d(a, b, c));
}

constexpr int kCases = 20000;

TEST(ExactPredicates, SignConventions) {
    const float o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1};
    EXPECT_EQ(detail::orient3d(o, x, y, z), 1); // d on the side of (b - a) x (c - a)
    EXPECT_EQ(detail::orient3d(o, y, x, z), -1);
    EXPECT_EQ(detail::orient3d(o, x, y, o), 0);
    EXPECT_EQ(detail::orient3d(o, o, o, o), 0);
    const float p[2] = {0, 0}, q[2] = {1, 0}, r[2] = {0, 1};
    EXPECT_EQ(detail::orient2d(p, q, r), 1); // counter-clockwise
    EXPECT_EQ(detail::orient2d(p, r, q), -1);
    EXPECT_EQ(detail::orient2d(p, q, q), 0);
    // CGAL's conventions are the same, so the comparisons below are meaningful.
    EXPECT_EQ(referenceOrient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), 1);
    EXPECT_EQ(referenceOrient2d({0, 0}, {1, 0}, {0, 1}), 1);
}

TEST(ExactPredicates, Orient3dRandom) {
    Inputs in(1);
    Tally uniform, wide;
    for (int i = 0; i < kCases; ++i)
        check3d(in.point3(-1, 1), in.point3(-1, 1), in.point3(-1, 1), in.point3(-1, 1), uniform);
    for (int i = 0; i < kCases; ++i) {
        P3 p[4];
        for (P3& q : p)
            q = {in.anyFloat(), in.anyFloat(), in.anyFloat()};
        check3d(p[0], p[1], p[2], p[3], wide);
    }
    EXPECT_GT(uniform.positive, 0);
    EXPECT_GT(uniform.negative, 0);
    EXPECT_GT(wide.positive, 0);
    EXPECT_GT(wide.negative, 0);
}

// d on the plane (a, b, c) rounded to float, then moved by up to two ulps per coordinate.
TEST(ExactPredicates, Orient3dNearCoplanar) {
    Inputs in(2);
    Tally tally;
    for (int i = 0; i < kCases; ++i) {
        const float scale = std::ldexp(1.0f, in.integer(-60, 60));
        const P3 a = in.point3(-scale, scale), b = in.point3(-scale, scale),
                 c = in.point3(-scale, scale);
        const double s = in.uniform(-1, 2), t = in.uniform(-1, 2);
        P3 d;
        for (int k = 0; k < 3; ++k)
            d[k] = Inputs::ulps(float(a[k] + s * (double(b[k]) - a[k]) + t * (double(c[k]) - a[k])),
                                in.integer(-2, 2));
        check3d(a, b, c, d, tally);
    }
    EXPECT_GT(tally.positive, 0);
    EXPECT_GT(tally.negative, 0);
}

// Exactly coplanar integer points up to 2^24 (the products of three exceed 53 bits), and the
// same moved by one unit: the naive formula misreads many of the zeros.
TEST(ExactPredicates, Orient3dExactlyCoplanarLarge) {
    Inputs in(3);
    Tally tally;
    for (int i = 0; i < kCases; ++i) {
        P3 a, u, v;
        for (int k = 0; k < 3; ++k) {
            a[k] = float(in.integer(-(1 << 22), 1 << 22));
            u[k] = float(in.integer(-(1 << 20), 1 << 20));
            v[k] = float(in.integer(-(1 << 20), 1 << 20));
        }
        const int i1 = in.integer(-2, 2), j1 = in.integer(-2, 2);
        P3 b, c, d;
        for (int k = 0; k < 3; ++k) {
            b[k] = a[k] + u[k];
            c[k] = a[k] + v[k];
            d[k] = a[k] + float(i1) * u[k] + float(j1) * v[k]; // exact: integers below 2^24
        }
        if (i % 2 == 1)
            d[in.integer(0, 2)] += float(in.integer(0, 1) * 2 - 1);
        // Scaling by a power of two keeps every sign: from about 1e-30 to 1e30.
        const int shift = in.integer(-140, 70);
        for (P3* p : {&a, &b, &c, &d})
            for (float& x : *p)
                x = std::ldexp(x, shift);
        check3d(a, b, c, d, tally);
    }
    EXPECT_GT(tally.zero, kCases / 4);
    EXPECT_GT(tally.positive, 0);
    EXPECT_GT(tally.negative, 0);
    EXPECT_GT(tally.naive_wrong, 0) << "the adversarial set should defeat plain double";
}

// Four coplanar points through the origin at moderate magnitude, then one replaced by a point
// of magnitude 1e-30: the sign hangs on the tiny point, whose differences from the others round
// away in double.
TEST(ExactPredicates, Orient3dMixedMagnitudes) {
    Inputs in(4);
    Tally tally;
    for (int i = 0; i < kCases; ++i) {
        P3 u, v;
        for (int k = 0; k < 3; ++k) {
            u[k] = float(in.integer(-1000, 1000));
            v[k] = float(in.integer(-1000, 1000));
        }
        P3 b, c, d;
        const int i1 = in.integer(-3, 3), j1 = in.integer(-3, 3);
        for (int k = 0; k < 3; ++k) {
            b[k] = u[k];
            c[k] = v[k];
            d[k] = float(i1) * u[k] + float(j1) * v[k];
        }
        const float tiny = 1e-30f;
        P3 a = {tiny * in.uniform(-1, 1), tiny * in.uniform(-1, 1), tiny * in.uniform(-1, 1)};
        if (i % 4 == 0)
            a = {0, 0, 0};
        const float big = i % 3 == 0 ? std::ldexp(1.0f, 100) : 1.0f; // about 1.3e30
        for (P3* p : {&b, &c, &d})
            for (float& x : *p)
                x *= big; // exact: small integers times one float
        check3d(a, b, c, d, tally);
        check3d(b, c, d, a, tally);
    }
    EXPECT_GT(tally.zero, 0);
    EXPECT_GT(tally.positive, 0);
    EXPECT_GT(tally.negative, 0);
    EXPECT_GT(tally.naive_wrong, 0) << "the adversarial set should defeat plain double";
}

TEST(ExactPredicates, Orient2dRandom) {
    Inputs in(5);
    Tally uniform, wide;
    for (int i = 0; i < kCases; ++i) {
        const auto p = [&] { return P2{in.uniform(-1, 1), in.uniform(-1, 1)}; };
        check2d(p(), p(), p(), uniform);
        const auto q = [&] { return P2{in.anyFloat(), in.anyFloat()}; };
        check2d(q(), q(), q(), wide);
    }
    EXPECT_GT(uniform.positive, 0);
    EXPECT_GT(uniform.negative, 0);
    EXPECT_GT(wide.positive, 0);
    EXPECT_GT(wide.negative, 0);
}

// c on line ab rounded to float and moved by up to two ulps; and exactly collinear points
// through the origin with a third one replaced by a point of magnitude 1e-30.
TEST(ExactPredicates, Orient2dNearlyCollinear) {
    Inputs in(6);
    Tally rounded, tiny;
    for (int i = 0; i < kCases; ++i) {
        const float scale = std::ldexp(1.0f, in.integer(-60, 60));
        const P2 a{in.uniform(-scale, scale), in.uniform(-scale, scale)};
        const P2 b{in.uniform(-scale, scale), in.uniform(-scale, scale)};
        const double t = in.uniform(-2, 3);
        P2 c;
        for (int k = 0; k < 2; ++k)
            c[k] = Inputs::ulps(float(a[k] + t * (double(b[k]) - a[k])), in.integer(-2, 2));
        check2d(a, b, c, rounded);

        const P2 u{float(in.integer(-1000, 1000)), float(in.integer(-1000, 1000))};
        const float big = i % 2 == 0 ? std::ldexp(1.0f, 100) : 1.0f;
        const P2 p{u[0] * big, u[1] * big};
        const int m = in.integer(-5, 5);
        const P2 q{u[0] * float(m) * big, u[1] * float(m) * big};
        P2 small{1e-30f * in.uniform(-1, 1), 1e-30f * in.uniform(-1, 1)};
        if (i % 5 == 0)
            small = {0, 0};
        check2d(small, p, q, tiny);
        check2d(p, small, q, tiny);
    }
    EXPECT_GT(rounded.positive, 0);
    EXPECT_GT(rounded.negative, 0);
    EXPECT_GT(tiny.zero, 0);
    EXPECT_GT(tiny.positive, 0);
    EXPECT_GT(tiny.negative, 0);
    EXPECT_GT(tiny.naive_wrong, 0) << "the adversarial set should defeat plain double";
}

// The largest and smallest floats: no overflow or underflow inside the predicates.
TEST(ExactPredicates, ExtremeMagnitudes) {
    const float big = std::numeric_limits<float>::max();
    const float small = std::numeric_limits<float>::denorm_min();
    Tally tally;
    const float values[] = {big, -big, small, -small, 0.0f, 1.0f, -1.0f};
    Inputs in(7);
    for (int i = 0; i < kCases; ++i) {
        const auto v = [&] { return values[in.integer(0, 6)]; };
        check3d({v(), v(), v()}, {v(), v(), v()}, {v(), v(), v()}, {v(), v(), v()}, tally);
        check2d({v(), v()}, {v(), v()}, {v(), v()}, tally);
    }
    EXPECT_GT(tally.zero, 0);
    EXPECT_GT(tally.positive, 0);
    EXPECT_GT(tally.negative, 0);
}

} // namespace
} // namespace vissort
