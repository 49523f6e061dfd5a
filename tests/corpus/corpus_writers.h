#pragma once
// Writing corpus models (corpus_models.h) as files: through assimp's own exporters (aiScene built
// in code, node hierarchy and instancing kept where the format has them), and by hand for text
// formats assimp reads but does not write (or writes only one way). Each writer returns an empty
// string on success, else a one-line reason.

#include <filesystem>
#include <string>

#include "corpus_models.h"

namespace vissort::test {

/// assimp's exporter `format_id` (Assimp::Exporter ids: "collada", "obj", "stlb", "3ds", "gltf2",
/// "glb2", "x", "fbx", "3mf", "assbin", ...). triangulate: fan polygons first (formats that hold
/// triangles only).
std::string exportWithAssimp(const CorpusModel& model, const std::string& format_id,
                             const std::filesystem::path& path, bool triangulate);

/// Wavefront OBJ with an `o` group per mesh instance, `usemtl` and a .mtl beside it (Kd, d).
std::string writeObjWithMaterials(const CorpusModel& model, const std::filesystem::path& path);
/// OFF: one object of every instance's polygons.
std::string writeOff(const CorpusModel& model, const std::filesystem::path& path);
/// ASCII PLY: one object, polygons as lists, a colour per vertex.
std::string writeAsciiPly(const CorpusModel& model, const std::filesystem::path& path);
/// AC3D: a world object with a child per instance, materials with transparency.
std::string writeAc3d(const CorpusModel& model, const std::filesystem::path& path);
/// ASCII STL: one `solid` per instance (assimp reads each as an object), triangles fanned.
std::string writeAsciiStlSolids(const CorpusModel& model, const std::filesystem::path& path);

} // namespace vissort::test
