// Boxes of triangles and objects (triangle_boxes.h), and the sweep and prune over object boxes
// (Baraff, "Dynamic simulation of non-penetrating rigid bodies", 1992: sort the intervals on one
// axis, test only those that overlap there).

#include "collide/triangle_boxes.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vissort::detail {

void computeTriangleBoxes(PositionsView positions, std::vector<Box3f>& boxes) {
    boxes.resize(positions.triangleCount());
    computeTriangleBoxes(positions, {0, uint32_t(boxes.size())}, boxes);
}

void computeTriangleBoxes(PositionsView positions, PrimitiveRange range, std::span<Box3f> out) {
    // One coordinate array at a time: three streams read forward, a loop that vectorizes.
    const std::size_t first_corner = 3 * std::size_t(range.first_triangle);
    const float* axes[3] = {positions.x.data(), positions.y.data(), positions.z.data()};
    for (int k = 0; k < 3; ++k) {
        const float* c = axes[k] + first_corner;
        for (std::size_t i = 0; i < range.triangle_count; ++i) {
            const float p = c[3 * i], q = c[3 * i + 1], r = c[3 * i + 2];
            out[i].min[k] = std::min(std::min(p, q), r);
            out[i].max[k] = std::max(std::max(p, q), r);
        }
    }
}

DiagonalExtents diagonalExtents(PositionsView positions, uint32_t t) {
    // In float: each sum of three rounds twice, by at most 2^-24 of the sum of magnitudes m
    // each time, so widening by 2^-20 m (itself rounded) leaves a wide margin.
    constexpr float kWiden = 0x1p-20f;
    const std::size_t first = 3 * std::size_t(t);
    DiagonalExtents e;
#if defined(__SSE2__)
    // The four sums of a corner at once: x (1, 1, 1, -1) + y (1, 1, -1, 1) + z (1, -1, 1, 1),
    // added in the same order as below, so the values are the same bit for bit.
    const __m128 sign_x = _mm_setr_ps(1, 1, 1, -1), sign_y = _mm_setr_ps(1, 1, -1, 1),
                 sign_z = _mm_setr_ps(1, -1, 1, 1);
    __m128 low = _mm_set1_ps(INFINITY), high = _mm_set1_ps(-INFINITY);
    float magnitude = 0;
    for (std::size_t c = first; c < first + 3; ++c) {
        const float x = positions.x[c], y = positions.y[c], z = positions.z[c];
        const __m128 sums = _mm_add_ps(
            _mm_add_ps(_mm_mul_ps(_mm_set1_ps(x), sign_x), _mm_mul_ps(_mm_set1_ps(y), sign_y)),
            _mm_mul_ps(_mm_set1_ps(z), sign_z));
        low = _mm_min_ps(low, sums);
        high = _mm_max_ps(high, sums);
        magnitude = std::max(magnitude, std::abs(x) + std::abs(y) + std::abs(z));
    }
    const __m128 widen = _mm_set1_ps(magnitude * kWiden);
    _mm_storeu_ps(e.min, _mm_sub_ps(low, widen));
    _mm_storeu_ps(e.max, _mm_add_ps(high, widen));
#else
    float magnitude = 0;
    for (int k = 0; k < 4; ++k) {
        e.min[k] = INFINITY;
        e.max[k] = -INFINITY;
    }
    for (std::size_t c = first; c < first + 3; ++c) {
        const float x = positions.x[c], y = positions.y[c], z = positions.z[c];
        const float sums[4] = {x + y + z, x + y - z, x - y + z, -x + y + z};
        for (int k = 0; k < 4; ++k) {
            e.min[k] = std::min(e.min[k], sums[k]);
            e.max[k] = std::max(e.max[k], sums[k]);
        }
        magnitude = std::max(magnitude, std::abs(x) + std::abs(y) + std::abs(z));
    }
    const float widen = magnitude * kWiden;
    for (int k = 0; k < 4; ++k) {
        e.min[k] -= widen;
        e.max[k] += widen;
    }
#endif
    return e;
}

Box3f boxOfCorners(PositionsView positions, PrimitiveRange range) {
    // Eight running minima and maxima, one per lane, so that the loop vectorizes without
    // reassociating anything (min and max are exact in any order): one streaming pass over each
    // coordinate array, several times faster than a box per triangle.
    constexpr std::size_t kLanes = 8;
    const std::size_t begin = 3 * std::size_t(range.first_triangle);
    const std::size_t end = begin + 3 * std::size_t(range.triangle_count);
    const float* axes[3] = {positions.x.data(), positions.y.data(), positions.z.data()};
    Box3f box;
    for (int k = 0; k < 3; ++k) {
        const float* c = axes[k];
        float low[kLanes], high[kLanes];
        for (std::size_t lane = 0; lane < kLanes; ++lane)
            low[lane] = high[lane] = c[begin];
        std::size_t i = begin;
        for (; i + kLanes <= end; i += kLanes)
            for (std::size_t lane = 0; lane < kLanes; ++lane) {
                low[lane] = std::min(low[lane], c[i + lane]);
                high[lane] = std::max(high[lane], c[i + lane]);
            }
        for (; i < end; ++i) {
            low[0] = std::min(low[0], c[i]);
            high[0] = std::max(high[0], c[i]);
        }
        box.min[k] = *std::min_element(low, low + kLanes);
        box.max[k] = *std::max_element(high, high + kLanes);
    }
    return box;
}

Box3f boxOfRange(std::span<const Box3f> triangle_boxes, PrimitiveRange range) {
    Box3f box = triangle_boxes[range.first_triangle];
    for (uint32_t t = 1; t < range.triangle_count; ++t)
        includeBox(box, triangle_boxes[range.first_triangle + t]);
    return box;
}

void appendTrianglesMeetingBox(std::span<const Box3f> triangle_boxes, PrimitiveRange object,
                               const Box3f& box, std::vector<uint32_t>& out) {
    for (uint32_t t = object.first_triangle; t < object.first_triangle + object.triangle_count; ++t)
        if (boxesOverlap(triangle_boxes[t], box))
            out.push_back(t);
}

void overlappingBoxPairs(std::span<const Box3f> object_boxes,
                         std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                         std::vector<uint32_t>& order) {
    pairs.clear();
    std::vector<uint32_t>& by_min_x = order;
    by_min_x.resize(object_boxes.size());
    std::iota(by_min_x.begin(), by_min_x.end(), 0u);
    std::sort(by_min_x.begin(), by_min_x.end(), [&](uint32_t a, uint32_t b) {
        return object_boxes[a].min[0] < object_boxes[b].min[0] ||
               (object_boxes[a].min[0] == object_boxes[b].min[0] && a < b);
    });
    for (std::size_t i = 0; i < by_min_x.size(); ++i) {
        const Box3f& a = object_boxes[by_min_x[i]];
        for (std::size_t j = i + 1; j < by_min_x.size(); ++j) {
            const Box3f& b = object_boxes[by_min_x[j]];
            if (b.min[0] > a.max[0])
                break; // sorted by min x: no later box reaches a
            if (boxesOverlap(a, b))
                pairs.emplace_back(std::min(by_min_x[i], by_min_x[j]),
                                   std::max(by_min_x[i], by_min_x[j]));
        }
    }
    std::sort(pairs.begin(), pairs.end());
}

} // namespace vissort::detail
