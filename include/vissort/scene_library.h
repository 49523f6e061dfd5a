#pragma once
// Named, generated scenes used alike by tests, benchmarks and the command line.
// Every scene is deterministic for a given `seed`.

#include <map>
#include <string>
#include <vector>

#include "vissort/scene.h"

namespace vissort {

/// key=value parameters of a `builtin:NAME?key=value&...` specification.
using SceneParameters = std::map<std::string, std::string>;

struct BuiltinSceneInfo {
    std::string name;
    std::string summary; // one line, with the parameters and their defaults
};

/// The names and one-line descriptions of every built-in scene.
std::vector<BuiltinSceneInfo> builtinScenes();

/// Makes a built-in scene, checked as loadScene checks every scene (validateScene). Unknown
/// names, unknown keys, malformed or absurd values (negative counts, more than 10 million
/// triangles) give an error naming the problem.
///   bunnies: n (18), seed (1): the paper's dynamic scene of deforming, bouncing bunnies.
///   slabs:   layers (8), seed (1): a stack of large, slightly tilted quads; acyclic.
///   soup:    n (1000), seed (1): random non-intersecting triangles.
///   plant:   layers (8), seed (1): CAD-like rows of pipes, tanks and steel, opaque and
///            transparent; depth complexity about 2 layers.
Result<Scene> makeBuiltinScene(const std::string& name, const SceneParameters& parameters);

} // namespace vissort
