// The brute-force checks of solid_checks.h on hand-made cases with known answers: the plant
// tests trust them to find meshes that are open or wound inwards and parts that come too close.

#include "solid_checks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vissort::test {
namespace {

// A scene of one object per triangle list.
Scene sceneOf(const std::vector<std::vector<Triangle>>& objects) {
    Scene scene;
    for (const std::vector<Triangle>& triangles : objects) {
        SceneObject object{"object_" + std::to_string(scene.objects.size()),
                           {1, 1, 1, 1},
                           false,
                           uint32_t(scene.triangleCount()),
                           uint32_t(triangles.size())};
        for (const Triangle& t : triangles)
            for (const Vec3& v : t) {
                scene.positions.x.push_back(float(v.x));
                scene.positions.y.push_back(float(v.y));
                scene.positions.z.push_back(float(v.z));
            }
        scene.objects.push_back(object);
    }
    return scene;
}

// The unit cube [0, 1]^3 shifted by `at`, wound outwards.
std::vector<Triangle> cube(const Vec3& at = {0, 0, 0}) {
    std::vector<Triangle> out;
    const auto corner = [&](int i) {
        return Vec3{at.x + (i & 1), at.y + ((i >> 1) & 1), at.z + ((i >> 2) & 1)};
    };
    // Faces as corner indices counter-clockwise seen from outside.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        out.push_back({corner(f[0]), corner(f[1]), corner(f[2])});
        out.push_back({corner(f[0]), corner(f[2]), corner(f[3])});
    }
    return out;
}

TEST(SolidChecks, TriangleDistancesOfKnownPairs) {
    const Triangle base{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    // Piercing: an edge of one passes through the other.
    EXPECT_EQ(triangleDistance(base, {{{0.2, 0.2, -1}, {0.3, 0.2, 1}, {0.2, 0.3, 1}}}), 0.0);
    // Coplanar and overlapping.
    EXPECT_NEAR(triangleDistance(base, {{{0.1, 0.1, 0}, {2, 0.1, 0}, {0.1, 2, 0}}}), 0.0, 1e-12);
    // Parallel, 0.01 apart.
    EXPECT_NEAR(triangleDistance(base, {{{0, 0, 0.01}, {1, 0, 0.01}, {0, 1, 0.01}}}), 0.01, 1e-12);
    // Skew edges: base's edge along x at z = 0 and an edge along y at x = 0.5, z = 0.3, wholly
    // beyond y < 0.
    EXPECT_NEAR(triangleDistance(base, {{{0.5, -2, 0.3}, {0.5, -1e-9, 0.3}, {0.5, -1, 2}}}), 0.3,
                1e-8);
    // A corner above the inside: the distance is its height.
    EXPECT_NEAR(triangleDistance(base, {{{0.2, 0.2, 0.5}, {0.2, 0.2, 3}, {0.3, 0.3, 3}}}), 0.5,
                1e-12);
}

TEST(SolidChecks, ClosestPointInEveryRegion) {
    const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    const auto expectAt = [&](const Vec3& p, const Vec3& expected) {
        const Vec3 q = closestOnTriangle(p, a, b, c);
        EXPECT_NEAR(q.x, expected.x, 1e-12);
        EXPECT_NEAR(q.y, expected.y, 1e-12);
        EXPECT_NEAR(q.z, expected.z, 1e-12);
    };
    expectAt({-1, -1, 1}, a);
    expectAt({2, -0.5, 0}, b);
    expectAt({-0.5, 2, 0}, c);
    expectAt({0.5, -1, 0}, {0.5, 0, 0});    // edge ab
    expectAt({-1, 0.5, 0}, {0, 0.5, 0});    // edge ac
    expectAt({1, 1, 0}, {0.5, 0.5, 0});     // edge bc
    expectAt({0.2, 0.3, 4}, {0.2, 0.3, 0}); // inside
}

TEST(SolidChecks, MeshesClosedOpenAndInsideOut) {
    std::vector<Triangle> flipped = cube(), open = cube();
    for (Triangle& t : flipped)
        std::swap(t[1], t[2]);
    open.pop_back(); // one triangle of the last face missing: its three edges unmatched
    const Scene scene = sceneOf({cube(), flipped, open});
    const MeshCheck closed = checkMesh(scene, scene.objects[0]);
    EXPECT_EQ(closed.unmatched_edges, 0u);
    EXPECT_NEAR(closed.volume, 1.0, 1e-12);
    EXPECT_NEAR(closed.smallest_area, 0.5, 1e-12);
    EXPECT_NEAR(checkMesh(scene, scene.objects[1]).volume, -1.0, 1e-12);
    EXPECT_EQ(checkMesh(scene, scene.objects[2]).unmatched_edges, 3u);
}

TEST(SolidChecks, GapsBetweenObjects) {
    // Three cubes: the second 0.01 beyond the first, the third 2 beyond the second.
    const Scene scene = sceneOf({cube(), cube({1.01, 0, 0}), cube({4.01, 0, 0})});
    const GapCheck near = checkGaps(scene, 0.02, 0.5);
    EXPECT_NEAR(near.closest, 0.01, 1e-6);
    ASSERT_EQ(near.too_close.size(), 1u);
    EXPECT_EQ(near.too_close.front(), "object_0 and object_1");
    const GapCheck apart = checkGaps(scene, 0.005, 0.5);
    EXPECT_TRUE(apart.too_close.empty());
    EXPECT_GT(apart.pairs_checked, 0u);
}

} // namespace
} // namespace vissort::test
