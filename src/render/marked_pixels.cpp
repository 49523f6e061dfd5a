#include "render/marked_pixels.h"

#include <algorithm>

namespace vissort::detail {

MarkedPixels::MarkedPixels(std::span<const uint8_t> stencil, uint32_t width, uint32_t height)
    : tiles_x_((width + kTileSide - 1) / kTileSide), tiles_y_((height + kTileSide - 1) / kTileSide),
      summed_(std::size_t(tiles_x_ + 1) * (tiles_y_ + 1), 0) {
    std::vector<uint8_t> tile_marked(std::size_t(tiles_x_) * tiles_y_, 0);
    uint32_t x0 = width, y0 = height, x1 = 0, y1 = 0;
    for (uint32_t y = 0; y < height; ++y) {
        const uint8_t* row = stencil.data() + std::size_t(y) * width;
        // Most rows hold no mark: find the first, then walk the rest.
        const uint8_t* first = std::find_if(row, row + width, [](uint8_t s) { return s != 0; });
        for (uint32_t x = uint32_t(first - row); x < width; ++x) {
            if (row[x] == 0)
                continue;
            ++count_;
            tile_marked[std::size_t(y / kTileSide) * tiles_x_ + x / kTileSide] = 1;
            x0 = std::min(x0, x);
            x1 = std::max(x1, x);
            y0 = std::min(y0, y);
            y1 = y;
        }
    }
    if (count_ != 0)
        bounds_ = {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
    const std::size_t stride = tiles_x_ + 1;
    for (uint32_t ty = 0; ty < tiles_y_; ++ty)
        for (uint32_t tx = 0; tx < tiles_x_; ++tx) {
            if (tile_marked[std::size_t(ty) * tiles_x_ + tx])
                tile_origins_.insert(tile_origins_.end(), {tx * kTileSide, ty * kTileSide});
            summed_[(ty + 1) * stride + tx + 1] =
                tile_marked[std::size_t(ty) * tiles_x_ + tx] + summed_[ty * stride + tx + 1] +
                summed_[(ty + 1) * stride + tx] - summed_[ty * stride + tx];
        }
}

bool MarkedPixels::anyTileIn(const PixelRect& rect) const {
    if (count_ == 0 || rect.empty())
        return false;
    const uint32_t width = tiles_x_ * kTileSide, height = tiles_y_ * kTileSide;
    if (rect.x >= width || rect.y >= height)
        return false;
    const std::size_t tx0 = rect.x / kTileSide, ty0 = rect.y / kTileSide;
    const std::size_t tx1 =
        (std::min<uint64_t>(uint64_t(rect.x) + rect.width, width) - 1) / kTileSide + 1;
    const std::size_t ty1 =
        (std::min<uint64_t>(uint64_t(rect.y) + rect.height, height) - 1) / kTileSide + 1;
    const std::size_t stride = tiles_x_ + 1;
    return summed_[ty1 * stride + tx1] - summed_[ty0 * stride + tx1] - summed_[ty1 * stride + tx0] +
               summed_[ty0 * stride + tx0] !=
           0;
}

} // namespace vissort::detail
