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

Scene makeSoup(const std::string &n, const std::string &seed = "1") {
    Result<Scene> scene = makeBuiltinScene("soup", {{"n", n}, {"seed", seed}});
    EXPECT_TRUE(scene) << scene.error;
    return scene ? std::move(*scene.value) : Scene{};
}

Triangle triangleOf(const Scene &scene, std::size_t t) {
    return {scene.positions.corner(3 * t), scene.positions.corner(3 * t + 1),
            scene.positions.corner(3 * t + 2)};
}

double area(const Triangle &t) {
    const Vec3 e1{t[1].x - t[0].x, t[1].y - t[0].y, t[1].z - t[0].z};
    const Vec3 e2{t[2].x - t[0].x, t[2].y - t[0].y, t[2].z - t[0].z};
    const Vec3 n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
    return std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z) / 2;
}

TEST(SoupScene, OneObjectPerTriangle) {
    for (const int n : {1, 27, 28, 1000}) {
        const Scene scene = makeSoup(std::to_string(n));
        EXPECT_EQ(scene.triangleCount(), std::size_t(n));
        ASSERT_EQ(scene.objects.size(), std::size_t(n));
        for (int i = 0; i < n; ++i) {
            EXPECT_EQ(scene.objects[i].first_triangle, uint32_t(i));
            EXPECT_EQ(scene.objects[i].triangle_count, 1u);
            EXPECT_TRUE(scene.objects[i].transparent);
        }
        EXPECT_FALSE(scene.isDynamic());
    }
    const Result<Scene> defaults = makeBuiltinScene("soup", {});
    ASSERT_TRUE(defaults);
    EXPECT_EQ(defaults.value->triangleCount(), 1000u);
}

TEST(SoupScene, SameSeedSameBitsOtherSeedOtherTriangles) {
    const Scene a = makeSoup("300", "5"), b = makeSoup("300", "5"), c = makeSoup("300", "6");
    EXPECT_EQ(a.positions.x, b.positions.x);
    EXPECT_EQ(a.positions.y, b.positions.y);
    EXPECT_EQ(a.positions.z, b.positions.z);
    EXPECT_NE(a.positions.x, c.positions.x);
}

TEST(SoupScene, NoTwoTrianglesIntersect) {
    const Scene scene = makeSoup("200", "11");
    const std::size_t n = scene.triangleCount();
    std::size_t intersecting = 0;
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b)
            intersecting +=
                vissort_test::trianglesIntersect(triangleOf(scene, a), triangleOf(scene, b));
    EXPECT_EQ(intersecting, 0u);
}

TEST(SoupScene, TrianglesAreNonDegenerateSmallerThanACellAndFillTheCube) {
    const std::size_t n = 1000; // a 10 x 10 x 10 grid of unit cells
    const Scene scene = makeSoup(std::to_string(n));
    double smallest = 1e30;
    for (std::size_t t = 0; t < n; ++t) {
        const Triangle tri = triangleOf(scene, t);
        smallest = std::min(smallest, area(tri));
        for (int i = 0; i < 3; ++i)
            for (int j = i + 1; j < 3; ++j) {
                const double dx = tri[i].x - tri[j].x, dy = tri[i].y - tri[j].y,
                             dz = tri[i].z - tri[j].z;
                EXPECT_LT(std::sqrt(dx * dx + dy * dy + dz * dz), 1.0);
            }
    }
    EXPECT_GT(smallest, 1e-3);
    const Bounds bounds = scene.positions.bounds();
    for (const double low : {bounds.min.x, bounds.min.y, bounds.min.z}) {
        EXPECT_GE(low, -5.0);
        EXPECT_LT(low, -4.0); // the grid is full: the outer cells are used
    }
    for (const double high : {bounds.max.x, bounds.max.y, bounds.max.z}) {
        EXPECT_LE(high, 5.0);
        EXPECT_GT(high, 4.0);
    }
}

TEST(SoupScene, TriangleIdsAreNotInGridOrder) {
    // The cells are shuffled: consecutive ids are not neighbours along x.
    const Scene scene = makeSoup("1000");
    std::size_t increasing = 0;
    for (std::size_t t = 0; t + 1 < 1000; ++t)
        increasing += scene.positions.x[3 * (t + 1)] > scene.positions.x[3 * t];
    EXPECT_GT(increasing, 350u);
    EXPECT_LT(increasing, 650u);
}

TEST(SoupScene, DefaultCameraSeesEveryCorner) {
    const Scene scene = makeSoup("500");
    ASSERT_TRUE(scene.camera.has_value());
    const CameraSpec &camera = *scene.camera;
    const Vec3 f{camera.target.x - camera.eye.x, camera.target.y - camera.eye.y,
                 camera.target.z - camera.eye.z};
    const double f_length = std::sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
    const double half_fov = camera.fov_degrees / 2 * kPi / 180;
    for (std::size_t i = 0; i < scene.positions.x.size(); ++i) {
        const Vec3 c = scene.positions.corner(i);
        const Vec3 d{c.x - camera.eye.x, c.y - camera.eye.y, c.z - camera.eye.z};
        const double cosine = (d.x * f.x + d.y * f.y + d.z * f.z) /
                              (f_length * std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
        EXPECT_LT(std::acos(std::min(1.0, cosine)), half_fov); // inside the image's inscribed cone
    }
}

} // namespace
} // namespace vissort
