// The generator checks of scene_checks.h.

#include "scene_checks.h"
#include "scenes/scene_library.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vissort::test {
namespace {

void expectSameCamera(const CameraSpec& a, const CameraSpec& b) {
    EXPECT_EQ(a.eye.x, b.eye.x);
    EXPECT_EQ(a.eye.y, b.eye.y);
    EXPECT_EQ(a.eye.z, b.eye.z);
    EXPECT_EQ(a.target.x, b.target.x);
    EXPECT_EQ(a.target.y, b.target.y);
    EXPECT_EQ(a.target.z, b.target.z);
}

} // namespace

void expectParameterErrors(const std::string& scene, std::span<const ParameterErrorCase> cases) {
    for (const ParameterErrorCase& c : cases) {
        const Result<Scene> made = samples::makeBuiltinScene(scene, c.parameters);
        EXPECT_FALSE(made) << c.expected;
        EXPECT_NE(made.error.find(c.expected), std::string::npos) << made.error;
        EXPECT_EQ(made.error.find('\n'), std::string::npos) << made.error;
    }
}

void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.positions.x, b.positions.x);
    EXPECT_EQ(a.positions.y, b.positions.y);
    EXPECT_EQ(a.positions.z, b.positions.z);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const SceneObject &x = a.objects[i], &y = b.objects[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.first_triangle, y.first_triangle) << x.name;
        EXPECT_EQ(x.triangle_count, y.triangle_count) << x.name;
        EXPECT_EQ(x.transparent, y.transparent) << x.name;
        EXPECT_EQ(x.colour.r, y.colour.r) << x.name;
        EXPECT_EQ(x.colour.g, y.colour.g) << x.name;
        EXPECT_EQ(x.colour.b, y.colour.b) << x.name;
        EXPECT_EQ(x.colour.a, y.colour.a) << x.name;
    }
    ASSERT_EQ(a.camera.has_value(), b.camera.has_value());
    if (a.camera)
        expectSameCamera(*a.camera, *b.camera);
    ASSERT_EQ(a.camera_path.size(), b.camera_path.size());
    for (std::size_t k = 0; k < a.camera_path.size(); ++k) {
        EXPECT_EQ(a.camera_path[k].time, b.camera_path[k].time);
        expectSameCamera(a.camera_path[k].camera, b.camera_path[k].camera);
    }
}

Scene makeCountedScene(const std::string& name, const std::string& n, const std::string& seed) {
    Result<Scene> scene = samples::makeBuiltinScene(name, {{"n", n}, {"seed", seed}});
    EXPECT_TRUE(scene) << scene.error;
    return scene ? std::move(*scene.value) : Scene{};
}

TrianglePositions frameAt(const Scene& scene, double t) {
    TrianglePositions positions;
    scene.animation->positionsAt(t, positions);
    return positions;
}

void expectNumberedObjects(const Scene& scene, const std::string& prefix, uint32_t count,
                           uint32_t triangles_each, float alpha) {
    ASSERT_EQ(scene.objects.size(), count);
    EXPECT_EQ(scene.triangleCount(), std::size_t(count) * triangles_each);
    for (uint32_t i = 0; i < count; ++i) {
        EXPECT_EQ(scene.objects[i].name, prefix + std::to_string(i));
        EXPECT_EQ(scene.objects[i].first_triangle, i * triangles_each);
        EXPECT_EQ(scene.objects[i].triangle_count, triangles_each);
        EXPECT_TRUE(scene.objects[i].transparent);
        EXPECT_FLOAT_EQ(scene.objects[i].colour.a, alpha);
    }
    if (count >= 2) {
        const Rgba a = scene.objects[0].colour, b = scene.objects[1].colour;
        EXPECT_GT(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 0.1f);
    }
}

} // namespace vissort::test
