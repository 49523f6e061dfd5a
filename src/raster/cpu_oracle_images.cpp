// CpuOracle's depth images of objects (cpu_oracle_impl.h, depth_images.h): made once a bind on
// first use, and the draws and queries of a primitive through them or set-up by set-up.

#include "raster/cpu_oracle_impl.h"

namespace vissort {

template <bool kNear> void CpuOracle::Impl::buildImage(uint32_t primitive, uint32_t slot) {
    const uint32_t first = primitive_setups_[primitive], last = primitive_setups_[primitive + 1];
    // Sized on the first image (a bind that makes none allocates nothing); its stale tiles are
    // cleared by the epochs, whatever an earlier bind of another size left.
    if (image_tiles_.size() != tiles_.size()) {
        image_depth_.resize(depth_.size());
        image_tiles_.assign(tiles_.size(), TileState{kInfinity, kInfinity, 0, 0});
    }
    std::swap(depth_, image_depth_);
    std::swap(tiles_, image_tiles_);
    std::swap(epoch_, image_epoch_);
    newEpoch(); // an empty buffer
    CpuOracleStats unused;
    for (uint32_t k = first; k < last; ++k) {
        if constexpr (kNear) {
            rasterize<true>(k, 0, int32_t(tiles_y_), unused);
        } else {
            // The farthest fragment per pixel: the nearest of the negated ones, each moved as a
            // query moves it.
            rasterize<true, true>(negatedPlane(setups_[k]), narrow_[k] != 0, spreadOf(k),
                                  errors_[k], 0, int32_t(tiles_y_), unused);
        }
    }
    detail::DepthImages& made = images<kNear>();
    made.begin(slot);
    const PixelRect& rect = imaged_rects_[slot];
    if (rect.x_min <= rect.x_max)
        for (int32_t ty = rect.y_min >> kTileShift; ty <= rect.y_max >> kTileShift; ++ty)
            for (int32_t tx = rect.x_min >> kTileShift; tx <= rect.x_max >> kTileShift; ++tx) {
                const std::size_t tile = std::size_t(ty) * tiles_x_ + std::size_t(tx);
                if (tiles_[tile].epoch == epoch_)
                    made.addTile(uint32_t(tile), tileDepths(tile));
            }
    std::swap(depth_, image_depth_);
    std::swap(tiles_, image_tiles_);
    std::swap(epoch_, image_epoch_);
    if (made.finish(image_budget_bytes_))
        ++stats_.images_built;
}

template <class Visit>
bool CpuOracle::Impl::forImageTiles(const detail::DepthImages& images, uint32_t slot,
                                    const TileRect& rect, Visit&& visit) const {
    const std::size_t end = images.firstEntry(slot) + images.entryCount(slot);
    for (std::size_t e = images.firstEntry(slot); e < end; ++e) {
        const uint32_t tile = images.tile(e);
        const int32_t ty = int32_t(tile / tiles_x_), tx = int32_t(tile % tiles_x_);
        if (ty >= rect.row_last)
            break; // entries are in tile order
        if (ty >= rect.row_first && tx >= rect.column_first && tx <= rect.column_last &&
            visit(e, tile))
            return true;
    }
    return false;
}

void CpuOracle::Impl::drawIn(uint32_t primitive, const TileRect& rect, CpuOracleStats& stats) {
    // Pixel columns of rect.
    const int32_t x_first = rect.column_first << kTileShift;
    const int32_t x_last = (rect.column_last << kTileShift) + int32_t(kTileSize) - 1;
    if (const uint32_t slot = builtSlot<true>(primitive); slot != kNoSlot) {
        const PixelRect& bounds = imaged_rects_[slot];
        const int32_t y_first = rect.row_first << kTileShift;
        const int32_t y_last = (rect.row_last << kTileShift) - 1;
        if (bounds.x_min > x_last || bounds.x_max < x_first || bounds.y_min > y_last ||
            bounds.y_max < y_first)
            return; // nothing of it in rect
        const detail::DepthImages& near = near_images_;
        const float error = image_errors_[slot];
        forImageTiles(near, slot, rect, [&](std::size_t e, uint32_t tile) {
            ++stats.tiles_visited;
            TileState& state = tiles_[tile];
            if (state.epoch != epoch_)
                clearTile(tile);
            if (error > global_error_)
                state.error = std::max(state.error, error);
            // Every depth of the image >= the tile's max >= every stored depth: none passes.
            if (near.bound(e) >= state.max)
                ++stats.tiles_culled;
            else
                detail::drawImageTile(near.depths(e), tileDepths(tile), state.min, state.max);
            return false;
        });
        return;
    }
    for (uint32_t k = primitive_setups_[primitive]; k < primitive_setups_[primitive + 1]; ++k)
        if (setups_[k].px_min <= x_last && setups_[k].px_max >= x_first)
            rasterize<true>(k, rect.row_first, rect.row_last, stats);
}

bool CpuOracle::Impl::anyBehindIn(uint32_t primitive, const TileRect& rect, CpuOracleStats& stats,
                                  QueryContext& context) {
    if (const uint32_t slot = builtSlot<false>(primitive); slot != kNoSlot) {
        const detail::DepthImages& far = far_images_;
        const bool exact = exactRule();
        const float error = image_errors_[slot];
        return forImageTiles(far, slot, rect, [&](std::size_t e, uint32_t tile) {
            ++stats.tiles_visited;
            const TileState& state = tiles_[tile];
            // The thresholds of rasterize: the exact rule's band, or the tolerance.
            const float band_width = exact ? bandOf(error, storedError(state)) : 0;
            const float behind_above = exact ? band_width : depth_tolerance_;
            const float undecided_above =
                exact ? -band_width : std::numeric_limits<float>::infinity();
            // Cleared since last touched (nothing is behind +infinity), or every depth of the
            // image <= the tile's min + threshold <= stored + threshold: none behind (or
            // undecided).
            if (state.epoch != epoch_ ||
                far.bound(e) <= state.min + (exact ? undecided_above : behind_above)) {
                ++stats.tiles_culled;
                return false;
            }
            const detail::QueryResult result = detail::queryImageTile(
                far.depths(e), tileDepths(tile), behind_above, undecided_above);
            if (result == detail::QueryResult::undecided)
                context.undecided->push_back({Undecided::Kind::image_tile, primitive, uint32_t(e)});
            return result == detail::QueryResult::behind;
        });
    }
    for (uint32_t k = primitive_setups_[primitive]; k < primitive_setups_[primitive + 1]; ++k)
        if (rasterize<false>(k, rect.row_first, rect.row_last, stats, &context))
            return true;
    return false;
}

// The passes make images through makeImage (cpu_oracle_impl.h).
template void CpuOracle::Impl::buildImage<true>(uint32_t, uint32_t);
template void CpuOracle::Impl::buildImage<false>(uint32_t, uint32_t);

} // namespace vissort
