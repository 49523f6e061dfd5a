#include "figures/comparison_strip.h"

#include <algorithm>
#include <cassert>

#include <stb/stb_easy_font.h>

namespace vissort::samples {
namespace {

constexpr uint32_t kMargin = 8;       // pixels around each tile
constexpr uint32_t kTextScale = 2;    // stb_easy_font's glyphs are about 7 pixels high
constexpr uint32_t kCaptionLines = 3; // room above each tile
constexpr uint8_t kCaptionColour[3] = {30, 30, 30};

// stb_easy_font's vertex: x, y, z and a colour; four make a quad, an axis-aligned rectangle.
struct FontVertex {
    float x, y, z;
    unsigned char colour[4];
};

} // namespace

void drawText(Strip& strip, uint32_t left, uint32_t top, const std::string& text,
              const uint8_t colour[3]) {
    std::vector<char> characters(text.begin(), text.end());
    characters.push_back('\0');
    std::vector<FontVertex> vertices(characters.size() * 300); // ~270 bytes a character
    const int quads = stb_easy_font_print(0, 0, characters.data(), nullptr, vertices.data(),
                                          int(vertices.size() * sizeof(FontVertex)));
    for (int q = 0; q < quads; ++q) {
        const FontVertex* v = &vertices[std::size_t(q) * 4];
        const float x0 = std::min({v[0].x, v[1].x, v[2].x, v[3].x});
        const float x1 = std::max({v[0].x, v[1].x, v[2].x, v[3].x});
        const float y0 = std::min({v[0].y, v[1].y, v[2].y, v[3].y});
        const float y1 = std::max({v[0].y, v[1].y, v[2].y, v[3].y});
        for (uint32_t y = top + uint32_t(y0 * kTextScale); y < top + uint32_t(y1 * kTextScale); ++y)
            for (uint32_t x = left + uint32_t(x0 * kTextScale);
                 x < left + uint32_t(x1 * kTextScale); ++x) {
                if (x >= strip.width || y >= strip.height)
                    continue;
                uint8_t* p = &strip.rgba[(std::size_t(y) * strip.width + x) * 4];
                p[0] = colour[0];
                p[1] = colour[1];
                p[2] = colour[2];
                p[3] = 255;
            }
    }
}

Strip composeStrip(const std::vector<StripTile>& tiles, uint32_t tile_width, uint32_t tile_height,
                   uint32_t columns) {
    assert(columns > 0);
    const uint32_t caption_height = kCaptionLines * 12 * kTextScale;
    const uint32_t cell_width = tile_width + 2 * kMargin;
    const uint32_t cell_height = caption_height + tile_height + 2 * kMargin;
    const uint32_t rows = uint32_t((tiles.size() + columns - 1) / columns);
    Strip strip;
    strip.width = cell_width * std::min<uint32_t>(columns, uint32_t(tiles.size()));
    strip.height = cell_height * rows;
    strip.rgba.assign(std::size_t(strip.width) * strip.height * 4, 255);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        assert(tiles[i].rgba.size() == std::size_t(tile_width) * tile_height * 4);
        const uint32_t left = uint32_t(i % columns) * cell_width + kMargin;
        const uint32_t top = uint32_t(i / columns) * cell_height + kMargin;
        drawText(strip, left, top, tiles[i].caption, kCaptionColour);
        for (uint32_t y = 0; y < tile_height; ++y)
            std::copy_n(
                &tiles[i].rgba[std::size_t(y) * tile_width * 4], tile_width * 4,
                &strip.rgba[(std::size_t(top + caption_height + y) * strip.width + left) * 4]);
    }
    return strip;
}

} // namespace vissort::samples
