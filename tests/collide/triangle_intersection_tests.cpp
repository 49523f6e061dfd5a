// The exact triangle-triangle test against CGAL's exact do_intersect (filtered predicates with
// an exact fallback), on hand-made contacts and near misses, degenerate triangles (segments and
// points, which CGAL is given as Segment_3 and Point_3) and many thousands of random pairs, most
// of them built to touch exactly or to miss by an ulp. Every answer is checked in both argument
// orders and under corner permutations, and every category must produce both answers.

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "collide/triangle_intersection.h"
#include "reference_triangles.h"

namespace vissort {
namespace {

using detail::TriangleCorners;
using detail::trianglesIntersect;
using P3 = std::array<float, 3>;

// ---- the reference ---------------------------------------------------------------------------

// The corners as doubles (exactly).
std::array<Vec3, 3> exactCorners(const TriangleCorners& t) {
    std::array<Vec3, 3> corners;
    for (int c = 0; c < 3; ++c)
        corners[c] = {t[c][0], t[c][1], t[c][2]};
    return corners;
}

// CGAL's answer on the same corners.
bool referenceIntersect(const TriangleCorners& a, const TriangleCorners& b) {
    return test::closedTrianglesMeet(exactCorners(a), exactCorners(b));
}

bool isFlat(const TriangleCorners& t) {
    return test::isDegenerateTriangle(exactCorners(t));
}

// ---- checking under symmetries -------------------------------------------------------------

constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                     {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};

TriangleCorners permuted(const TriangleCorners& t, int permutation) {
    const int* p = kPermutations[permutation];
    return {t[p[0]], t[p[1]], t[p[2]]};
}

std::string describe(const TriangleCorners& a, const TriangleCorners& b) {
    std::string s;
    char buffer[64];
    for (const TriangleCorners* t : {&a, &b}) {
        s += t == &a ? "a:" : " b:";
        for (const auto& c : *t) {
            std::snprintf(buffer, sizeof buffer, " (%a, %a, %a)", c[0], c[1], c[2]);
            s += buffer;
        }
    }
    return s;
}

// Both argument orders under every pair of corner permutations (72 calls).
void expectEverywhere(const TriangleCorners& a, const TriangleCorners& b, bool expected) {
    for (int pa = 0; pa < 6; ++pa)
        for (int pb = 0; pb < 6; ++pb) {
            const TriangleCorners ap = permuted(a, pa), bp = permuted(b, pb);
            ASSERT_EQ(trianglesIntersect(ap, bp), expected) << describe(ap, bp);
            ASSERT_EQ(trianglesIntersect(bp, ap), expected) << describe(bp, ap);
        }
}

struct Outcomes {
    int met = 0, missed = 0;
};

// Checks a pair against CGAL: every permutation for the first pairs of a category, then both
// orders and one random permutation each (the permutations are covered many times over).
void checkPair(const TriangleCorners& a, const TriangleCorners& b, Outcomes& outcomes,
               std::mt19937& rng) {
    const bool expected = referenceIntersect(a, b);
    (expected ? outcomes.met : outcomes.missed) += 1;
    if (outcomes.met + outcomes.missed <= 200) {
        expectEverywhere(a, b, expected);
        return;
    }
    const TriangleCorners ap = permuted(a, int(rng() % 6)), bp = permuted(b, int(rng() % 6));
    ASSERT_EQ(trianglesIntersect(ap, bp), expected) << describe(ap, bp);
    ASSERT_EQ(trianglesIntersect(bp, ap), expected) << describe(bp, ap);
}

// A hand-made case: the expected answer, confirmed by CGAL too, everywhere.
void checkFixture(const TriangleCorners& a, const TriangleCorners& b, bool expected,
                  Outcomes& outcomes) {
    ASSERT_EQ(referenceIntersect(a, b), expected) << "fixture is wrong: " << describe(a, b);
    (expected ? outcomes.met : outcomes.missed) += 1;
    expectEverywhere(a, b, expected);
}

float up(float f) {
    return std::nextafter(f, INFINITY);
}
float down(float f) {
    return std::nextafter(f, -INFINITY);
}

// The triangle most fixtures meet: in the plane z = 0, legs of 4 along x and y.
const TriangleCorners kBase = {{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}};

// ---- hand-made cases -------------------------------------------------------------------------

TEST(TriangleIntersection, Coplanar) {
    Outcomes o;
    checkFixture(kBase, {{{1, 1, 0}, {5, 1, 0}, {1, 5, 0}}}, true, o);       // overlapping
    checkFixture(kBase, {{{4, 0, 0}, {6, 0, 0}, {5, 2, 0}}}, true, o);       // vertex on vertex
    checkFixture(kBase, {{{2, 2, 0}, {4, 4, 0}, {5, 1, 0}}}, true, o);       // vertex on edge
    checkFixture(kBase, {{{1, 0, 0}, {3, 0, 0}, {2, -2, 0}}}, true, o);      // collinear edges
    checkFixture(kBase, {{{4, 0, 0}, {6, 0, 0}, {5, -2, 0}}}, true, o);      // edges end to end
    checkFixture(kBase, {{{2, -1, 0}, {2, 5, 0}, {-1, 2, 0}}}, true, o);     // edges crossing
    checkFixture(kBase, {{{1, 1, 0}, {2, 1, 0}, {1, 2, 0}}}, true, o);       // b inside a
    checkFixture(kBase, {{{-1, -1, 0}, {10, -1, 0}, {-1, 10, 0}}}, true, o); // a inside b
    checkFixture(kBase, kBase, true, o);                                     // identical
    checkFixture(kBase, {{{3, 3, 0}, {6, 3, 0}, {3, 6, 0}}}, false, o);      // disjoint
    checkFixture(kBase, {{{5, 0, 0}, {7, 0, 0}, {6, -2, 0}}}, false, o);     // collinear, apart
    // One ulp beyond the hypotenuse x + y = 4, and one ulp short of it.
    checkFixture(kBase, {{{2, up(2), 0}, {4, 4, 0}, {5, 1, 0}}}, false, o);
    checkFixture(kBase, {{{2, down(2), 0}, {4, 4, 0}, {5, 1, 0}}}, true, o);
    checkFixture(kBase, {{{up(4), 0, 0}, {6, 0, 0}, {5, -2, 0}}}, false, o);
    // A relative gap of about 1e-7.
    checkFixture(kBase, {{{2, 2.0000002f, 0}, {4, 4, 0}, {5, 1, 0}}}, false, o);
    EXPECT_GT(o.met, 0);
    EXPECT_GT(o.missed, 0);
}

TEST(TriangleIntersection, CrossingPlanes) {
    Outcomes o;
    const float tiny = std::numeric_limits<float>::denorm_min();
    checkFixture(kBase, {{{1, 1, -1}, {1, 1, 1}, {2, 1, 1}}}, true, o); // edge through face
    checkFixture(kBase, {{{1, 1, 0}, {1, 1, 3}, {2, 2, 3}}}, true, o);  // vertex on face
    checkFixture(kBase, {{{1, 1, tiny}, {1, 1, 3}, {2, 2, 3}}}, false, o);
    checkFixture(kBase, {{{1, 1, -tiny}, {1, 1, 3}, {2, 2, 3}}}, true, o);
    checkFixture(kBase, {{{1, 1, 1e-7f}, {1, 1, 3}, {2, 2, 3}}}, false, o);
    checkFixture(kBase, {{{0, 0, 0}, {-1, -1, 1}, {-1, 0, 2}}}, true, o); // vertex on vertex
    checkFixture(kBase, {{{0, 0, tiny}, {-1, -1, 1}, {-1, 0, 2}}}, false, o);
    checkFixture(kBase, {{{2, 0, 0}, {2, -1, 1}, {3, -1, 2}}}, true, o); // vertex on edge
    checkFixture(kBase, {{{2, -tiny, 0}, {2, -1, 1}, {3, -1, 2}}}, false, o);
    checkFixture(kBase, {{{1, 1, 0}, {2, 1, 0}, {1, 1, 2}}}, true, o);  // edge on face
    checkFixture(kBase, {{{-1, 1, 0}, {5, 1, 0}, {1, 1, 2}}}, true, o); // edge across face
    checkFixture(kBase, {{{4, 0, 0}, {0, 4, 0}, {2, 2, 5}}}, true, o);  // edge on edge
    checkFixture(kBase, {{{5, 0, 0}, {5, 4, 0}, {5, 2, 5}}}, false, o); // edge in plane, out
    // Edge against edge at the single point (2, 0, 0) of a's edge; then an ulp below.
    checkFixture(kBase, {{{2, -1, 1}, {2, 1, -1}, {2, -3, 0}}}, true, o);
    const float d = 0x1p-23f;
    checkFixture(kBase, {{{2, -1, 1 - d}, {2, 1, -1 - d}, {2, -3, -d}}}, false, o);
    // Piercing both ways (the intersection is a segment inside both).
    checkFixture(kBase, {{{1, 1, -1}, {3, 0.5f, 1}, {0.5f, 2, 1}}}, true, o);
    // Separated: all of b above a's plane, and a plane-straddling miss beside it.
    checkFixture(kBase, {{{0, 0, 1}, {4, 0, 1}, {0, 4, 1}}}, false, o);
    checkFixture(kBase, {{{5, 5, -1}, {6, 5, 1}, {5, 6, 1}}}, false, o);
    EXPECT_GT(o.met, 0);
    EXPECT_GT(o.missed, 0);
}

TEST(TriangleIntersection, Degenerate) {
    Outcomes o;
    const float tiny = std::numeric_limits<float>::denorm_min();
    // Segments against a triangle.
    checkFixture(kBase, {{{1, 1, -1}, {1, 1, 1}, {1, 1, 0.5f}}}, true, o); // through face
    checkFixture(kBase, {{{1, 1, 1}, {1, 1, 2}, {1, 1, 3}}}, false, o);    // above
    checkFixture(kBase, {{{1, 1, 0}, {1, 1, 1}, {1, 1, 2}}}, true, o);     // ending on face
    checkFixture(kBase, {{{1, 1, tiny}, {1, 1, 1}, {1, 1, 2}}}, false, o);
    checkFixture(kBase, {{{1, 1, 0}, {2, 1, 0}, {3, 1, 0}}}, true, o);  // in the face
    checkFixture(kBase, {{{5, 5, 0}, {6, 6, 0}, {7, 7, 0}}}, false, o); // in the plane, out
    checkFixture(kBase, {{{2, 2, 0}, {3, 3, 0}, {5, 5, 0}}}, true, o);  // ending on an edge
    checkFixture(kBase, {{{2, up(2), 0}, {3, 3, 0}, {5, 5, 0}}}, false, o);
    checkFixture(kBase, {{{-1, 2, 0}, {5, 2, 0}, {5, 2, 0}}}, true, o);   // two equal corners
    checkFixture(kBase, {{{-1, -1, 1}, {5, 5, -1}, {2, 2, 0}}}, true, o); // across, 3D
    // Points against a triangle.
    checkFixture(kBase, {{{1, 1, 0}, {1, 1, 0}, {1, 1, 0}}}, true, o);
    checkFixture(kBase, {{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}}, false, o);
    checkFixture(kBase, {{{4, 0, 0}, {4, 0, 0}, {4, 0, 0}}}, true, o);
    checkFixture(kBase, {{{2, 0, 0}, {2, 0, 0}, {2, 0, 0}}}, true, o);
    checkFixture(kBase, {{{2, -tiny, 0}, {2, -tiny, 0}, {2, -tiny, 0}}}, false, o);
    // Segments against segments.
    const TriangleCorners diagonal = {{{0, 0, 0}, {2, 2, 2}, {1, 1, 1}}};
    checkFixture(diagonal, {{{0, 2, 0}, {2, 0, 2}, {1, 1, 1}}}, true, o);           // crossing
    checkFixture(diagonal, {{{0, 2, 1}, {2, 0, 1}, {0, 2, 1}}}, true, o);           // crossing
    checkFixture(diagonal, {{{0, 2, 1.5f}, {2, 0, 1.5f}, {1, 1, 1.5f}}}, false, o); // skew
    checkFixture(diagonal, {{{0, 2, 2}, {2, 0, 0}, {0, 2, 2}}}, true, o); // crossing, coplanar
    checkFixture(diagonal, {{{0, 2, up(2)}, {2, 0, 0}, {0, 2, up(2)}}}, false, o); // one ulp
    checkFixture(diagonal, {{{1, 1, 1}, {3, 3, 3}, {2, 2, 2}}}, true, o); // collinear overlap
    checkFixture(diagonal, {{{2, 2, 2}, {3, 3, 3}, {4, 4, 4}}}, true, o); // collinear touch
    checkFixture(diagonal, {{{up(2), up(2), up(2)}, {3, 3, 3}, {4, 4, 4}}}, false, o);
    checkFixture(diagonal, {{{0, 1, 0}, {2, 3, 2}, {1, 2, 1}}}, false, o); // parallel
    // Points against segments and points.
    checkFixture(diagonal, {{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}}, true, o);
    checkFixture(diagonal, {{{1, 1, up(1)}, {1, 1, up(1)}, {1, 1, up(1)}}}, false, o);
    checkFixture(diagonal, {{{3, 3, 3}, {3, 3, 3}, {3, 3, 3}}}, false, o);
    const TriangleCorners point = {{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}}};
    checkFixture(point, point, true, o);
    checkFixture(point, {{{1, 2, up(3)}, {1, 2, up(3)}, {1, 2, up(3)}}}, false, o);
    EXPECT_GT(o.met, 0);
    EXPECT_GT(o.missed, 0);
}

// ---- random pairs --------------------------------------------------------------------------

class Generator {
public:
    explicit Generator(uint32_t seed) : rng(seed) {}
    std::mt19937 rng;

    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    P3 point(float lo, float hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    // Multiples of 1/64 in [-1, 1]: sums and halves of a few of them stay exact.
    float dyadic() { return float(integer(-64, 64)) / 64; }
    P3 dyadicPoint() { return {dyadic(), dyadic(), dyadic()}; }
    TriangleCorners triangleNear(const P3& centre, float size) {
        TriangleCorners t;
        for (auto& c : t)
            for (int k = 0; k < 3; ++k)
                c[k] = centre[k] + uniform(-size, size);
        return t;
    }
    // Moves one coordinate of p by an ulp either way, or not at all.
    void nudge(P3& p) {
        const int k = integer(0, 2);
        switch (integer(0, 2)) {
        case 0:
            p[k] = up(p[k]);
            break;
        case 1:
            p[k] = down(p[k]);
            break;
        default:
            break;
        }
    }
};

constexpr int kPairs = 10000;

void expectBoth(const Outcomes& o, const char* category) {
    std::printf("  %-28s %6d met, %6d missed\n", category, o.met, o.missed);
    EXPECT_GT(o.met, 0) << category;
    EXPECT_GT(o.missed, 0) << category;
}

TEST(TriangleIntersection, RandomNearPairs) {
    Generator g(11);
    Outcomes o;
    for (int i = 0; i < kPairs; ++i) {
        const P3 centre = g.point(-1, 1);
        const TriangleCorners a = g.triangleNear(centre, 0.5f);
        const P3 shifted = {centre[0] + g.uniform(-0.5f, 0.5f), centre[1] + g.uniform(-0.5f, 0.5f),
                            centre[2] + g.uniform(-0.5f, 0.5f)};
        const TriangleCorners b = g.triangleNear(shifted, 0.5f);
        checkPair(a, b, o, g.rng);
    }
    expectBoth(o, "near pairs");
}

// Corners on a 4 x 4 x 4 grid: coplanar, collinear and coincident corners, shared vertices,
// edges on faces and degenerate triangles all happen often. Scaled by powers of two (exact)
// from about 1e-30 to 1e30.
TEST(TriangleIntersection, RandomGrid) {
    Generator g(12);
    Outcomes o, degenerate;
    for (int i = 0; i < 3 * kPairs; ++i) {
        TriangleCorners t[2];
        for (auto& tri : t)
            for (auto& c : tri)
                for (float& x : c)
                    x = float(g.integer(0, 3));
        const int shift = i % 3 == 0 ? g.integer(-100, 100) : 0;
        for (auto& tri : t)
            for (auto& c : tri)
                for (float& x : c)
                    x = std::ldexp(x, shift);
        const bool flat = isFlat(t[0]) || isFlat(t[1]);
        checkPair(t[0], t[1], flat ? degenerate : o, g.rng);
    }
    expectBoth(o, "grid");
    expectBoth(degenerate, "grid, degenerate");
}

// Degenerate triangles with exactly collinear dyadic corners (segments, and points) against
// triangles and each other, on a grid fine enough for near misses and coarse enough to touch.
TEST(TriangleIntersection, RandomDegenerate) {
    Generator g(13);
    Outcomes vs_triangle, vs_degenerate, points;
    const auto degenerate = [&](const P3& p) {
        P3 u{float(g.integer(-8, 8)) / 64, float(g.integer(-8, 8)) / 64,
             float(g.integer(-8, 8)) / 64};
        if (g.integer(0, 5) == 0)
            u = {0, 0, 0};
        TriangleCorners t;
        for (auto& c : t) {
            const float m = float(g.integer(-2, 2));
            for (int k = 0; k < 3; ++k)
                c[k] = p[k] + m * u[k];
        }
        return t;
    };
    for (int i = 0; i < kPairs; ++i) {
        const TriangleCorners d = degenerate(g.dyadicPoint());
        TriangleCorners t;
        for (auto& c : t)
            c = g.dyadicPoint();
        // Often put a corner of t on d, or one of d's on t's edge midpoint.
        if (i % 3 == 0)
            t[0] = d[g.integer(0, 2)];
        checkPair(d, t, isFlat(t) ? vs_degenerate : vs_triangle, g.rng);
        // Through a corner of d, or on a random line.
        const TriangleCorners e = degenerate(i % 3 == 1 ? d[g.integer(0, 2)] : g.dyadicPoint());
        checkPair(d, e, vs_degenerate, g.rng);
        TriangleCorners dot;
        dot[0] = dot[1] = dot[2] = i % 2 == 0 ? d[0] : g.dyadicPoint();
        g.nudge(dot[0]);
        dot[1] = dot[2] = dot[0];
        checkPair(dot, i % 2 == 0 ? t : d, points, g.rng);
    }
    expectBoth(vs_triangle, "degenerate vs triangle");
    expectBoth(vs_degenerate, "degenerate vs degenerate");
    expectBoth(points, "points");
}

// a in the plane z = 0.5 (exact), b with a corner snapped onto that plane and moved by an ulp
// or not, its other corners on either side.
TEST(TriangleIntersection, RandomSnappedToPlane) {
    Generator g(14);
    Outcomes above, straddling, flat;
    for (int i = 0; i < kPairs; ++i) {
        TriangleCorners a;
        for (auto& c : a)
            c = {g.uniform(-1, 1), g.uniform(-1, 1), 0.5f};
        TriangleCorners b;
        b[0] = {g.uniform(-1, 1), g.uniform(-1, 1), 0.5f};
        if (g.integer(0, 1) == 0)
            b[0][2] = g.integer(0, 1) ? up(0.5f) : down(0.5f);
        const bool straddle = i % 2 == 1;
        for (int c = 1; c < 3; ++c)
            b[c] = {g.uniform(-1, 1), g.uniform(-1, 1),
                    straddle && c == 2 ? g.uniform(0, 0.5f) : g.uniform(0.5f, 1)};
        checkPair(a, b, straddle ? straddling : above, g.rng);
        // Coplanar pairs in the same plane, some corners shared.
        TriangleCorners c;
        for (auto& corner : c)
            corner = {g.uniform(-1, 1), g.uniform(-1, 1), 0.5f};
        if (i % 4 == 0)
            c[1] = a[2];
        checkPair(a, c, flat, g.rng);
    }
    expectBoth(above, "snapped, above");
    expectBoth(straddling, "snapped, straddling");
    expectBoth(flat, "coplanar in z = 0.5");
}

// Dyadic triangles with b's first corner on a's vertex, edge midpoint or an interior point
// (a0 + a1 + 2 a2) / 4, all exact; then moved by an ulp or not.
TEST(TriangleIntersection, RandomSnappedToFeatures) {
    Generator g(15);
    Outcomes shared_vertex, on_edge, on_face, shared_edge;
    for (int i = 0; i < kPairs; ++i) {
        TriangleCorners a;
        for (auto& c : a)
            c = g.dyadicPoint();
        TriangleCorners b;
        for (auto& c : b)
            c = g.point(-1, 1);
        const int feature = i % 4;
        P3 x;
        for (int k = 0; k < 3; ++k) {
            switch (feature) {
            case 0:
                x[k] = a[0][k];
                break;
            case 1:
                x[k] = (a[0][k] + a[1][k]) / 2;
                break;
            case 2:
                x[k] = (a[0][k] + a[1][k] + 2 * a[2][k]) / 4;
                break;
            default:
                x[k] = a[1][k];
                break;
            }
        }
        b[0] = x;
        if (feature == 3)
            b[1] = a[0]; // a shared edge
        else
            g.nudge(b[0]);
        Outcomes* outcomes[4] = {&shared_vertex, &on_edge, &on_face, &shared_edge};
        checkPair(a, b, *outcomes[feature], g.rng);
    }
    expectBoth(shared_vertex, "shared vertex, nudged");
    expectBoth(on_edge, "on an edge, nudged");
    expectBoth(on_face, "on a face, nudged");
    EXPECT_GT(shared_edge.met, 0); // a shared edge always touches
    EXPECT_EQ(shared_edge.missed, 0);
}

} // namespace
} // namespace vissort
