#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "vissort/scene_library.h"

namespace vissort_test {
using Triangle = std::array<vissort::Vec3, 3>;
bool trianglesIntersect(const Triangle &a, const Triangle &b); // triangle_intersection_tests.cpp
} // namespace vissort_test

namespace vissort {
namespace {

using vissort_test::Triangle;

constexpr double kPi = 3.14159265358979323846;

Scene makeSlabs(const std::string &layers, const std::string &seed = "1") {
    Result<Scene> scene = makeBuiltinScene("slabs", {{"layers", layers}, {"seed", seed}});
    EXPECT_TRUE(scene) << scene.error;
    return scene ? std::move(*scene.value) : Scene{};
}

Triangle triangleOf(const Scene &scene, std::size_t t) {
    return {scene.positions.corner(3 * t), scene.positions.corner(3 * t + 1),
            scene.positions.corner(3 * t + 2)};
}

// Moeller-Trumbore, both sides, hits at distance > 0.
bool rayHits(const Vec3 &o, const Vec3 &d, const Triangle &t) {
    const Vec3 e1{t[1].x - t[0].x, t[1].y - t[0].y, t[1].z - t[0].z};
    const Vec3 e2{t[2].x - t[0].x, t[2].y - t[0].y, t[2].z - t[0].z};
    const Vec3 p{d.y * e2.z - d.z * e2.y, d.z * e2.x - d.x * e2.z, d.x * e2.y - d.y * e2.x};
    const double det = e1.x * p.x + e1.y * p.y + e1.z * p.z;
    if (std::abs(det) < 1e-15)
        return false;
    const Vec3 s{o.x - t[0].x, o.y - t[0].y, o.z - t[0].z};
    const double u = (s.x * p.x + s.y * p.y + s.z * p.z) / det;
    const Vec3 q{s.y * e1.z - s.z * e1.y, s.z * e1.x - s.x * e1.z, s.x * e1.y - s.y * e1.x};
    const double v = (d.x * q.x + d.y * q.y + d.z * q.z) / det;
    const double distance = (e2.x * q.x + e2.y * q.y + e2.z * q.z) / det;
    return u >= 0 && v >= 0 && u + v <= 1 && distance > 0;
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
    const Result<Scene> defaults = makeBuiltinScene("slabs", {});
    ASSERT_TRUE(defaults);
    EXPECT_EQ(defaults.value->triangleCount(), 16u);
}

TEST(SlabsScene, SameSeedSameBitsOtherSeedOtherTilts) {
    const Scene a = makeSlabs("50", "7"), b = makeSlabs("50", "7"), c = makeSlabs("50", "8");
    EXPECT_EQ(a.positions.x, b.positions.x);
    EXPECT_EQ(a.positions.y, b.positions.y);
    EXPECT_EQ(a.positions.z, b.positions.z);
    EXPECT_NE(a.positions.z, c.positions.z);
}

TEST(SlabsScene, QuadsAreFlatSquaresTiltedLessThanFourDegrees) {
    const Scene scene = makeSlabs("200");
    bool some_tilt = false;
    for (std::size_t layer = 0; layer < 200; ++layer) {
        const Triangle t0 = triangleOf(scene, 2 * layer), t1 = triangleOf(scene, 2 * layer + 1);
        // Two triangles sharing a diagonal of a planar quad: the 4th corner is coplanar.
        const Vec3 e1{t0[1].x - t0[0].x, t0[1].y - t0[0].y, t0[1].z - t0[0].z};
        const Vec3 e2{t0[2].x - t0[0].x, t0[2].y - t0[0].y, t0[2].z - t0[0].z};
        Vec3 n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
        const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        EXPECT_NEAR(length, 16.0, 1e-3); // twice the area of half a 4 x 4 quad
        n = {n.x / length, n.y / length, n.z / length};
        for (const Vec3 &p : t1) {
            const double off_plane =
                n.x * (p.x - t0[0].x) + n.y * (p.y - t0[0].y) + n.z * (p.z - t0[0].z);
            EXPECT_NEAR(off_plane, 0.0, 1e-3);
        }
        const double tilt_degrees = std::acos(std::min(1.0, std::abs(n.z))) * 180 / kPi;
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
            EXPECT_FALSE(
                vissort_test::trianglesIntersect(triangleOf(scene, a), triangleOf(scene, b)))
                << a << " " << b;
        }
    }
    // A horizontal plane between consecutive layers: every layer is strictly below the next,
    // so the stack's order is the same (acyclic) from every viewpoint.
    const TrianglePositions &p = scene.positions;
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
    const CameraSpec &camera = *scene.camera;
    EXPECT_EQ(camera.projection, Projection::perspective);
    EXPECT_DOUBLE_EQ(camera.eye.x, camera.target.x);
    EXPECT_DOUBLE_EQ(camera.eye.y, camera.target.y);
    const Bounds bounds = scene.positions.bounds();
    EXPECT_GT(camera.eye.z, bounds.max.z);
    EXPECT_LT(camera.target.z, camera.eye.z);
    // Every corner inside the vertical (and, for square images, horizontal) field of view.
    const double half_fov = std::tan(camera.fov_degrees / 2 * kPi / 180);
    for (std::size_t i = 0; i < scene.positions.x.size(); ++i) {
        const Vec3 c = scene.positions.corner(i);
        const double depth = camera.eye.z - c.z;
        EXPECT_LT(std::abs(c.x - camera.eye.x), depth * half_fov);
        EXPECT_LT(std::abs(c.y - camera.eye.y), depth * half_fov);
    }
    // Rays near the centre of the image hit every quad: depth complexity = layers.
    for (const auto &[dx, dy] : {std::pair{0.01, 0.02}, {0.05, -0.03}, {-0.04, 0.0}}) {
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
