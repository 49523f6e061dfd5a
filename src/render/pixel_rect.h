#pragma once
// A rectangle of pixels: where a per-pixel step runs.

#include <cstdint>

namespace vissort::detail {

/// x from the left, y from the top row.
struct PixelRect {
    uint32_t x = 0, y = 0, width = 0, height = 0;

    bool empty() const { return width == 0 || height == 0; }
    uint64_t area() const { return uint64_t(width) * height; }
};

} // namespace vissort::detail
