#include <array>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "reference_triangles.h"
#include "scene_checks.h"
#include "scenes/scene_library.h"
#include "solid_checks.h"

namespace vissort {
namespace {

using test::rayHits;
using test::Triangle;
using test::triangleOf;

Scene makeSlabs(const std::string& layers, const std::string& seed = "1") {
    Result<Scene> scene = samples::makeBuiltinScene("slabs", {{"layers", layers}, {"seed", seed}});
    EXPECT_TRUE(scene) << scene.error;
    return scene ? std::move(*scene.value) : Scene{};
}

TEST(SlabsScene, CountsAndObjects) {
    for (const int layers : {1, 8, 1000}) {
        const Scene scene = makeSlabs(std::to_string(layers));
        EXPECT_EQ(scene.triangleCount(), 2u * layers);
        ASSERT_EQ(scene.objects.size(), std::size_t(layers));
        for (int i = 0; i < layers; ++i) {
            EXPECT_EQ(scene.objects[i].first_triangle, 2u * i);
            EXPECT_EQ(scene.objects[i].triangle_count, 2u);
            EXPECT_TRUE(scene.objects[i].transparent);
            EXPECT_FLOAT_EQ(scene.objects[i].colour.a, 0.4f);
        }
        EXPECT_FALSE(scene.isDynamic());
    }
    const Result<Scene> defaults = samples::makeBuiltinScene("slabs", {});
    ASSERT_TRUE(defaults);
    EXPECT_EQ(defaults.value->triangleCount(), 16u);
}

TEST(SlabsScene, SameSeedSameBitsOtherSeedOtherTilts) {
    const Scene a = makeSlabs("50", "7"), b = makeSlabs("50", "7"), c = makeSlabs("50", "8");
    test::expectSameScene(a, b);
    EXPECT_NE(a.positions.z, c.positions.z);
}

TEST(SlabsScene, QuadsAreFlatSquaresTiltedLessThanFourDegrees) {
    const Scene scene = makeSlabs("200");
    bool some_tilt = false;
    for (std::size_t layer = 0; layer < 200; ++layer) {
        const Triangle t0 = triangleOf(scene, 2 * layer), t1 = triangleOf(scene, 2 * layer + 1);
        // Two triangles sharing a diagonal of a planar quad: the 4th corner is coplanar.
        const Vec3 normal = cross(t0[1] - t0[0], t0[2] - t0[0]);
        EXPECT_NEAR(length(normal), 16.0, 1e-3); // twice the area of half a 4 x 4 quad
        const Vec3 n = normalized(normal);
        for (const Vec3& p : t1)
            EXPECT_NEAR(dot(n, p - t0[0]), 0.0, 1e-3);
        const double tilt_degrees =
            std::acos(std::min(1.0, std::abs(n.z))) * 180 / std::numbers::pi;
        EXPECT_LT(tilt_degrees, 4.0);
        some_tilt |= tilt_degrees > 0.1;
    }
    EXPECT_TRUE(some_tilt);
}

TEST(SlabsScene, QuadsNeverIntersectAndPlanesSeparateTheLayers) {
    const Scene scene = makeSlabs("40", "3");
    const std::size_t triangles = scene.triangleCount();
    for (std::size_t a = 0; a < triangles; ++a) {
        for (std::size_t b = (a / 2 + 1) * 2; b < triangles; ++b) { // triangles of later quads
            EXPECT_FALSE(test::closedTrianglesMeet(triangleOf(scene, a), triangleOf(scene, b)))
                << a << " " << b;
        }
    }
    // A horizontal plane between consecutive layers: every layer is strictly below the next,
    // so the stack's order is the same (acyclic) from every viewpoint.
    const TrianglePositions& p = scene.positions;
    for (std::size_t layer = 0; layer + 1 < 40; ++layer) {
        float top = -1e30f, next_bottom = 1e30f;
        for (std::size_t i = 0; i < 6; ++i) {
            top = std::max(top, p.z[layer * 6 + i]);
            next_bottom = std::min(next_bottom, p.z[(layer + 1) * 6 + i]);
        }
        EXPECT_LT(top, next_bottom) << layer;
    }
}

TEST(SlabsScene, CameraLooksDownTheStackAndMiddleRaysCrossEveryLayer) {
    const std::size_t layers = 30;
    const Scene scene = makeSlabs(std::to_string(layers));
    ASSERT_TRUE(scene.camera.has_value());
    const CameraSpec& camera = *scene.camera;
    EXPECT_EQ(camera.projection, Projection::perspective);
    EXPECT_DOUBLE_EQ(camera.eye.x, camera.target.x);
    EXPECT_DOUBLE_EQ(camera.eye.y, camera.target.y);
    const Bounds bounds = scene.positions.bounds();
    EXPECT_GT(camera.eye.z, bounds.max.z);
    EXPECT_LT(camera.target.z, camera.eye.z);
    // Every corner inside the vertical (and, for square images, horizontal) field of view.
    const double half_fov = std::tan(camera.fov_degrees / 2 * std::numbers::pi / 180);
    for (std::size_t i = 0; i < scene.positions.x.size(); ++i) {
        const Vec3 c = scene.positions.corner(i);
        const double depth = camera.eye.z - c.z;
        EXPECT_LT(std::abs(c.x - camera.eye.x), depth * half_fov);
        EXPECT_LT(std::abs(c.y - camera.eye.y), depth * half_fov);
    }
    // Rays near the centre of the image hit every quad: depth complexity = layers.
    for (const auto& [dx, dy] : {std::pair{0.01, 0.02}, {0.05, -0.03}, {-0.04, 0.0}}) {
        const Vec3 direction{dx, dy, -1};
        for (std::size_t layer = 0; layer < layers; ++layer) {
            const bool hit = rayHits(camera.eye, direction, triangleOf(scene, 2 * layer)) ||
                             rayHits(camera.eye, direction, triangleOf(scene, 2 * layer + 1));
            EXPECT_TRUE(hit) << "layer " << layer;
        }
    }
}

} // namespace
} // namespace vissort
