// CpuOracle's tile rasterizer (cpu_oracle_impl.h): one set-up walked over the tiles and pixels of
// a range of tile rows, for a draw, a query or a far image; why its shortcuts are exact: the
// comment at the top of cpu_oracle.cpp.

#include "raster/cpu_oracle_impl.h"

namespace vissort {

template <bool kDraw, bool kFarImage>
bool CpuOracle::Impl::rasterize(const StoredSetup& s, bool narrow, double spread, float error,
                                int32_t ty_begin, int32_t ty_end, CpuOracleStats& stats,
                                QueryContext* context, uint32_t k) {
    const int32_t px_min = s.px_min, px_max = s.px_max, py_min = s.py_min, py_max = s.py_max;
    const int32_t tx_first = px_min >> kTileShift, tx_last = px_max >> kTileShift;
    const int32_t ty_first = std::max(py_min >> kTileShift, ty_begin);
    const int32_t ty_last = std::min(py_max >> kTileShift, ty_end - 1);
    if (ty_first > ty_last)
        return false; // outside the band
    const bool exact = exactRule();
    // The band pixels after the walk (the walk covers only the certain ones).
    const auto band = [&] {
        return exact && s.band_first != 0 &&
               rasterizeBand<kDraw>(s, error, ty_begin, ty_end, context, k);
    };
    if (tx_last - tx_first < detail::kSmallTiles && ty_last - ty_first < detail::kSmallTiles)
        return rasterizeSmall<kDraw, kFarImage>(s, narrow, spread, error, ty_first, ty_last, stats,
                                                context, k) ||
               band();
    const int32_t last_x = int32_t(width_) - 1, last_y = int32_t(height_) - 1;
    int64_t origin[3];
    edgeOrigins(s, origin);
    detail::TileWalk walk;
    static_cast<detail::TriangleWalk&>(walk) = walkOf<kDraw, kFarImage>(s, narrow, spread);
    for (int32_t ty = ty_first; ty <= ty_last; ++ty) {
        // Rows of the tile within the viewport, then within the triangle's bounding box.
        const int32_t vy0 = ty << kTileShift, vy1 = std::min(vy0 + int32_t(kTileSize) - 1, last_y);
        const int32_t y0 = std::max(vy0, py_min), y1 = std::min(vy1, py_max);
        const bool whole_rows = y0 == vy0 && y1 == vy1;
        // What the tiles of this row share: each edge at (px_min, y0) and its least and greatest
        // change over the rows, and the depth plane's row terms.
        int64_t edge_at_row[3], rise_low[3], rise_high[3];
        for (int e = 0; e < 3; ++e) {
            edge_at_row[e] =
                origin[e] + int64_t(px_min) * s.edgeStepX(e) + int64_t(y0) * s.edgeStepY(e);
            const int64_t span_y = int64_t(y1 - y0) * s.edgeStepY(e);
            rise_low[e] = std::min<int64_t>(span_y, 0);
            rise_high[e] = std::max<int64_t>(span_y, 0);
        }
        const double by0 = rowTerm(s, y0), by1 = rowTerm(s, y1);
        for (int32_t tx = tx_first; tx <= tx_last; ++tx) {
            ++stats.tiles_visited;
            const int32_t vx0 = tx << kTileShift;
            const int32_t vx1 = std::min(vx0 + int32_t(kTileSize) - 1, last_x);
            const int32_t x0 = std::max(vx0, px_min), x1 = std::min(vx1, px_max);

            // Coverage from the edge functions at the corners of the pixel rectangle.
            int64_t edge_row[3];
            bool inside_all = true, outside_one = false;
            for (int e = 0; e < 3; ++e) {
                edge_row[e] = edge_at_row[e] + int64_t(x0 - px_min) * s.edgeStepX(e);
                const int64_t span_x = int64_t(x1 - x0) * s.edgeStepX(e);
                const int64_t lowest = edge_row[e] + std::min<int64_t>(span_x, 0) + rise_low[e];
                const int64_t highest = edge_row[e] + std::max<int64_t>(span_x, 0) + rise_high[e];
                outside_one |= highest <= 0;
                inside_all &= lowest > 0;
            }
            const std::size_t tile = std::size_t(ty) * tiles_x_ + std::size_t(tx);
            if (outside_one) {
                ++stats.tiles_culled;
                continue;
            }
            TileState& state = tiles_[tile];
            if (state.epoch != epoch_) {
                // Cleared since last touched: a query finds nothing behind +infinity.
                if constexpr (!kDraw) {
                    ++stats.tiles_culled;
                    continue;
                }
                clearTile(tile);
            }
            const bool full_tile = inside_all && whole_rows && x0 == vx0 && x1 == vx1;

            // Rounding to float is monotone: every fragment lies in [float(lowest),
            // float(highest)], and these decide every comparison with a float exactly.
            double lowest, highest;
            depthBounds(s, columnTerm(s, x0), columnTerm(s, x1), by0, by1, walk.offset, spread,
                        lowest, highest);
            bool all_pass = false;
            if constexpr (kDraw) {
                // Every fragment drawn here counts in the tile's error, passing or not.
                if (error > global_error_)
                    state.error = std::max(state.error, error);
                // Every fragment >= the tile's max >= every stored depth: none passes LESS.
                if (float(lowest) >= state.max) {
                    ++stats.tiles_culled;
                    continue;
                }
                // Every fragment < the tile's min <= every stored depth: all pass, no depth test
                // needed (the common case back to front).
                all_pass = float(highest) < state.min;
            } else {
                if (exact) {
                    const float band_width = bandOf(error, storedError(state));
                    walk.behind_above = band_width;
                    walk.undecided_above = -band_width;
                }
                // Every fragment <= the tile's min + threshold <= stored + threshold: none
                // behind, none undecided.
                const float threshold = exact ? walk.undecided_above : walk.behind_above;
                if (float(highest) <= state.min + threshold) {
                    ++stats.tiles_culled;
                    continue;
                }
                // Every pixel covered, every fragment > the tile's max + threshold: behind
                // somewhere.
                if (full_tile && float(lowest) > state.max + walk.behind_above) {
                    ++stats.tiles_accepted;
                    return true;
                }
            }

            // Per pixel (fast_rows.h): rule 6's expression, (d0 + ddx (cx - x0)) + ddy (cy - y0).
            walk.origin = tileDepths(tile) + std::size_t(y0 - vy0) * kTileSize;
            walk.vx0 = vx0;
            walk.y0 = y0;
            walk.lane_first = x0 - vx0;
            walk.lane_last = x1 - vx0;
            walk.rows = y1 - y0 + 1;
            walk.all_covered = inside_all;
            for (int e = 0; e < 3; ++e)
                walk.edge[e] = edge_row[e];
            if constexpr (kDraw) {
                if (all_pass) {
                    fill_tile_(walk);
                    // Bounds from the depth bounds instead of the pixels: every fragment written
                    // lies in [float(lowest), float(highest)].
                    state.min = std::min(state.min, float(lowest));
                    if (full_tile)
                        state.max = float(highest);
                    continue;
                }
                detail::TileDraw result;
                draw_tile_(walk, result);
                state.min = std::min(state.min, result.written_min);
                // A draw covering the whole tile visited every stored depth: the bound is exact.
                if (full_tile)
                    state.max = result.stored_max;
            } else {
                const detail::QueryResult result = query_tile_(walk);
                if (result == detail::QueryResult::behind)
                    return true;
                if (result == detail::QueryResult::undecided)
                    context->undecided->push_back({Undecided::Kind::setup_tile, k, uint32_t(tile)});
            }
        }
    }
    return band();
}

template <bool kDraw>
bool CpuOracle::Impl::rasterizeBand(const StoredSetup& s, float error, int32_t ty_begin,
                                    int32_t ty_end, QueryContext* context, uint32_t k) {
    const uint32_t count = band_pixels_[s.band_first];
    const uint32_t* pixels = band_pixels_.data() + s.band_first + 1;
    const uint32_t row_first = uint32_t(ty_begin) << kTileShift;
    const uint32_t row_end = uint32_t(ty_end) << kTileShift;
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t px = pixels[i] & 0xFFFF, py = pixels[i] >> 16;
        if (py < row_first || py >= row_end)
            continue;
        const std::size_t tile = std::size_t(py >> kTileShift) * tiles_x_ + (px >> kTileShift);
        TileState& state = tiles_[tile];
        float& stored = *pixel(px, py);
        const float fragment = fragmentAt(s, px, py);
        if constexpr (kDraw) {
            if (state.epoch != epoch_)
                clearTile(tile);
            if (error > global_error_)
                state.error = std::max(state.error, error);
            if (fragment < stored) {
                stored = fragment;
                state.min = std::min(state.min, fragment);
            }
        } else {
            if (state.epoch != epoch_)
                continue; // nothing drawn there
            switch (detail::decide(fragment, stored, bandOf(error, storedError(state)))) {
            case detail::Decision::behind:
                return true;
            case detail::Decision::undecided:
                context->undecided->push_back({Undecided::Kind::setup_pixel, k, pixels[i]});
                break;
            case detail::Decision::not_behind:
                break;
            }
        }
    }
    return false;
}

template <bool kDraw, bool kFarImage>
bool CpuOracle::Impl::rasterizeSmall(const StoredSetup& s, bool narrow, double spread, float error,
                                     int32_t ty_first, int32_t ty_last, CpuOracleStats& stats,
                                     QueryContext* context, uint32_t k) {
    detail::SmallWalk walk;
    walk.depth = depth_.data();
    walk.tiles_x = tiles_x_;
    walk.px_min = s.px_min;
    walk.px_max = s.px_max;
    // The rows of the band.
    walk.py_min = std::max(int32_t(s.py_min), ty_first << kTileShift);
    walk.py_max = std::min(int32_t(s.py_max), (ty_last << kTileShift) + int32_t(kTileSize) - 1);
    int64_t origin[3];
    edgeOrigins(s, origin);
    for (int e = 0; e < 3; ++e)
        walk.edge[e] = origin[e] + int64_t(walk.px_min) * s.edgeStepX(e) +
                       int64_t(walk.py_min) * s.edgeStepY(e);
    // narrow holds over the whole bounds, so over the band's rows too.
    static_cast<detail::TriangleWalk&>(walk) = walkOf<kDraw, kFarImage>(s, narrow, spread);
    double lowest, highest;
    depthBounds(s, columnTerm(s, walk.px_min), columnTerm(s, walk.px_max), rowTerm(s, walk.py_min),
                rowTerm(s, walk.py_max), walk.offset, spread, lowest, highest);
    const bool exact = exactRule();

    // Which tiles to walk, decided as the tile walk decides (rasterize), with the triangle's
    // depth bounds for each tile's. A query's band is the widest of its live tiles'.
    const int32_t tx_first = walk.px_min >> kTileShift, tx_last = walk.px_max >> kTileShift;
    bool any = false;
    float widest = 0;
    for (int32_t ty = ty_first; ty <= ty_last; ++ty)
        for (int32_t tx = tx_first; tx <= tx_last; ++tx) {
            ++stats.tiles_visited;
            const std::size_t tile = std::size_t(ty) * tiles_x_ + std::size_t(tx);
            TileState& state = tiles_[tile];
            bool& live = walk.live[ty - ty_first][tx - tx_first];
            if constexpr (kDraw) {
                if (state.epoch != epoch_)
                    clearTile(tile);
                // Every fragment drawn here counts in the tile's error, passing or not.
                if (error > global_error_)
                    state.error = std::max(state.error, error);
                // Every fragment >= the tile's max >= every stored depth: none passes LESS.
                live = lowest < double(state.max);
            } else if (exact) {
                // Cleared since last touched (nothing is behind +infinity), or every fragment
                // <= the tile's min - band: none behind, none undecided.
                const float band_width = bandOf(error, storedError(state));
                live = state.epoch == epoch_ && float(highest) > state.min - band_width;
                if (live)
                    widest = std::max(widest, band_width);
            } else {
                // Cleared since last touched (nothing is behind +infinity), or every fragment
                // <= the tile's min + tolerance <= stored + tolerance: none behind.
                live = state.epoch == epoch_ && highest > double(state.min + depth_tolerance_);
            }
            stats.tiles_culled += live ? 0 : 1;
            any |= live;
        }
    if (!any)
        return false;
    const bool simd_walk = use_simd_ && walk.narrow;
    if constexpr (kDraw) {
        detail::SmallDraw drawn;
        (simd_walk ? draw_small_ : detail::scalarRowKernels().draw_small)(walk, drawn);
        // Stored depths only fall, so max stays a bound; min follows the writes.
        for (int32_t ty = ty_first; ty <= ty_last; ++ty)
            for (int32_t tx = tx_first; tx <= tx_last; ++tx) {
                float& least = tiles_[std::size_t(ty) * tiles_x_ + std::size_t(tx)].min;
                least = std::min(least, drawn.written_min[ty - ty_first][tx - tx_first]);
            }
        return false;
    } else {
        if (exact) {
            walk.behind_above = widest;
            walk.undecided_above = -widest;
        }
        const detail::QueryResult result =
            (simd_walk ? query_small_ : detail::scalarRowKernels().query_small)(walk);
        if (result == detail::QueryResult::undecided)
            for (int32_t ty = ty_first; ty <= ty_last; ++ty)
                for (int32_t tx = tx_first; tx <= tx_last; ++tx)
                    if (walk.live[ty - ty_first][tx - tx_first])
                        context->undecided->push_back(
                            {Undecided::Kind::setup_tile, k,
                             uint32_t(std::size_t(ty) * tiles_x_ + std::size_t(tx))});
        return result == detail::QueryResult::behind;
    }
}

// The walks the other files call (through rasterize(k, ...) and buildImage).
template bool CpuOracle::Impl::rasterize<true, false>(const StoredSetup&, bool, double, float,
                                                      int32_t, int32_t, CpuOracleStats&,
                                                      QueryContext*, uint32_t);
template bool CpuOracle::Impl::rasterize<false, false>(const StoredSetup&, bool, double, float,
                                                       int32_t, int32_t, CpuOracleStats&,
                                                       QueryContext*, uint32_t);
template bool CpuOracle::Impl::rasterize<true, true>(const StoredSetup&, bool, double, float,
                                                     int32_t, int32_t, CpuOracleStats&,
                                                     QueryContext*, uint32_t);

} // namespace vissort
