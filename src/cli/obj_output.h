#pragma once
// Writing primitives as OBJ for checks by any outside tool (order's and collide's
// --dump-primitives).

#include <span>
#include <string>

#include "vissort/geometry.h"

namespace vissort::cli {

/// Writes one `o prim_<index>` group per primitive, in index order, each with its triangles in
/// id order (so with primitives tiling the triangles in order, face i of the file is triangle
/// i), after a `# comment` line. False when the file cannot be written.
bool writePrimitivesObj(const std::string& path, const std::string& comment,
                        PositionsView positions, std::span<const PrimitiveRange> primitives);

} // namespace vissort::cli
