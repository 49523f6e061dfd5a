#include "scenes/scene_library.h"

#include <set>

#include <gtest/gtest.h>

namespace vissort {
namespace {

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

TEST(SceneLibrary, ListsTheScenesWithTheirParameters) {
    const std::vector<samples::BuiltinSceneInfo> scenes = samples::builtinScenes();
    std::set<std::string> names;
    for (const samples::BuiltinSceneInfo& info : scenes)
        names.insert(info.name);
    EXPECT_EQ(names,
              (std::set<std::string>{"bunnies", "pile", "plant", "powerplant", "slabs", "soup"}));
    for (const samples::BuiltinSceneInfo& info : scenes) {
        EXPECT_TRUE(contains(info.summary, "seed (1)"));
        EXPECT_EQ(info.summary.find('\n'), std::string::npos);
    }
}

TEST(SceneLibrary, EveryListedSceneBuildsWithDefaultsAndIsValid) {
    for (const samples::BuiltinSceneInfo& info : samples::builtinScenes()) {
        const Result<Scene> scene = samples::makeBuiltinScene(info.name, {});
        ASSERT_TRUE(scene) << info.name << ": " << scene.error;
        EXPECT_EQ(scene.value->name, "builtin:" + info.name);
        EXPECT_EQ(validateScene(*scene.value).error, "") << info.name;
        ASSERT_TRUE(scene.value->camera.has_value()) << info.name;
        EXPECT_EQ(validateCamera(*scene.value->camera).error, "") << info.name;
        // Transparent objects blend (alpha < 1); opaque ones (the plant's steel) do not.
        bool any_transparent = false;
        for (const SceneObject& object : scene.value->objects) {
            EXPECT_EQ(object.transparent, object.colour.a < 1.0f)
                << info.name << " " << object.name;
            any_transparent |= object.transparent;
        }
        EXPECT_TRUE(any_transparent) << info.name;
    }
}

TEST(SceneLibrary, UnknownNamesAreErrorsListingTheKnownOnes) {
    const Result<Scene> scene = samples::makeBuiltinScene("teapot", {});
    EXPECT_FALSE(scene);
    EXPECT_TRUE(contains(scene.error, "'builtin:teapot'"));
    EXPECT_TRUE(contains(scene.error, "bunnies, pile, plant, powerplant, slabs, soup"));
}

TEST(SceneLibrary, ParameterErrorsNameTheSceneAndTheKey) {
    const struct {
        const char* scene;
        SceneParameters parameters;
        const char* expected;
    } cases[] = {
        {"bunnies", {{"n", "0"}}, "builtin:bunnies: parameter n=0 is out of range"},
        {"bunnies", {{"n", "10001"}}, "parameter n=10001 is out of range"},
        {"bunnies", {{"n", "many"}}, "parameter n='many' is not an integer"},
        {"bunnies", {{"seed", "-2"}}, "parameter seed='-2' is not a non-negative integer"},
        {"bunnies", {{"layers", "3"}}, "unknown parameter 'layers' (accepted: n, seed)"},
        {"slabs", {{"layers", "0"}}, "builtin:slabs: parameter layers=0 is out of range"},
        {"slabs", {{"layers", "100001"}}, "parameter layers=100001 is out of range"},
        {"slabs", {{"n", "3"}}, "unknown parameter 'n' (accepted: layers, seed)"},
        {"soup", {{"n", "-5"}}, "builtin:soup: parameter n=-5 is out of range"},
        {"soup", {{"n", "10000001"}}, "parameter n=10000001 is out of range"},
        {"soup", {{"n", "1e6"}}, "parameter n='1e6' is not an integer"},
    };
    for (const auto& c : cases) {
        const Result<Scene> scene = samples::makeBuiltinScene(c.scene, c.parameters);
        EXPECT_FALSE(scene) << c.expected;
        EXPECT_TRUE(contains(scene.error, c.expected));
    }
}

TEST(SceneLibrary, BunniesAboveTheTriangleLimitAreRefused) {
    // 2722 bunnies of 3674 triangles are 10,000,628 triangles: over the 10 million limit.
    const Result<Scene> scene = samples::makeBuiltinScene("bunnies", {{"n", "2722"}});
    EXPECT_FALSE(scene);
    EXPECT_TRUE(
        contains(scene.error, "builtin:bunnies: parameter n=2722 gives 10000628 triangles"));
}

} // namespace
} // namespace vissort
