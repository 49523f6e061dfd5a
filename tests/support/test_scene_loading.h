#pragma once
// Loads a scene for a test: "builtin:..." as is, anything else relative to the repository (the
// tests run from the build tree). A failure to load fails the test and gives an empty scene.

#include <string>

#include <gtest/gtest.h>

#include "scenes/scene_library.h"
#include "vissort/scene.h"

namespace vissort::test {

inline Scene loadTestScene(const std::string& spec) {
    const std::string path =
        spec.rfind("builtin:", 0) == 0 ? spec : std::string(VISSORT_SOURCE_DIR) + "/" + spec;
    Result<Scene> loaded = samples::loadScene(path);
    EXPECT_TRUE(loaded) << loaded.error;
    return loaded ? std::move(*loaded.value) : Scene{};
}

} // namespace vissort::test
