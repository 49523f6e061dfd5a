// CpuOracle's passes split into screen bands (cpu_oracle_impl.h): each band runs the whole
// sequence on its own tile rows on a worker pool, and the answers are OR-ed across bands.

#include "raster/cpu_oracle_impl.h"

namespace vissort {

uint32_t CpuOracle::Impl::bandsFor(std::size_t count) const {
    if (threads_ <= 1 || count < parallel_threshold_ || count == 0 || tiles_y_ < 2)
        return 1;
    return std::min(threads_ * kBandsPerThread, tiles_y_);
}

void CpuOracle::Impl::bandRows(uint32_t b, uint32_t bands, int32_t& first, int32_t& last) const {
    first = int32_t(uint64_t(b) * tiles_y_ / bands);
    last = int32_t(uint64_t(b + 1) * tiles_y_ / bands);
}

// Each band runs the whole sequence on its own tile rows: a tile sees the same draws and queries
// in the same order as with one thread, so it ends with the same depths; a query is behind when
// it is behind in some tile, so the answer is the OR over bands. Answers are set to 0 first, then
// a band that finds a fragment behind stores 1 (a relaxed atomic store: every writer writes the
// same value, and the pool's join publishes it); a band skips a query another band has answered.
void CpuOracle::Impl::backToFrontPass(uint32_t bands, std::span<const uint32_t> sequence,
                                      std::span<const uint8_t> query, std::span<uint8_t> behind) {
    clearBuffer();
    for (std::size_t i = 0; i < sequence.size(); ++i) {
        assert(sequence[i] < primitive_count_);
        if (query[i]) {
            behind[i] = 0;
            ++stats_.queries;
        }
    }
    stats_.draws += sequence.size();
    // Every image the bands use, made before they start; the draws' times, as the sequential
    // pass would stamp them, and each query's (drawnBefore).
    query_times_.resize(sequence.size());
    reserveClock(sequence.size());
    for (std::size_t i = sequence.size(); i-- > 0;) {
        makeImage<true>(sequence[i]);
        if (query[i])
            makeImage<false>(sequence[i]);
        query_times_[i] = clock_;
        stamp(sequence[i]);
    }
    if (band_undecided_.size() < bands)
        band_undecided_.resize(bands);
    runBands(bands, [&](uint32_t b, CpuOracleStats& stats) {
        TileRect rows = wholeScreen();
        bandRows(b, bands, rows.row_first, rows.row_last);
        for (std::size_t i = sequence.size(); i-- > 0;) {
            if (query[i]) {
                std::atomic_ref<uint8_t> answer(behind[i]);
                QueryContext context{&band_undecided_[b], query_times_[i]};
                if (answer.load(std::memory_order_relaxed) == 0 &&
                    queryIn(sequence[i], rows, stats, context))
                    answer.store(1, std::memory_order_relaxed);
            }
            drawIn(sequence[i], rows, stats);
        }
    });
}

// As backToFrontPass: each band draws every occluder into its rows, then answers every target
// there; the answers are OR-ed across bands.
void CpuOracle::Impl::queryAgainst(uint32_t bands, std::span<const uint32_t> occluders,
                                   std::span<const uint32_t> targets, std::span<uint8_t> behind) {
    clearBuffer();
    std::fill(behind.begin(), behind.end(), uint8_t(0));
    stats_.draws += occluders.size();
    stats_.queries += targets.size();
    // Only the pixels of the targets decide the answers, so an occluder's set-up whose bounds miss
    // the targets' bounds is not drawn: the depths there are the same, the answers too. A cycle
    // search tests a few targets against much of the list (source_cycle.cpp), most of it
    // elsewhere on the screen.
    int32_t x_min = int32_t(width_), x_max = -1, y_min = int32_t(height_), y_max = -1;
    for (uint32_t p : targets) {
        assert(p < primitive_count_);
        // A primitive with an image slot has its set-ups' bounds at hand (objects of thousands
        // of triangles: the walk over them was a sixth of the power plant's ordering time).
        if (const uint32_t slot = slotOf(p); slot != kNoSlot) {
            const PixelRect& r = imaged_rects_[slot];
            x_min = std::min(x_min, r.x_min);
            x_max = std::max(x_max, r.x_max);
            y_min = std::min(y_min, r.y_min);
            y_max = std::max(y_max, r.y_max);
            continue;
        }
        for (uint32_t k = primitive_setups_[p]; k < primitive_setups_[p + 1]; ++k) {
            x_min = std::min<int32_t>(x_min, setups_[k].px_min);
            x_max = std::max<int32_t>(x_max, setups_[k].px_max);
            y_min = std::min<int32_t>(y_min, setups_[k].py_min);
            y_max = std::max<int32_t>(y_max, setups_[k].py_max);
        }
    }
    if (x_min > x_max || y_min > y_max)
        return; // no target has a fragment
    const TileRect near_targets{y_min >> kTileShift, (y_max >> kTileShift) + 1, x_min >> kTileShift,
                                x_max >> kTileShift};
    // Every image the bands use, made before they start: the targets', and those of the
    // occluders that reach the targets' bounds.
    for (uint32_t p : occluders) {
        assert(p < primitive_count_);
        const uint32_t slot = slotOf(p);
        if (slot == kNoSlot)
            continue;
        const PixelRect& r = imaged_rects_[slot];
        if (r.x_min <= x_max && r.x_max >= x_min && r.y_min <= y_max && r.y_max >= y_min)
            makeImage<true>(p);
    }
    for (uint32_t p : targets)
        makeImage<false>(p);
    reserveClock(occluders.size());
    for (uint32_t p : occluders)
        stamp(p);
    const uint32_t time = clock_;
    if (band_undecided_.size() < std::max<uint32_t>(bands, 1))
        band_undecided_.resize(std::max<uint32_t>(bands, 1));
    const auto band = [&](uint32_t b, CpuOracleStats& stats) {
        TileRect rect = near_targets; // within the band's rows
        int32_t first_row, last_row;
        bandRows(b, bands, first_row, last_row);
        rect.row_first = std::max(rect.row_first, first_row);
        rect.row_last = std::min(rect.row_last, last_row);
        if (rect.row_first >= rect.row_last)
            return;
        for (uint32_t p : occluders)
            drawIn(p, rect, stats);
        for (std::size_t i = 0; i < targets.size(); ++i) {
            std::atomic_ref<uint8_t> answer(behind[i]);
            QueryContext context{&band_undecided_[b], time};
            if (answer.load(std::memory_order_relaxed) == 0 &&
                queryIn(targets[i], rect, stats, context))
                answer.store(1, std::memory_order_relaxed);
        }
    };
    if (bands <= 1)
        band(0, stats_);
    else
        runBands(bands, band);
}

} // namespace vissort
