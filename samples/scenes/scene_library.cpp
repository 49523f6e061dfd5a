// The registry of built-in scenes: names, summaries and dispatch to their generators, and the
// loader that knows them.

#include "scenes/scene_library.h"

#include <vector>

#include "vissort/closest_name.h"

#include "scenes/builtin_scenes.h"

namespace vissort::samples {
namespace {

struct BuiltinScene {
    const char* name;
    const char* summary;
    Result<Scene> (*make)(const SceneParameters&);
};

constexpr BuiltinScene kBuiltinScenes[] = {
    {"bunnies",
     "n (18, 1..10000), seed (1): the paper's dynamic scene, n deforming Stanford bunnies "
     "bouncing in a cube",
     detail::makeBunniesScene},
    {"pile",
     "n (1000, 1..100000), seed (1): n small bodies (rigid ellipsoids and capsules, deforming "
     "blobs) of 256 triangles falling into a pile on a floor and settling, for collisions",
     detail::makePileScene},
    {"plant",
     "layers (8, 1..1000), seed (1): rows of pipe racks, tanks, pumps and steel on a floor, "
     "transparent pipes and tanks, opaque steel; max depth complexity about 2 layers",
     detail::makePlantScene},
    {"powerplant",
     "scale (1, 0.05..10), seed (1): a three-storey process plant after the paper's power "
     "plant, about 730K opaque and 90K transparent triangles at scale 1, bays and triangles "
     "growing with scale; its walkthrough along the aisles and up a stair is --path scene",
     detail::makePowerplantScene},
    {"slabs",
     "layers (8, 1..100000), seed (1): a stack of 4x4 quads along z, slightly tilted, "
     "non-intersecting, acyclic; depth complexity = layers",
     detail::makeSlabsScene},
    {"soup",
     "n (1000, 1..10000000), seed (1): n random triangles in a cube, one per cell of a jittered "
     "grid, never intersecting",
     detail::makeSoupScene},
};

} // namespace

std::vector<BuiltinSceneInfo> builtinScenes() {
    std::vector<BuiltinSceneInfo> infos;
    for (const BuiltinScene& scene : kBuiltinScenes)
        infos.push_back({scene.name, scene.summary});
    return infos;
}

Result<Scene> makeBuiltinScene(const std::string& name, const SceneParameters& parameters) {
    std::string known;
    std::vector<std::string> names;
    for (const BuiltinScene& scene : kBuiltinScenes) {
        if (name == scene.name) {
            // Checked as loadScene checks what a file holds, for the callers that make a scene
            // without loadScene (the Python module).
            Result<Scene> made = scene.make(parameters);
            if (made)
                if (Status valid = validateScene(*made.value); !valid)
                    return Result<Scene>::failure(made.value->name + ": " + valid.error);
            return made;
        }
        known += (known.empty() ? "" : ", ") + std::string(scene.name);
        names.emplace_back(scene.name);
    }
    return Result<Scene>::failure("unknown built-in scene 'builtin:" + name + "' (" +
                                  didYouMeanFirst(name, names, "builtin:") + "known: " + known +
                                  ")");
}

Result<Scene> loadScene(const std::string& specification,
                        std::optional<ObjectGrouping> mesh_file_objects) {
    return vissort::loadScene(specification, makeBuiltinScene, mesh_file_objects);
}

} // namespace vissort::samples
