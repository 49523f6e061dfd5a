#pragma once
// The cameras a mesh file stores (Collada, glTF, FBX, 3DS, ...), as vissort's cameras. Internal:
// no assimp type leaves src/scene/.

#include <string>
#include <vector>

#include "vissort/scene.h"

struct aiScene;

namespace vissort::detail {

/// Every camera of the file, in file order, placed by its node's world transform (the same
/// transform that places the meshes). `extension` (lower case, no dot) says how assimp stored
/// the field of view: glTF's importer writes yfov * aspect, the others the full horizontal angle.
/// Cameras that cannot be used keep a one-line `problem`. A perspective camera's target is on
/// its view line, as far from the eye as the centre of `bounds` (the scene's): what an orbit
/// turns around.
std::vector<StoredCamera> fileCameras(const aiScene& scene, const std::string& extension,
                                      const Bounds& bounds);

} // namespace vissort::detail
