#pragma once
// Images of one size laid out in a grid with a caption above each: the side-by-side comparison
// of `vissort render --method all`.

#include <cstdint>
#include <string>
#include <vector>

namespace vissort::samples {

struct StripTile {
    std::vector<uint8_t> rgba; // tile_width * tile_height RGBA pixels
    std::string caption;       // up to a few short lines ('\n' separated)
};

struct Strip {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

/// Draws text (stb_easy_font at twice its size, about 14 pixels a line) with its top-left
/// corner at (left, top), clipped to the strip.
void drawText(Strip& strip, uint32_t left, uint32_t top, const std::string& text,
              const uint8_t colour[3]);

/// Lays tiles out `columns` to a row, in order, each under its caption (dark text on white),
/// with a margin around every tile. Every tile must have tile_width * tile_height pixels.
Strip composeStrip(const std::vector<StripTile>& tiles, uint32_t tile_width, uint32_t tile_height,
                   uint32_t columns);

} // namespace vissort::samples
