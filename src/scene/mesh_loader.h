#pragma once
// Reads triangle meshes with assimp. Internal: no assimp type leaves src/scene/.

#include <cstddef>
#include <string>

#include "vissort/scene.h"

namespace vissort::detail {

/// Reads the meshes of a file as objects, grouped as `grouping` says (ObjectGrouping, scene.h);
/// under mesh grouping one object per mesh, in file order (an OBJ `o`/`g` group of one material
/// is one mesh). Polygons are fan-triangulated in place; no vertex welding or reordering that would
/// change triangle ids. Objects get the material's diffuse colour and opacity when the file has
/// one (transparent when opacity < 1), else a default grey, opaque.
Result<Scene> loadMeshFile(const std::string& path, ObjectGrouping grouping = ObjectGrouping::mesh);

/// The same from bytes in memory; `format_hint` is a file extension such as "obj".
/// `label` names the source in error messages.
Result<Scene> loadMeshMemory(const void* data, std::size_t size, const std::string& format_hint,
                             const std::string& label,
                             ObjectGrouping grouping = ObjectGrouping::mesh);

} // namespace vissort::detail
