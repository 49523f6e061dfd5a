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

using test::Triangle;
using test::triangleOf;

Scene makeSoup(const std::string& n, const std::string& seed = "1") {
    Result<Scene> scene = samples::makeBuiltinScene("soup", {{"n", n}, {"seed", seed}});
    EXPECT_TRUE(scene) << scene.error;
    return scene ? std::move(*scene.value) : Scene{};
}

double area(const Triangle& t) {
    return length(cross(t[1] - t[0], t[2] - t[0])) / 2;
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
    const Result<Scene> defaults = samples::makeBuiltinScene("soup", {});
    ASSERT_TRUE(defaults);
    EXPECT_EQ(defaults.value->triangleCount(), 1000u);
}

TEST(SoupScene, SameSeedSameBitsOtherSeedOtherTriangles) {
    const Scene a = makeSoup("300", "5"), b = makeSoup("300", "5"), c = makeSoup("300", "6");
    test::expectSameScene(a, b);
    EXPECT_NE(a.positions.x, c.positions.x);
}

TEST(SoupScene, NoTwoTrianglesIntersect) {
    const Scene scene = makeSoup("200", "11");
    const std::size_t n = scene.triangleCount();
    std::size_t intersecting = 0;
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b)
            intersecting += test::closedTrianglesMeet(triangleOf(scene, a), triangleOf(scene, b));
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
            for (int j = i + 1; j < 3; ++j)
                EXPECT_LT(length(tri[i] - tri[j]), 1.0);
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
    const CameraSpec& camera = *scene.camera;
    const Vec3 f = camera.target - camera.eye;
    const double half_fov = camera.fov_degrees / 2 * std::numbers::pi / 180;
    for (std::size_t i = 0; i < scene.positions.x.size(); ++i) {
        const Vec3 c = scene.positions.corner(i);
        const Vec3 d = c - camera.eye;
        const double cosine = dot(d, f) / (length(f) * length(d));
        EXPECT_LT(std::acos(std::min(1.0, cosine)), half_fov); // inside the image's inscribed cone
    }
}

} // namespace
} // namespace vissort
