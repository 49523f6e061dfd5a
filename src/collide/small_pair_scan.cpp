// The triangle stage for two small objects (small_pair_scan.h).

#include "collide/small_pair_scan.h"

#include <algorithm>
#include <bit>

namespace vissort::detail {

uint64_t scannedTrianglePairs(PositionsView positions, std::span<const Box3f> triangle_boxes,
                              PrimitiveRange a, PrimitiveRange b, const Box3f& box_a,
                              const Box3f& box_b, std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                              SmallPairScratch& scratch) {
    if (!boxesOverlap(box_a, box_b))
        return 0;
    // Only a triangle inside both objects' boxes can touch the other object.
    Box3f common;
    for (int k = 0; k < 3; ++k) {
        common.min[k] = std::max(box_a.min[k], box_b.min[k]);
        common.max[k] = std::min(box_a.max[k], box_b.max[k]);
    }
    scratch.near_a.clear();
    scratch.near_b.clear();
    appendTrianglesMeetingBox(triangle_boxes, a, common, scratch.near_a);
    appendTrianglesMeetingBox(triangle_boxes, b, common, scratch.near_b);
    // The second object's near boxes as columns: each of the first's is tested against four
    // at a time (box_columns.h).
    BoxColumns& columns_b = scratch.columns_b;
    columns_b.clear();
    for (uint32_t tb : scratch.near_b)
        columns_b.push(triangle_boxes[tb]);
    columns_b.pad();
    scratch.diagonals_b.resize(scratch.near_b.size());
    for (std::size_t k = 0; k < scratch.near_b.size(); ++k)
        scratch.diagonals_b[k] = diagonalExtents(positions, scratch.near_b[k]);
    uint64_t box_pairs = 0;
    for (uint32_t ta : scratch.near_a) {
        const BoxLanes box(triangle_boxes[ta]);
        bool have_diagonals = false; // computed at its first box pair: many have none
        DiagonalExtents diagonals;
        for (std::size_t first = 0; first < columns_b.size(); first += BoxColumns::kLanes) {
            // The padding's empty boxes meet nothing, so every bit is one of near_b.
            for (unsigned mask = overlapMask4(box, columns_b, first); mask != 0; mask &= mask - 1) {
                const std::size_t k = first + std::size_t(std::countr_zero(mask));
                ++box_pairs;
                if (!have_diagonals) {
                    diagonals = diagonalExtents(positions, ta);
                    have_diagonals = true;
                }
                if (diagonalsOverlap(diagonals, scratch.diagonals_b[k]))
                    pairs.emplace_back(ta, scratch.near_b[k]);
            }
        }
    }
    return box_pairs;
}

} // namespace vissort::detail
