#pragma once
// The triangle stage of the vissort method for two small objects (at most kScanTriangles
// triangles each): the triangles of each that meet the two objects' common box, by a scan of
// this frame's triangle boxes, then every pair of those whose boxes meet and whose diagonal
// extents meet (triangle_boxes.h). For a few hundred triangles a scan is cheaper than refitting
// and descending two trees (docs/collision.md measures both); the candidates are the same. The
// algorithm of the brute force method's triangle stage, with the diagonals. Internal.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "collide/box_columns.h"
#include "collide/triangle_boxes.h"

namespace vissort::detail {

/// Objects of at most this many triangles take the scan when both of a pair do.
inline constexpr uint32_t kScanTriangles = 1024;

/// One thread's scratch: the triangles near the common box, and the second object's boxes and
/// extents.
struct SmallPairScratch {
    std::vector<uint32_t> near_a, near_b;
    BoxColumns columns_b;
    std::vector<DiagonalExtents> diagonals_b;
    std::vector<uint32_t> hits; // the near triangles of b whose boxes meet one of a's
};

/// Every pair (ta, tb), ta of a, tb of b, whose boxes overlap and whose diagonal extents
/// overlap, appended to pairs. triangle_boxes: indexed by triangle id, current for both objects'
/// triangles; box_a, box_b: the objects' boxes. Returns how many pairs' boxes overlapped.
uint64_t scannedTrianglePairs(PositionsView positions, std::span<const Box3f> triangle_boxes,
                              PrimitiveRange a, PrimitiveRange b, const Box3f& box_a,
                              const Box3f& box_b, std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                              SmallPairScratch& scratch);

} // namespace vissort::detail
