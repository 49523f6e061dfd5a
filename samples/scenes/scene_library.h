#pragma once
// The samples' named, generated scenes (`builtin:NAME?key=value&...`), used alike by tests,
// benchmarks, the command line and the Python module; not part of the installed library, which
// loads files (vissort::loadScene). Every scene is deterministic for a given `seed`.

#include <string>
#include <vector>

#include "vissort/scene.h"

namespace vissort::samples {

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
///   pile:    n (1000), seed (1): small rigid and deforming bodies settling into a pile.
///   slabs:   layers (8), seed (1): a stack of large, slightly tilted quads; acyclic.
///   soup:    n (1000), seed (1): random non-intersecting triangles.
///   plant:   layers (8), seed (1): CAD-like rows of pipes, tanks and steel, opaque and
///            transparent; depth complexity about 2 layers.
Result<Scene> makeBuiltinScene(const std::string& name, const SceneParameters& parameters);

/// vissort::loadScene with these scenes as its `builtin:` ones: a file, a JSON scene or
/// `builtin:NAME?key=value&...`; `mesh_file_objects` as vissort::loadScene takes it.
Result<Scene> loadScene(const std::string& specification,
                        std::optional<ObjectGrouping> mesh_file_objects = std::nullopt);

} // namespace vissort::samples
