// Scene specifications (loadScene), the Scene queries and validateScene; the samples' built-in
// scenes through samples::loadScene.

#include "scenes/scene_library.h"
#include "vissort/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>

namespace vissort {
namespace {

namespace fs = std::filesystem;

const std::string kSource = VISSORT_SOURCE_DIR;

/// Three objects of 2, 1 and 3 triangles; triangle t has every corner at x = t.
Scene handMadeScene() {
    Scene scene;
    scene.name = "hand";
    scene.positions.resize(6);
    for (std::size_t c = 0; c < 18; ++c) {
        scene.positions.x[c] = static_cast<float>(c / 3);
        scene.positions.y[c] = static_cast<float>(c % 3 == 1);
        scene.positions.z[c] = static_cast<float>(c % 3 == 2);
    }
    scene.objects = {
        {"a", Rgba{}, false, 0, 2}, {"b", Rgba{}, false, 2, 1}, {"c", Rgba{}, true, 3, 3}};
    return scene;
}

void expectFailure(const Result<Scene>& loaded, const std::string& contains) {
    ASSERT_FALSE(loaded) << "expected an error containing '" << contains << "'";
    EXPECT_EQ(loaded.error.find('\n'), std::string::npos) << loaded.error;
    EXPECT_NE(loaded.error.find(contains), std::string::npos) << loaded.error;
}

// --- Scene queries ---

TEST(Scene, ObjectOfTriangleMatchesALinearScan) {
    const Scene scene = handMadeScene();
    for (uint32_t t = 0; t < 6; ++t) {
        uint32_t expected = 0;
        for (uint32_t o = 0; o < scene.objects.size(); ++o)
            if (t >= scene.objects[o].first_triangle &&
                t < scene.objects[o].first_triangle + scene.objects[o].triangle_count)
                expected = o;
        EXPECT_EQ(scene.objectOfTriangle(t), expected) << "triangle " << t;
    }
}

TEST(Scene, PrimitivesPerObjectAndPerTriangle) {
    const Scene scene = handMadeScene();
    const std::vector<PrimitiveRange> objects = scene.objectPrimitives();
    ASSERT_EQ(objects.size(), 3u);
    EXPECT_EQ(objects[1].first_triangle, 2u);
    EXPECT_EQ(objects[1].triangle_count, 1u);
    EXPECT_EQ(objects[2].first_triangle, 3u);
    EXPECT_EQ(objects[2].triangle_count, 3u);
    const std::vector<PrimitiveRange> triangles = scene.trianglePrimitives();
    ASSERT_EQ(triangles.size(), 6u);
    for (uint32_t t = 0; t < 6; ++t) {
        EXPECT_EQ(triangles[t].first_triangle, t);
        EXPECT_EQ(triangles[t].triangle_count, 1u);
    }
}

TEST(Scene, StaticFramesAreThePositions) {
    const Scene scene = handMadeScene();
    EXPECT_FALSE(scene.isDynamic());
    TrianglePositions out;
    out.resize(1); // stale content must be replaced, not kept
    scene.frame(12.0, out);
    EXPECT_EQ(out.x, scene.positions.x);
    EXPECT_EQ(out.y, scene.positions.y);
    EXPECT_EQ(out.z, scene.positions.z);
}

TEST(Scene, AnimationDrivesFrames) {
    // An animation that moves every corner to x = t.
    struct Flatten final : Animation {
        void positionsAt(double t, TrianglePositions& out) const override {
            out.resize(6);
            std::fill(out.x.begin(), out.x.end(), static_cast<float>(t));
        }
    };
    Scene scene = handMadeScene();
    scene.animation = std::make_shared<Flatten>();
    EXPECT_TRUE(scene.isDynamic());
    const TrianglePositions at = scene.frame(2.5);
    ASSERT_EQ(at.x.size(), 18u);
    EXPECT_EQ(at.x[17], 2.5f);
}

// --- validateScene ---

TEST(ValidateScene, AcceptsAValidScene) {
    EXPECT_EQ(validateScene(handMadeScene()).error, "");
}

TEST(ValidateScene, RejectsBrokenInvariants) {
    const auto broken = [](auto change) {
        Scene scene = handMadeScene();
        change(scene);
        return validateScene(scene).error;
    };
    EXPECT_NE(broken([](Scene& s) {
                  s.positions = {};
                  s.objects.clear();
              }),
              "");
    EXPECT_NE(broken([](Scene& s) { s.objects.clear(); }), "");
    EXPECT_NE(broken([](Scene& s) { s.positions.y.pop_back(); }), "");
    EXPECT_NE(broken([](Scene& s) {
                  s.positions.x.pop_back();
                  s.positions.y.pop_back();
                  s.positions.z.pop_back();
              }),
              "");
    EXPECT_NE(broken([](Scene& s) {
                  s.positions.z[7] = std::numeric_limits<float>::quiet_NaN();
              }).find("triangle 2"),
              std::string::npos);
    EXPECT_NE(broken([](Scene& s) { s.positions.x[0] = std::numeric_limits<float>::infinity(); }),
              "");
    EXPECT_NE(broken([](Scene& s) { s.objects[1].first_triangle = 3; }), ""); // gap
    EXPECT_NE(broken([](Scene& s) { s.objects[1].triangle_count = 2; }), ""); // overlap
    EXPECT_NE(broken([](Scene& s) { s.objects[2].triangle_count = 2; }), ""); // short
    EXPECT_NE(broken([](Scene& s) {
                  s.objects.push_back({"d", Rgba{}, false, 6, 0});
              }),
              ""); // empty object
    EXPECT_NE(
        broken([](Scene& s) { s.objects[0].colour.g = std::numeric_limits<float>::quiet_NaN(); }),
        "");
    EXPECT_NE(broken([](Scene& s) {
                  s.camera = CameraSpec{};
                  s.camera->target = s.camera->eye;
              }).find("camera"),
              std::string::npos);
    EXPECT_EQ(broken([](Scene& s) { s.camera = CameraSpec{}; }), "");
}

TEST(ValidateScene, PartsMustTileTheirObject) {
    const auto with_parts = [](std::vector<ObjectPart> parts) {
        Scene scene = handMadeScene();
        scene.objects[2].parts = std::move(parts); // object c: triangles 3, 4, 5
        return validateScene(scene).error;
    };
    EXPECT_EQ(with_parts({{"p", Rgba{}, 3, 1}, {"q", Rgba{}, 4, 2}}), "");
    EXPECT_NE(with_parts({{"p", Rgba{}, 3, 1}, {"q", Rgba{}, 5, 1}}).find("'q' does not follow"),
              std::string::npos); // a gap
    EXPECT_NE(with_parts({{"p", Rgba{}, 3, 2}}).find("parts do not cover"), std::string::npos);
    EXPECT_NE(with_parts({{"p", Rgba{}, 3, 1}, {"q", Rgba{}, 4, 3}}).find("parts do not cover"),
              std::string::npos);                                          // past the object's end
    EXPECT_NE(with_parts({{"p", Rgba{}, 3, 0}, {"q", Rgba{}, 3, 3}}), ""); // an empty part
    Rgba nan;
    nan.r = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(with_parts({{"p", nan, 3, 3}}).find("non-finite colour"), std::string::npos);
}

TEST(LoadScene, ObjectGroupingAppliesToMeshFilesOnly) {
    const std::string crabs = kSource + "/tests/data/meshes/crabs.obj";
    const Result<Scene> each = samples::loadScene(crabs);
    const Result<Scene> whole = samples::loadScene(crabs, ObjectGrouping::file);
    ASSERT_TRUE(each) << each.error;
    ASSERT_TRUE(whole) << whole.error;
    EXPECT_EQ(each.value->objects.size(), 4u);
    EXPECT_EQ(whole.value->objects.size(), 1u);
    expectFailure(
        samples::loadScene(kSource + "/tests/data/scenes/three_sticks.json", ObjectGrouping::mesh),
        "a JSON scene says it per entry");
    expectFailure(samples::loadScene("builtin:bunnies", ObjectGrouping::file),
                  "a built-in scene makes its own objects");
}

// --- loadScene ---

TEST(LoadScene, MeshFilesAndJsonScenesByPath) {
    const Result<Scene> mesh = samples::loadScene(kSource + "/assets/models/spot.obj");
    ASSERT_TRUE(mesh) << mesh.error;
    EXPECT_EQ(mesh.value->triangleCount(), 5856u);
    const Result<Scene> json = samples::loadScene(kSource + "/tests/data/scenes/three_sticks.json");
    ASSERT_TRUE(json) << json.error;
    EXPECT_EQ(json.value->objects.size(), 3u);
    EXPECT_EQ(json.value->triangleCount(), 36u);
}

TEST(LoadScene, JsonExtensionIsCaseInsensitive) {
    const fs::path file =
        fs::temp_directory_path() / ("vissort_load_" + std::to_string(::getpid()) + ".JSON");
    std::ofstream(file)
        << R"({"objects": [{"shape": "box"}, {"shape": "box", "translate": [2, 0, 0]}]})";
    const Result<Scene> loaded = samples::loadScene(file.string());
    fs::remove(file);
    ASSERT_TRUE(loaded) << loaded.error;
    EXPECT_EQ(loaded.value->objects.size(), 2u);
}

TEST(LoadScene, MissingFilesNameThePath) {
    expectFailure(loadScene("/nonexistent/vissort/scene.json"), "/nonexistent/vissort/scene.json");
    expectFailure(loadScene("/nonexistent/vissort/mesh.obj"), "/nonexistent/vissort/mesh.obj");
}

TEST(LoadScene, MalformedSpecifications) {
    expectFailure(loadScene(""), "empty scene specification");
    expectFailure(loadScene("builtin:"), "missing the built-in scene name");
    expectFailure(loadScene("builtin:?layers=3"), "missing the built-in scene name");
    expectFailure(loadScene("builtin:slabs?layers"), "'layers' needs a value");
    expectFailure(loadScene("builtin:slabs?layers=2&seed=1&layers=3"), "'layers' given twice");
    expectFailure(loadScene("builtin:slabs?=3"), "has no key");
    expectFailure(loadScene("builtin:slabs?layers=3&"), "empty parameter");
    expectFailure(loadScene("builtin:slabs?layers=3&&seed=1"), "empty parameter");
}

TEST(LoadScene, ControlCharactersInMessagesAreEscapedToKeepOneLine) {
    // Found by the scene_parameters fuzzer: the specification is quoted in the message as is.
    expectFailure(samples::loadScene("builtin:soup?&\n\n"),
                  "builtin:soup?&\\x0a\\x0a: empty parameter");
    expectFailure(samples::loadScene("builtin:soup?n\r=1"), "unknown parameter 'n\\x0d'");
    expectFailure(samples::loadScene("builtin:soup?n=1\t"), "'1\\x09' is not an integer");
    expectFailure(loadScene("/nonexistent/a\nb.obj"), "/nonexistent/a\\x0ab.obj: file not found");
}

TEST(LoadScene, BuiltinWithoutAMakerSaysWhereTheScenesAre) {
    expectFailure(loadScene("builtin:slabs"), "no built-in scenes here");
    expectFailure(loadScene("builtin:slabs?layers=3"),
                  "the Python module have the samples' scenes");
}

TEST(LoadScene, BuiltinMakerGetsTheNameAndParametersAndItsSceneIsChecked) {
    std::string asked_name;
    SceneParameters asked_parameters;
    const BuiltinSceneMaker maker = [&](const std::string& name, const SceneParameters& p) {
        asked_name = name;
        asked_parameters = p;
        if (name == "broken") {
            Scene scene = handMadeScene();
            scene.positions.x[4] = std::numeric_limits<float>::quiet_NaN();
            return Result<Scene>{std::move(scene), {}};
        }
        if (name != "hand")
            return Result<Scene>::failure("no scene '" + name + "'");
        return Result<Scene>{handMadeScene(), {}};
    };
    const Result<Scene> made = loadScene("builtin:hand?size=3&seed=7", maker);
    ASSERT_TRUE(made) << made.error;
    EXPECT_EQ(made.value->triangleCount(), 6u);
    EXPECT_EQ(asked_name, "hand");
    EXPECT_EQ(asked_parameters, (SceneParameters{{"seed", "7"}, {"size", "3"}}));
    expectFailure(loadScene("builtin:other", maker), "no scene 'other'");
    // What the maker makes is checked as a file's scene is.
    expectFailure(loadScene("builtin:broken", maker), "builtin:broken: ");
    expectFailure(loadScene("builtin:broken", maker), "finite");
    // The syntax is the library's: the maker is not asked for a malformed specification.
    asked_name.clear();
    expectFailure(loadScene("builtin:hand?size", maker), "'size' needs a value");
    EXPECT_EQ(asked_name, "");
}

TEST(LoadMeshFromMemory, ReadsBytesAsTheFileAndRejectsGarbage) {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n";
    const Result<Scene> loaded = loadMeshFromMemory(obj.data(), obj.size(), "obj", "two.obj");
    ASSERT_TRUE(loaded) << loaded.error;
    EXPECT_EQ(loaded.value->triangleCount(), 2u);
    const std::string garbage = "this is not a mesh\n";
    expectFailure(loadMeshFromMemory(garbage.data(), garbage.size(), "ply", "garbage.ply"),
                  "garbage.ply");
    const std::string nan_corner = "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n";
    expectFailure(loadMeshFromMemory(nan_corner.data(), nan_corner.size(), "obj", "nan.obj"),
                  "nan.obj");
}

TEST(LoadScene, BuiltinScenesGetTheirParameters) {
    const Result<Scene> plain = samples::loadScene("builtin:slabs");
    ASSERT_TRUE(plain) << plain.error;
    EXPECT_EQ(validateScene(*plain.value).error, "");
    const Result<Scene> empty_query = samples::loadScene("builtin:slabs?");
    ASSERT_TRUE(empty_query) << empty_query.error;
    EXPECT_EQ(empty_query.value->positions.x, plain.value->positions.x);

    const Result<Scene> three = samples::loadScene("builtin:slabs?layers=3&seed=2");
    const Result<Scene> five = samples::loadScene("builtin:slabs?seed=2&layers=5");
    ASSERT_TRUE(three) << three.error;
    ASSERT_TRUE(five) << five.error;
    EXPECT_LT(three.value->triangleCount(), five.value->triangleCount());
    const Result<Scene> again = samples::loadScene("builtin:slabs?seed=2&layers=3");
    ASSERT_TRUE(again) << again.error;
    EXPECT_EQ(again.value->positions.x, three.value->positions.x); // key order does not matter
}

TEST(LoadScene, BuiltinErrorsNameTheSpecification) {
    expectFailure(samples::loadScene("builtin:no_such_scene"), "builtin:no_such_scene");
    expectFailure(samples::loadScene("builtin:slabs?bogus_key=1"), "bogus_key");
    expectFailure(samples::loadScene("builtin:slabs?layers=-4"), "layers");
}

} // namespace
} // namespace vissort
