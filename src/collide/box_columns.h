#pragma once
// Boxes as columns (a structure of arrays: all minimum x, then all minimum y, ...), so that one
// box is tested against four at once: six vector comparisons and one mask instead of four
// separate tests with a load and a branch each. The triangle stages' inner loops, where one
// triangle's box meets a short run of the other object's. Internal.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "collide/triangle_boxes.h"

namespace vissort::detail {

class BoxColumns {
public:
    /// Lanes a mask covers, and the empty boxes kept after the last box so that a mask may be
    /// taken from any box index up to size() - 1 (the lanes past the end never overlap).
    static constexpr std::size_t kLanes = 4, kPadding = 2 * kLanes;

    /// Makes room for size boxes (their values are unset) and makes the padding after them.
    void resize(std::size_t size) {
        size_ = size;
        pad();
    }
    /// Empties the columns, keeping their memory; push then appends, and pad ends.
    void clear() { size_ = 0; }
    void push(const Box3f& box) {
        reserve(size_ + 1);
        set(size_++, box);
    }
    /// Makes the padding after the last box: once after the pushes, before any mask.
    void pad() {
        reserve(size_);
        for (int k = 0; k < 3; ++k)
            for (std::size_t i = size_; i < size_ + kPadding; ++i) {
                min_[k][i] = INFINITY;
                max_[k][i] = -INFINITY;
            }
    }
    void set(std::size_t i, const Box3f& box) {
        for (int k = 0; k < 3; ++k) {
            min_[k][i] = box.min[k];
            max_[k][i] = box.max[k];
        }
    }
    Box3f box(std::size_t i) const {
        Box3f b;
        for (int k = 0; k < 3; ++k) {
            b.min[k] = min_[k][i];
            b.max[k] = max_[k][i];
        }
        return b;
    }
    std::size_t size() const { return size_; }
    float* min(int axis) { return min_[axis].data(); }
    float* max(int axis) { return max_[axis].data(); }
    const float* min(int axis) const { return min_[axis].data(); }
    const float* max(int axis) const { return max_[axis].data(); }

private:
    void reserve(std::size_t size) {
        if (min_[0].size() < size + kPadding)
            for (int k = 0; k < 3; ++k) {
                min_[k].resize(2 * size + kPadding);
                max_[k].resize(2 * size + kPadding);
            }
    }
    std::size_t size_ = 0;
    std::vector<float> min_[3], max_[3];
};

/// One box, ready to be tested against four of a BoxColumns at a time.
struct BoxLanes {
#if defined(__SSE2__)
    __m128 min[3], max[3];
    explicit BoxLanes(const Box3f& b) {
        for (int k = 0; k < 3; ++k) {
            min[k] = _mm_set1_ps(b.min[k]);
            max[k] = _mm_set1_ps(b.max[k]);
        }
    }
#else
    Box3f box;
    explicit BoxLanes(const Box3f& b) : box(b) {}
#endif
};

/// Bit i (i < 4) set when box overlaps (closed, as boxesOverlap) box first + i of columns;
/// first + 3 < columns.size() + BoxColumns::kPadding.
inline unsigned overlapMask4(const BoxLanes& box, const BoxColumns& columns, std::size_t first) {
#if defined(__SSE2__)
    __m128 meet = _mm_and_ps(_mm_cmple_ps(box.min[0], _mm_loadu_ps(columns.max(0) + first)),
                             _mm_cmple_ps(_mm_loadu_ps(columns.min(0) + first), box.max[0]));
    for (int k = 1; k < 3; ++k)
        meet = _mm_and_ps(
            meet, _mm_and_ps(_mm_cmple_ps(box.min[k], _mm_loadu_ps(columns.max(k) + first)),
                             _mm_cmple_ps(_mm_loadu_ps(columns.min(k) + first), box.max[k])));
    return unsigned(_mm_movemask_ps(meet));
#else
    unsigned mask = 0;
    for (std::size_t i = 0; i < BoxColumns::kLanes; ++i) {
        bool meet = true;
        for (int k = 0; k < 3; ++k)
            meet &= box.box.min[k] <= columns.max(k)[first + i] &&
                    columns.min(k)[first + i] <= box.box.max[k];
        mask |= unsigned(meet) << i;
    }
    return mask;
#endif
}

/// Bit i (i < 8) set when box overlaps box first + i of columns, for the i < count (<= 8).
inline unsigned overlapMask8(const BoxLanes& box, const BoxColumns& columns, std::size_t first,
                             std::size_t count) {
    unsigned mask = overlapMask4(box, columns, first);
    if (count > BoxColumns::kLanes)
        mask |= overlapMask4(box, columns, first + BoxColumns::kLanes) << BoxColumns::kLanes;
    return mask & ((1u << count) - 1);
}

} // namespace vissort::detail
