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
    std::vector<uint32_t>& hits = scratch.hits;
    hits.resize(columns_b.size() + BoxColumns::kLanes);
    for (uint32_t ta : scratch.near_a) {
        const BoxLanes box(triangle_boxes[ta]);
        // The near triangles of b whose boxes meet ta's, listed without a branch per mask (an
        // empty mask is a coin toss the predictor loses); the padding's empty boxes meet nothing.
        std::size_t count = 0;
        for (std::size_t first = 0; first < columns_b.size(); first += BoxColumns::kLanes) {
            const unsigned mask = overlapMask4(box, columns_b, first);
            for (uint32_t lane = 0; lane < BoxColumns::kLanes; ++lane) {
                hits[count] = uint32_t(first) + lane;
                count += (mask >> lane) & 1;
            }
        }
        if (count == 0)
            continue;
        box_pairs += count;
        // Likewise the pairs whose diagonals meet too (about half of them).
        const DiagonalExtents diagonals = diagonalExtents(positions, ta);
        std::size_t kept = pairs.size();
        pairs.resize(kept + count);
        for (std::size_t h = 0; h < count; ++h) {
            pairs[kept] = {ta, scratch.near_b[hits[h]]};
            kept += diagonalsOverlap(diagonals, scratch.diagonals_b[hits[h]]);
        }
        pairs.resize(kept);
    }
    return box_pairs;
}

} // namespace vissort::detail
