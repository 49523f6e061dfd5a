// The brute-force reference the slabs and soup tests use to prove their triangles disjoint, and
// tests of that reference on hand-made pairs.

#include <array>

#include <gtest/gtest.h>

#include "vissort/geometry.h"

namespace vissort_test {

using Triangle = std::array<vissort::Vec3, 3>;

namespace {

using vissort::Vec3;

// Six times the signed volume of the tetrahedron (a, b, c, d).
double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return dot(cross(b - a, c - a), d - a);
}

// Conservative: touching and coplanar cases count as crossing, so "no pair crosses" is strict.
bool segmentCrossesTriangle(const Vec3& p, const Vec3& q, const Triangle& t) {
    const double sp = orient(t[0], t[1], t[2], p), sq = orient(t[0], t[1], t[2], q);
    if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0))
        return false;
    const double e0 = orient(p, q, t[0], t[1]), e1 = orient(p, q, t[1], t[2]),
                 e2 = orient(p, q, t[2], t[0]);
    return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
}

} // namespace

/// True when the closed triangles a and b share a point. Two non-coplanar triangles meet along a
/// segment whose ends lie on edges of a or of b, so testing the six edges suffices.
bool trianglesIntersect(const Triangle& a, const Triangle& b) {
    for (int i = 0; i < 3; ++i) {
        if (segmentCrossesTriangle(a[i], a[(i + 1) % 3], b))
            return true;
        if (segmentCrossesTriangle(b[i], b[(i + 1) % 3], a))
            return true;
    }
    return false;
}

namespace {

TEST(TriangleIntersectionReference, PiercingTrianglesIntersect) {
    const Triangle floor = {{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}};
    const Triangle pierce = {{{0, 0, -1}, {0, 0, 1}, {0, 5, 0.5}}}; // edge through the interior
    EXPECT_TRUE(trianglesIntersect(floor, pierce));
    EXPECT_TRUE(trianglesIntersect(pierce, floor));
}

TEST(TriangleIntersectionReference, InterlockedTrianglesIntersect) {
    // Each passes through the other's edge only: a chain-link configuration.
    const Triangle a = {{{0, 0, 0}, {2, 0, 0}, {1, 2, 0}}};
    const Triangle b = {{{1, 1, -1}, {1, 1, 1}, {1, -2, 0}}};
    EXPECT_TRUE(trianglesIntersect(a, b));
}

TEST(TriangleIntersectionReference, SeparatedTrianglesDoNot) {
    const Triangle a = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    const Triangle above = {{{0, 0, 0.01}, {1, 0, 0.02}, {0, 1, 0.03}}};
    const Triangle beside = {{{0.6, 0.6, -1}, {0.6, 0.6, 1}, {2, 2, 0}}}; // past the hypotenuse
    EXPECT_FALSE(trianglesIntersect(a, above));
    EXPECT_FALSE(trianglesIntersect(a, beside));
}

TEST(TriangleIntersectionReference, SharedCornerCountsAsIntersecting) {
    const Triangle a = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    const Triangle b = {{{0, 0, 0}, {-1, 0, 1}, {0, -1, 1}}};
    EXPECT_TRUE(trianglesIntersect(a, b));
}

} // namespace
} // namespace vissort_test
