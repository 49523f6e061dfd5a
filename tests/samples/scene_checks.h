#pragma once
// Checks every built-in scene generator's tests make: its parameter errors, and that one seed
// gives the same scene bit for bit.

#include <cstdint>
#include <span>
#include <string>

#include "scenes/scene_library.h"
#include "vissort/scene.h"

namespace vissort::test {

/// Parameters a generator must refuse, and a part of the one-line error it must give.
struct ParameterErrorCase {
    SceneParameters parameters;
    const char* expected;
};

/// Each case refused by samples::makeBuiltinScene(scene, ...) with one line containing its text.
void expectParameterErrors(const std::string& scene, std::span<const ParameterErrorCase> cases);

/// The same positions (bit for bit), objects (names, ranges, every colour channel, transparency),
/// camera and camera path.
void expectSameScene(const Scene& a, const Scene& b);

/// builtin:NAME?n=N&seed=SEED, failing the test (and giving an empty scene) when it is refused.
Scene makeCountedScene(const std::string& name, const std::string& n, const std::string& seed);

/// The scene's animation at t.
TrianglePositions frameAt(const Scene& scene, double t);

/// Objects PREFIX0 .. PREFIX(count-1), triangles_each triangles each in order, transparent with
/// the given alpha, the first two in clearly different colours.
void expectNumberedObjects(const Scene& scene, const std::string& prefix, uint32_t count,
                           uint32_t triangles_each, float alpha);

} // namespace vissort::test
