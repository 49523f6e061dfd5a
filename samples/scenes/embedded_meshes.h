#pragma once
// Meshes compiled into the library (generated from assets/models/ by CMake).

#include <cstddef>

namespace vissort::detail {

/// assets/models/bunny-lowres.obj, the text of the OBJ file (3,674 triangles).
extern const char kBunnyLowresObj[];
extern const std::size_t kBunnyLowresObjSize;

} // namespace vissort::detail
