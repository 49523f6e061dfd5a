// Tests of the `plant` scene: parameters, determinism, closed outward meshes, the gaps between
// parts (against a brute-force triangle distance), the default camera, and the depth complexity
// it sees (against an independent ray-triangle test and the all-hits ray caster).

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "exact/ray_caster.h"
#include "scene_checks.h"
#include "scenes/scene_library.h"
#include "solid_checks.h"

namespace vissort {
namespace {

using test::boundsOf;
using test::rayHits;
using test::Triangle;
using test::triangleOf;

constexpr std::size_t kObjectsPerRow = 22; // 4 pipes, 8 columns, 8 beams, a pump, a tank
constexpr double kSmallestGap = 0.05; // the scene's gap between the floor and what stands on it

Scene makePlant(int layers, int seed = 1) {
    Result<Scene> scene = samples::makeBuiltinScene(
        "plant", {{"layers", std::to_string(layers)}, {"seed", std::to_string(seed)}});
    EXPECT_TRUE(scene) << scene.error;
    return scene ? std::move(*scene.value) : Scene{};
}

bool hasPart(const std::string& name, const std::string& part) {
    return name.find(part) != std::string::npos;
}

Bounds boundsOf(const Scene& scene, const SceneObject& object) {
    return test::boundsOf(scene, object.first_triangle, object.triangle_count);
}

TEST(PlantScene, DefaultsAreEightLayersAndSeedOne) {
    const Result<Scene> defaults = samples::makeBuiltinScene("plant", {});
    ASSERT_TRUE(defaults) << defaults.error;
    const Scene explicit_scene = makePlant(8, 1);
    EXPECT_EQ(defaults.value->name, "builtin:plant");
    EXPECT_EQ(defaults.value->objects.size(), 1 + 8 * kObjectsPerRow);
    EXPECT_EQ(defaults.value->positions.x, explicit_scene.positions.x);
    EXPECT_EQ(defaults.value->positions.z, explicit_scene.positions.z);
    EXPECT_FALSE(defaults.value->isDynamic());
    EXPECT_EQ(validateScene(*defaults.value).error, "");
}

TEST(PlantScene, BadParametersAreOneLineErrorsNamingTheKey) {
    const test::ParameterErrorCase cases[] = {
        {{{"layers", "0"}},
         "builtin:plant: parameter layers=0 is out of range (allowed 1 to 1000)"},
        {{{"layers", "1001"}}, "builtin:plant: parameter layers=1001 is out of range"},
        {{{"layers", "-3"}}, "builtin:plant: parameter layers=-3 is out of range"},
        {{{"layers", "2.5"}}, "builtin:plant: parameter layers='2.5' is not an integer"},
        {{{"seed", "-1"}}, "builtin:plant: parameter seed='-1' is not a non-negative integer"},
        {{{"n", "3"}}, "builtin:plant: unknown parameter 'n' (accepted: layers, seed)"},
    };
    test::expectParameterErrors("plant", cases);
    EXPECT_TRUE(
        samples::makeBuiltinScene("plant", {{"layers", "1000"}, {"seed", "18446744073709551615"}}));
}

TEST(PlantScene, SameSeedSameBitsOtherSeedOtherPlant) {
    const Scene a = makePlant(6, 7), b = makePlant(6, 7), c = makePlant(6, 8);
    ASSERT_TRUE(a.camera);
    test::expectSameScene(a, b);
    EXPECT_NE(a.positions.x, c.positions.x);
}

TEST(PlantScene, EveryRowHasItsNamedPartsAndModerateTriangleCounts) {
    std::size_t previous_triangles = 0;
    for (const int layers : {1, 2, 5, 12}) {
        const Scene scene = makePlant(layers);
        ASSERT_EQ(scene.objects.size(), 1 + layers * kObjectsPerRow);
        EXPECT_EQ(validateScene(scene).error, "");
        EXPECT_EQ(scene.objects[0].name, "floor");
        EXPECT_GT(scene.triangleCount(), previous_triangles);
        previous_triangles = scene.triangleCount();
        for (int row = 0; row < layers; ++row) {
            const std::string prefix = "row" + std::to_string(row) + "_";
            std::set<std::string> expected = {prefix + "pump", prefix + "tank"};
            for (int i = 0; i < 4; ++i)
                expected.insert(prefix + "pipe_" + std::to_string(i));
            for (int i = 0; i < 8; ++i) {
                expected.insert(prefix + "column_" + std::to_string(i));
                expected.insert(prefix + "beam_" + std::to_string(i));
            }
            std::set<std::string> names;
            std::size_t row_triangles = 0;
            for (std::size_t i = 0; i < kObjectsPerRow; ++i) {
                const SceneObject& object = scene.objects[1 + row * kObjectsPerRow + i];
                names.insert(object.name);
                row_triangles += object.triangle_count;
            }
            EXPECT_EQ(names, expected) << "row " << row;
            EXPECT_GE(row_triangles, 2000u) << "row " << row;
            EXPECT_LE(row_triangles, 6000u) << "row " << row;
        }
    }
}

TEST(PlantScene, PipesAndTanksAreTransparentSteelAndConcreteOpaque) {
    const Scene scene = makePlant(10, 3);
    std::size_t transparent = 0, opaque = 0;
    for (const SceneObject& object : scene.objects) {
        const bool equipment = hasPart(object.name, "_pipe_") || hasPart(object.name, "_tank");
        EXPECT_EQ(object.transparent, equipment) << object.name;
        if (object.transparent) {
            ++transparent;
            EXPECT_GE(object.colour.a, 0.3f) << object.name;
            EXPECT_LE(object.colour.a, 0.6f) << object.name;
        } else {
            ++opaque;
            EXPECT_EQ(object.colour.a, 1.0f) << object.name;
        }
    }
    EXPECT_EQ(transparent, 10u * 5);
    EXPECT_EQ(opaque, 1 + 10u * 17);
}

TEST(PlantScene, EveryObjectIsClosedWoundOutwardsWithoutDegenerateTriangles) {
    for (const int seed : {1, 2}) {
        const Scene scene = makePlant(3, seed);
        for (const SceneObject& object : scene.objects) {
            const test::MeshCheck mesh = test::checkMesh(scene, object);
            EXPECT_EQ(mesh.unmatched_edges, 0u) << object.name;
            EXPECT_GT(mesh.smallest_area, 1e-4) << object.name;
            EXPECT_GT(mesh.volume, 0.0) << object.name << ": wound inwards";
        }
    }
}

TEST(PlantScene, PartsNeverTouchAndKeepTheSmallestGapApart) {
    for (const int seed : {1, 4, 9}) {
        const Scene scene = makePlant(2, seed);
        // Boxes farther apart than twice the gap cannot hold closer triangles.
        const test::GapCheck gaps = test::checkGaps(scene, 0.98 * kSmallestGap, 2 * kSmallestGap);
        EXPECT_TRUE(gaps.too_close.empty()) << gaps.too_close.size() << " pairs, the first "
                                            << gaps.too_close.front() << " (seed " << seed << ")";
        EXPECT_GT(gaps.pairs_checked, 0u);
        // Parts rest on each other: the gap is reached, so the check above looked at them.
        EXPECT_LT(gaps.closest, 1.02 * kSmallestGap) << "seed " << seed;
    }
}

TEST(PlantScene, DefaultCameraFramesThePlantFromTheFrontAtTheHeadersHeight) {
    for (const int layers : {1, 8, 40}) {
        const Scene scene = makePlant(layers);
        ASSERT_TRUE(scene.camera.has_value());
        const CameraSpec& camera = *scene.camera;
        EXPECT_EQ(camera.projection, Projection::perspective);
        EXPECT_EQ(validateCamera(camera).error, "");
        const Bounds bounds = scene.positions.bounds();
        EXPECT_GT(camera.eye.z, bounds.max.z); // in front of the first row
        EXPECT_EQ(camera.eye.x, 0.0);
        EXPECT_EQ(camera.target.x, 0.0);
        EXPECT_GT(camera.eye.y, camera.target.y); // slightly from above
        EXPECT_GT(camera.eye.y, 0.5 * bounds.max.y);
        // The eye is at the height of every header's axis: inside each header's height range.
        for (const SceneObject& object : scene.objects) {
            if (!hasPart(object.name, "_pipe_3"))
                continue;
            const Bounds header = boundsOf(scene, object);
            EXPECT_GT(camera.eye.y, header.min.y + 0.3) << object.name;
            EXPECT_LT(camera.eye.y, header.max.y - 0.3) << object.name;
            EXPECT_LT(header.min.x, -2.0) << object.name;
            EXPECT_GT(header.max.x, 2.0) << object.name;
        }
        // Every corner of the plant inside a square image's field of view.
        const Vec3 forward = normalized(camera.target - camera.eye);
        const Vec3 right = normalized(cross(forward, camera.up));
        const Vec3 up = cross(right, forward);
        const double reach = std::tan(camera.fov_degrees / 2 * std::numbers::pi / 180);
        for (std::size_t i = 0; i < scene.positions.x.size(); ++i) {
            const Vec3 d = scene.positions.corner(i) - camera.eye;
            const double depth = dot(d, forward);
            ASSERT_GT(depth, 0.0);
            EXPECT_LT(std::abs(dot(d, right)), depth * reach);
            EXPECT_LT(std::abs(dot(d, up)), depth * reach);
        }
    }
}

TEST(PlantScene, RayAlongTheRowsAtTheEyesHeightCrossesEveryHeaderAndNothingElse) {
    for (const int layers : {1, 7, 20}) {
        const Scene scene = makePlant(layers, 5);
        // Off the axis by a little, so that the ray passes no triangle edge exactly.
        const Vec3 origin = scene.camera->eye + Vec3{0.013, 0.037, 0};
        const Vec3 direction{0, 0, -1};
        std::map<std::string, int> hits;
        for (std::size_t t = 0; t < scene.triangleCount(); ++t)
            if (rayHits(origin, direction, triangleOf(scene, t)))
                ++hits[scene.objects[scene.objectOfTriangle(static_cast<uint32_t>(t))].name];
        ASSERT_EQ(hits.size(), std::size_t(layers));
        for (int row = 0; row < layers; ++row)
            EXPECT_EQ(hits["row" + std::to_string(row) + "_pipe_3"], 2) << "row " << row;
    }
}

TEST(PlantScene, MaximumDepthComplexityIsAboutTwiceTheLayers) {
    // What `vissort info` measures: all hits through 256 x 256 pixel centres of the default view.
    std::size_t previous = 0;
    for (const int layers : {4, 8, 16}) {
        const Scene scene = makePlant(layers);
        const Bounds bounds = scene.positions.bounds();
        const ViewProjection view = frameCamera(*scene.camera, bounds, 256, 256);
        const detail::AllHits hits = detail::castAllHits(scene.positions, view);
        std::size_t most = 0;
        for (std::size_t p = 0; p < hits.pixelCount(); ++p)
            most = std::max<std::size_t>(most, hits.endHit(p) - hits.firstHit(p));
        EXPECT_GE(double(most), 0.7 * 2 * layers) << "layers " << layers;
        EXPECT_LE(double(most), 1.3 * 2 * layers) << "layers " << layers;
        EXPECT_GT(most, previous);
        previous = most;
    }
}

} // namespace
} // namespace vissort
