// CpuOracle's exact rule (cpu_oracle_impl.h): the fragments a query's walks could not decide by
// floats, decided by the exact model against what was drawn at their pixels.

#include "raster/cpu_oracle_impl.h"

#include <optional>

namespace vissort {

void CpuOracle::Impl::ensureTileIndex() {
    if (tile_index_built_.load(std::memory_order_acquire))
        return;
    const std::lock_guard<std::mutex> lock(tile_index_mutex_);
    if (tile_index_built_.load(std::memory_order_relaxed))
        return;
    // Counting sort of (tile, set-up) over each set-up's pixel bounds.
    const std::size_t tiles = std::size_t(tiles_x_) * tiles_y_;
    tile_starts_.assign(tiles + 1, 0);
    const auto forEachTile = [&](const StoredSetup& s, auto&& visit) {
        for (uint32_t ty = s.py_min >> kTileShift; ty <= uint32_t(s.py_max >> kTileShift); ++ty)
            for (uint32_t tx = s.px_min >> kTileShift; tx <= uint32_t(s.px_max >> kTileShift); ++tx)
                visit(std::size_t(ty) * tiles_x_ + tx);
    };
    for (const StoredSetup& s : setups_)
        forEachTile(s, [&](std::size_t tile) { ++tile_starts_[tile + 1]; });
    for (std::size_t t = 0; t < tiles; ++t)
        tile_starts_[t + 1] += tile_starts_[t];
    tile_setups_.resize(tile_starts_[tiles]);
    // Each tile's start serves as its cursor (ascending set-ups: a primitive's are a run), then
    // the starts, each moved to the next tile's, are moved back: no scratch array to allocate.
    for (uint32_t k = 0; k < setups_.size(); ++k)
        forEachTile(setups_[k], [&](std::size_t tile) { tile_setups_[tile_starts_[tile]++] = k; });
    for (std::size_t t = tiles; t > 0; --t)
        tile_starts_[t] = tile_starts_[t - 1];
    tile_starts_[0] = 0;
    // No tile's pixel lists made yet (their vectors kept: a rebind reuses their memory).
    pixel_lists_.resize(tiles);
    if (tiles > pixel_lists_made_capacity_) {
        pixel_lists_made_ = std::make_unique<std::atomic<bool>[]>(tiles);
        pixel_lists_made_capacity_ = tiles;
    }
    for (std::size_t t = 0; t < tiles; ++t)
        pixel_lists_made_[t].store(false, std::memory_order_relaxed);
    tile_index_built_.store(true, std::memory_order_release);
}

const uint32_t* CpuOracle::Impl::pixelList(uint32_t px, uint32_t py, uint32_t& count) {
    const std::size_t tile = std::size_t(py >> kTileShift) * tiles_x_ + (px >> kTileShift);
    if (!pixel_lists_made_[tile].load(std::memory_order_acquire)) {
        const std::lock_guard<std::mutex> lock(tile_index_mutex_);
        if (!pixel_lists_made_[tile].load(std::memory_order_relaxed)) {
            makePixelLists(tile, pixel_lists_[tile]);
            pixel_lists_made_[tile].store(true, std::memory_order_release);
        }
    }
    const std::vector<uint32_t>& lists = pixel_lists_[tile];
    const uint32_t pixel = (py & (kTileSize - 1)) * kTileSize + (px & (kTileSize - 1));
    count = lists[pixel + 1] - lists[pixel];
    return lists.data() + lists[pixel];
}

void CpuOracle::Impl::makePixelLists(std::size_t tile, std::vector<uint32_t>& lists) {
    // (pixel of the tile, set-up) for every pixel a set-up's draws cover, then sorted by pixel
    // and, within a pixel, so that copies of a triangle (equal planes first of all) lie side by
    // side: behindSomethingDrawn asks about one of a run of copies only.
    std::vector<PixelEntry>& entries = pixel_list_entries_;
    entries.clear();
    const uint32_t tx = uint32_t(tile % tiles_x_), ty = uint32_t(tile / tiles_x_);
    const uint32_t x_first = tx << kTileShift, y_first = ty << kTileShift;
    const uint32_t x_end = std::min(x_first + kTileSize, width_);
    const uint32_t y_end = std::min(y_first + kTileSize, height_);
    for (uint32_t j = tile_starts_[tile]; j < tile_starts_[tile + 1]; ++j) {
        const uint32_t k = tile_setups_[j];
        const StoredSetup& s = setups_[k];
        for (uint32_t py = std::max<uint32_t>(y_first, s.py_min), x_lo, x_hi;
             py < y_end && py <= s.py_max; ++py)
            if (certainRowSpan(s, py, x_lo, x_hi))
                for (uint32_t px = std::max(x_lo, x_first); px <= std::min(x_hi, x_end - 1); ++px)
                    entries.push_back({(py - y_first) * kTileSize + (px - x_first), s.d0, k});
        if (s.band_first == 0)
            continue;
        // The band pixels are row by row (bandPixelsOf): the tile's rows are one run.
        const uint32_t* const band_first = band_pixels_.data() + s.band_first + 1;
        const uint32_t* const band_end = band_first + band_pixels_[s.band_first];
        for (const uint32_t* at = std::lower_bound(band_first, band_end, y_first << 16);
             at != band_end && (*at >> 16) < y_end; ++at) {
            const uint32_t px = *at & 0xFFFF, py = *at >> 16;
            if (px >= x_first && px < x_end && !certainlyCovers(s, px, py))
                entries.push_back({(py - y_first) * kTileSize + (px - x_first), s.d0, k});
        }
    }
    // A counting sort by pixel (the tile's 64), then each pixel's few entries by plane and
    // set-up: one std::sort of the tile's entries was half of making the lists.
    lists.assign(kTilePixels + 1 + entries.size(), 0);
    const uint32_t first = uint32_t(kTilePixels + 1);
    for (const PixelEntry& e : entries)
        ++lists[e.pixel + 1];
    lists[0] = first;
    for (std::size_t p = 0; p < kTilePixels; ++p)
        lists[p + 1] += lists[p];
    std::vector<PixelEntry>& sorted = pixel_list_sorted_;
    sorted.resize(entries.size());
    for (const PixelEntry& e : entries)
        sorted[lists[e.pixel]++ - first] = e; // the starts as cursors, moved back below
    for (std::size_t p = kTilePixels; p > 0; --p)
        lists[p] = lists[p - 1];
    lists[0] = first;
    for (std::size_t p = 0; p < kTilePixels; ++p)
        std::sort(sorted.begin() + (lists[p] - first), sorted.begin() + (lists[p + 1] - first),
                  [](const PixelEntry& a, const PixelEntry& b) {
                      return a.d0 != b.d0 ? a.d0 < b.d0 : a.setup < b.setup;
                  });
    for (std::size_t i = 0; i < sorted.size(); ++i)
        lists[first + i] = sorted[i].setup;
}

bool CpuOracle::Impl::behindSomethingDrawn(uint32_t query_setup, uint32_t px, uint32_t py,
                                           QueryContext& context, float fragment, float error,
                                           CpuOracleStats& stats) {
    ++stats.arbitrations;
    ensureTileIndex();
    const uint32_t triangle = setups_[query_setup].triangle();
    uint32_t count = 0;
    const uint32_t* list = pixelList(px, py, count);
    std::optional<detail::DepthArbiter::Query> query; // made at the first set-up to ask about
    const StoredSetup* asked = nullptr;               // the last one asked about: not nearer
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t k = list[i];
        const StoredSetup& s = setups_[k];
        // The query's own triangle, one certainly farther than the query's fragment by the
        // floats, or one not drawn before the query decides nothing here.
        if (s.triangle() == triangle ||
            fragmentAt(s, px, py) - double(errors_[k]) > double(fragment) + double(error) ||
            !drawnBefore(primitiveOfSetup(k), context.time))
            continue;
        // A copy of the last triangle asked about (the same shape: kSetupShapeBytes) answers
        // alike: where a query ties with a stack of copies (assimp's OBJ/box_longline.obj has
        // 236 of each face) a pixel costs one question, not the stack.
        if (asked != nullptr && asked->d0 == s.d0 && std::memcmp(asked, &s, kSetupShapeBytes) == 0)
            continue;
        if (!query)
            query = arbiter_.query(triangle, px, py);
        if (arbiter_.nearnessCovering(*query, s.triangle()) ==
            detail::DepthArbiter::Nearness::nearer)
            return true;
        asked = &s;
    }
    return false;
}

bool CpuOracle::Impl::tileSettledByPairs(uint32_t query_setup, uint32_t tile, uint32_t time) {
    ensureTileIndex();
    const StoredSetup& q = setups_[query_setup];
    const uint32_t triangle = q.triangle();
    // The query's pixels in the tile, within [x0, x1] x [y0, y1].
    const uint32_t tx = tile % tiles_x_, ty = tile / tiles_x_;
    const uint32_t x0 = std::max<uint32_t>(tx << kTileShift, q.px_min);
    const uint32_t x1 = std::min<uint32_t>(((tx + 1) << kTileShift) - 1, q.px_max);
    const uint32_t y0 = std::max<uint32_t>(ty << kTileShift, q.py_min);
    const uint32_t y1 = std::min<uint32_t>(((ty + 1) << kTileShift) - 1, q.py_max);
    if (x0 > x1 || y0 > y1)
        return true;
    // A plane's float depths over a rectangle lie between those at its corners (an affine
    // function, evaluated in double before the float rounding, which keeps order), widened by
    // a hair for the double's own rounding.
    const auto extremes = [&](const StoredSetup& s, uint32_t ax, uint32_t bx, uint32_t ay,
                              uint32_t by, double& low, double& high) {
        low = std::numeric_limits<double>::infinity();
        high = -low;
        for (uint32_t px : {ax, bx})
            for (uint32_t py : {ay, by}) {
                const double d = fragmentAt(s, px, py);
                low = std::min(low, d);
                high = std::max(high, d);
            }
        const double hair = 0x1p-40 * (std::abs(low) + std::abs(high) + 1);
        low -= hair;
        high += hair;
    };
    double q_low, q_high;
    extremes(q, x0, x1, y0, y1, q_low, q_high);
    q_high += double(errors_[query_setup]);
    std::optional<detail::TriangleCorners> corners;
    for (uint32_t j = tile_starts_[tile]; j < tile_starts_[tile + 1]; ++j) {
        const uint32_t k = tile_setups_[j];
        const StoredSetup& s = setups_[k];
        const uint32_t other = s.triangle();
        if (other == triangle || s.px_min > x1 || s.px_max < x0 || s.py_min > y1 || s.py_max < y0 ||
            !drawnBefore(primitiveOfSetup(k), time))
            continue;
        // Certainly farther than the query over the pixels both may cover.
        double low, high;
        extremes(s, std::max<uint32_t>(x0, s.px_min), std::min<uint32_t>(x1, s.px_max),
                 std::max<uint32_t>(y0, s.py_min), std::min<uint32_t>(y1, s.py_max), low, high);
        if (low - double(errors_[k]) > q_high)
            continue;
        if (arbiter_.knownNeverNearer(triangle, other))
            continue;
        // A copy of the query's triangle ties with it everywhere.
        if (!corners)
            corners = detail::TriangleCorners::of(positions_, triangle);
        if (!detail::TriangleCorners::of(positions_, other).sameCornersAs(*corners))
            return false;
    }
    return true;
}

bool CpuOracle::Impl::resolve(QueryContext& context, const TileRect& rect, CpuOracleStats& stats) {
    std::vector<Undecided>& undecided = *context.undecided;
    const uint32_t row_first = uint32_t(rect.row_first) << kTileShift;
    const uint32_t row_end = std::min(uint32_t(rect.row_last) << kTileShift, height_);
    // Whether set-up k's fragment at (px, py) is behind, its float undecided or not.
    const auto setupBehind = [&](uint32_t k, uint32_t px, uint32_t py) {
        const StoredSetup& s = setups_[k];
        const std::size_t tile = std::size_t(py >> kTileShift) * tiles_x_ + (px >> kTileShift);
        const TileState& state = tiles_[tile];
        if (state.epoch != epoch_)
            return false;
        const float fragment = fragmentAt(s, px, py);
        switch (detail::decide(fragment, *pixel(px, py), bandOf(errors_[k], storedError(state)))) {
        case detail::Decision::behind:
            return true;
        case detail::Decision::undecided:
            return behindSomethingDrawn(k, px, py, context, fragment, errors_[k], stats);
        case detail::Decision::not_behind:
            return false;
        }
        return false;
    };
    bool behind = false;
    for (const Undecided& u : undecided) {
        if (u.kind == Undecided::Kind::setup_pixel) {
            behind = setupBehind(u.what, u.where & 0xFFFF, u.where >> 16);
        } else if (u.kind == Undecided::Kind::setup_tile) {
            if (tileSettledByPairs(u.what, u.where, context.time))
                continue; // nothing drawn is nearer at any pixel of the tile
            const StoredSetup& s = setups_[u.what];
            const uint32_t tx = u.where % tiles_x_, ty = u.where / tiles_x_;
            for (uint32_t py = std::max(ty << kTileShift, row_first);
                 !behind && py < std::min((ty + 1) << kTileShift, row_end); ++py)
                for (uint32_t px = tx << kTileShift;
                     !behind && px < std::min((tx + 1) << kTileShift, width_); ++px)
                    behind = certainlyCovers(s, px, py) && setupBehind(u.what, px, py);
        } else {
            // A far image's tile: each pixel whose image depth is undecided, against every
            // triangle of the primitive that covers it by the exact model: the set-ups of the
            // primitive in the pixel's list (certain pixels and exact band pixels), which the
            // arbitration reads anyway. Testing each set-up whose bounds hold the pixel with
            // the exact model instead was half of the 2CylinderEngine's ordering time.
            const detail::DepthImages& far = far_images_;
            const uint32_t tile = far.tile(u.where);
            const uint32_t slot = slotOf(u.what);
            const TileState& state = tiles_[tile];
            const float band_width = bandOf(image_errors_[slot], storedError(state));
            const uint32_t tx = tile % tiles_x_, ty = tile / tiles_x_;
            const float* image = far.depths(u.where);
            ensureTileIndex();
            const uint32_t first_setup = primitive_setups_[u.what];
            const uint32_t setup_count = primitive_setups_[u.what + 1] - first_setup;
            for (uint32_t py = std::max(ty << kTileShift, row_first);
                 !behind && py < std::min((ty + 1) << kTileShift, row_end); ++py)
                for (uint32_t px = tx << kTileShift;
                     !behind && px < std::min((tx + 1) << kTileShift, width_); ++px) {
                    const float depth =
                        image[(py & (kTileSize - 1)) * kTileSize + (px & (kTileSize - 1))];
                    if (detail::decide(depth, *pixel(px, py), band_width) !=
                        detail::Decision::undecided)
                        continue;
                    uint32_t count = 0;
                    const uint32_t* list = pixelList(px, py, count);
                    for (uint32_t i = 0; !behind && i < count; ++i) {
                        const uint32_t k = list[i];
                        if (k - first_setup < setup_count)
                            behind = behindSomethingDrawn(k, px, py, context,
                                                          fragmentAt(setups_[k], px, py),
                                                          errors_[k], stats);
                    }
                }
        }
        if (behind)
            break;
    }
    undecided.clear();
    return behind;
}

} // namespace vissort
