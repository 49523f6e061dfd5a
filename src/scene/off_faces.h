#pragma once
// An OFF file's face list, read past assimp. Internal to src/scene/.
//
// Why: assimp's OFF reader (5.2) silently drops every polygon of 10 or more corners (a pipe's
// 12-sided cap vanished) and clamps a corner index beyond the vertices to a valid one (a face
// that points nowhere becomes a triangle somewhere): a wrong scene with no error. The loader
// counts the triangles the faces make here and refuses the file when assimp's count differs.

#include <cstdint>
#include <istream>

#include "vissort/result.h"

namespace vissort::detail {

struct OffFaces {
    uint64_t fan_triangles = 0; // n - 2 for every face of n >= 3 corners
    uint64_t most_corners = 0;  // the largest polygon
};

/// Reads the header and face list of an OFF file (any of assimp's [ST][C][N][4][n]OFF keywords,
/// or none); a one-line problem, without the file's name, when a face refers to a vertex the
/// file does not have, lists fewer corners than it declares, or the file ends before its faces.
/// Vertex and face lines may carry colours and comments ('#'), which are skipped.
Result<OffFaces> readOffFaces(std::istream& in);

} // namespace vissort::detail
