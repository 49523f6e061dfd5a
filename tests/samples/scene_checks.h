#pragma once
// Checks every built-in scene generator's tests make: its parameter errors, and that one seed
// gives the same scene bit for bit.

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

} // namespace vissort::test
