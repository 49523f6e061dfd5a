#pragma once
// Axis-aligned boxes of triangles and objects in float: the coordinates' own minima and maxima,
// so a box contains its triangle exactly and closed boxes that do not overlap prove that their
// contents do not touch. The pretest every method shares. Internal.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "vissort/geometry.h"

namespace vissort::detail {

struct Box3f {
    float min[3] = {0, 0, 0}, max[3] = {0, 0, 0};
};

/// A box that overlaps nothing (an object without triangles).
inline constexpr Box3f kEmptyBox = {{INFINITY, INFINITY, INFINITY},
                                    {-INFINITY, -INFINITY, -INFINITY}};

/// Closed boxes: touching counts as overlapping.
inline bool boxesOverlap(const Box3f& a, const Box3f& b) {
#if defined(__SSE2__)
    // Six comparisons in two vector instructions and one branch: in the trees' descents the
    // outcome is a coin toss, and a branch per comparison is mispredicted often. Each box is
    // read as two overlapping 4-float loads inside its 24 bytes: (min x, min y, min z, max x)
    // and (min z, max x, max y, max z), the latter shifted to put the maxima in lanes 0-2.
    const __m128 a_min = _mm_loadu_ps(a.min), b_min = _mm_loadu_ps(b.min);
    const __m128 a_tail = _mm_loadu_ps(a.min + 2), b_tail = _mm_loadu_ps(b.min + 2);
    const __m128 a_max = _mm_shuffle_ps(a_tail, a_tail, _MM_SHUFFLE(3, 3, 2, 1));
    const __m128 b_max = _mm_shuffle_ps(b_tail, b_tail, _MM_SHUFFLE(3, 3, 2, 1));
    const __m128 meet = _mm_and_ps(_mm_cmple_ps(a_min, b_max), _mm_cmple_ps(b_min, a_max));
    return (_mm_movemask_ps(meet) & 7) == 7;
#else
    return a.min[0] <= b.max[0] && b.min[0] <= a.max[0] && a.min[1] <= b.max[1] &&
           b.min[1] <= a.max[1] && a.min[2] <= b.max[2] && b.min[2] <= a.max[2];
#endif
}

/// Grows a to contain b.
inline void includeBox(Box3f& a, const Box3f& b) {
    for (int k = 0; k < 3; ++k) {
        a.min[k] = std::min(a.min[k], b.min[k]);
        a.max[k] = std::max(a.max[k], b.max[k]);
    }
}

/// A triangle's extents along the four cube diagonals (1, 1, 1), (1, 1, -1), (1, -1, 1) and
/// (-1, 1, 1), unnormalized (x + y + z, ...), widened outwards past any float rounding: with the
/// box, the triangle's 14-sided discrete-orientation polytope (k-DOP, Klosowski et al., IEEE
/// TVCG 1998). Two triangles whose extents miss each other along any of the seven directions
/// cannot touch.
struct DiagonalExtents {
    float min[4], max[4];
};

inline bool diagonalsOverlap(const DiagonalExtents& a, const DiagonalExtents& b) {
#if defined(__SSE2__)
    const __m128 meet = _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(a.min), _mm_loadu_ps(b.max)),
                                   _mm_cmple_ps(_mm_loadu_ps(b.min), _mm_loadu_ps(a.max)));
    return _mm_movemask_ps(meet) == 15;
#else
    bool overlap = true;
    for (int k = 0; k < 4; ++k)
        overlap &= a.min[k] <= b.max[k] && b.min[k] <= a.max[k];
    return overlap;
#endif
}

/// The diagonal extents of triangle t of positions.
DiagonalExtents diagonalExtents(PositionsView positions, uint32_t t);

/// boxes[t] = the box of triangle t, for every triangle of positions (boxes is resized).
void computeTriangleBoxes(PositionsView positions, std::vector<Box3f>& boxes);
/// out[i] = the box of triangle range.first_triangle + i, for every triangle of range (out holds
/// range.triangle_count boxes): the loop every refit and scan shares.
void computeTriangleBoxes(PositionsView positions, PrimitiveRange range, std::span<Box3f> out);

/// The box of the triangles of range (triangle_count >= 1), from their corners: the same box as
/// the union of their triangle boxes, in one streaming pass.
Box3f boxOfCorners(PositionsView positions, PrimitiveRange range);

/// The box of the triangles of range (triangle_count >= 1), from their boxes.
Box3f boxOfRange(std::span<const Box3f> triangle_boxes, PrimitiveRange range);

/// Appends to out the triangles of object whose boxes overlap box (the only ones that can touch
/// what it holds), ascending.
void appendTrianglesMeetingBox(std::span<const Box3f> triangle_boxes, PrimitiveRange object,
                               const Box3f& box, std::vector<uint32_t>& out);

/// Every pair (a, b), a < b, of objects whose boxes overlap, ascending, into pairs (cleared).
/// Sweep and prune along x: O(n log n + pairs) per call. order is scratch (no allocation once
/// it has grown).
void overlappingBoxPairs(std::span<const Box3f> object_boxes,
                         std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                         std::vector<uint32_t>& order);

} // namespace vissort::detail
