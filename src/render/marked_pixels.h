#pragma once
// The pixels a checked blend marked (verified_blending.h), read back from its stencil: how many,
// the rectangle around them, and which tiles hold any, so that the repair draws only the
// triangles that may cover a marked pixel (on the bunnies at 1024x1024, a few hundred of 66K).

#include <cstdint>
#include <span>
#include <vector>

#include "render/pixel_rect.h"

namespace vissort::detail {

class MarkedPixels {
public:
    static constexpr uint32_t kTileSide = 8; // pixels

    MarkedPixels() = default;
    /// From one stencil byte per pixel, rows from the top, nonzero where marked.
    MarkedPixels(std::span<const uint8_t> stencil, uint32_t width, uint32_t height);

    uint64_t count() const { return count_; }
    /// The rectangle around the marked pixels; empty when there are none.
    PixelRect bounds() const { return bounds_; }
    /// The tiles holding a marked pixel: their top-left pixels as x, y pairs, in rows.
    const std::vector<uint32_t>& tileOrigins() const { return tile_origins_; }
    /// Whether a tile that rect overlaps (clipped to the image) holds a marked pixel.
    bool anyTileIn(const PixelRect& rect) const;

private:
    uint32_t tiles_x_ = 0, tiles_y_ = 0;
    // Marked tiles in rows and columns [0, y) x [0, x), at (y * (tiles_x_ + 1) + x): any
    // rectangle of tiles answers in four reads.
    std::vector<uint32_t> summed_;
    std::vector<uint32_t> tile_origins_;
    uint64_t count_ = 0;
    PixelRect bounds_;
};

} // namespace vissort::detail
