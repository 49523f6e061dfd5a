// CpuOracle's exact rule (cpu_oracle_impl.h): the fragments a query's walks could not decide by
// floats, decided by the exact model against what was drawn at their pixels.

#include "raster/cpu_oracle_impl.h"

namespace vissort {

void CpuOracle::Impl::ensureTileIndex() {
    if (tile_index_built_.load(std::memory_order_acquire))
        return;
    const std::lock_guard<std::mutex> lock(tile_index_mutex_);
    if (tile_index_built_.load(std::memory_order_relaxed))
        return;
    // Counting sort of (cell, set-up) over each set-up's pixel bounds.
    const std::size_t cells = std::size_t(cellsX()) * cellsY();
    cell_starts_.assign(cells + 1, 0);
    const auto forEachCell = [&](const StoredSetup& s, auto&& visit) {
        for (uint32_t cy = s.py_min >> kCellShift; cy <= uint32_t(s.py_max >> kCellShift); ++cy)
            for (uint32_t cx = s.px_min >> kCellShift; cx <= uint32_t(s.px_max >> kCellShift); ++cx)
                visit(std::size_t(cy) * cellsX() + cx);
    };
    for (const StoredSetup& s : setups_)
        forEachCell(s, [&](std::size_t cell) { ++cell_starts_[cell + 1]; });
    for (std::size_t c = 0; c < cells; ++c)
        cell_starts_[c + 1] += cell_starts_[c];
    cell_setups_.resize(cell_starts_[cells]);
    std::vector<uint32_t> next(cell_starts_.begin(), cell_starts_.end() - 1);
    for (uint32_t k = 0; k < setups_.size(); ++k)
        forEachCell(setups_[k], [&](std::size_t cell) { cell_setups_[next[cell]++] = k; });
    tile_index_built_.store(true, std::memory_order_release);
}

bool CpuOracle::Impl::behindSomethingDrawn(uint32_t triangle, uint32_t px, uint32_t py,
                                           QueryContext& context, float fragment, float error,
                                           CpuOracleStats& stats) {
    ++stats.arbitrations;
    ensureTileIndex();
    const detail::DepthArbiter::Query query = arbiter_.query(triangle, px, py);
    const uint32_t cell = (py >> kCellShift) * cellsX() + (px >> kCellShift);
    // Certainly farther than the query's fragment, by the floats, or not there at all: set-up k
    // decides nothing here.
    const auto irrelevant = [&](uint32_t k) {
        const StoredSetup& s = setups_[k];
        return px < s.px_min || px > s.px_max || py < s.py_min || py > s.py_max ||
               fragmentAt(s, px, py) - double(errors_[k]) > double(fragment) + double(error) ||
               !setupCovers(s, px, py);
    };
    std::vector<uint32_t>* listed = arbitrationList(context, triangle, cell);
    if (listed == nullptr) {
        for (uint32_t i = cell_starts_[cell]; i < cell_starts_[cell + 1]; ++i) {
            const uint32_t k = cell_setups_[i];
            if (setups_[k].triangle() != triangle && !irrelevant(k) &&
                drawnBefore(primitiveOfSetup(k), context.time) &&
                arbiter_.nearness(query, setups_[k].triangle()) ==
                    detail::DepthArbiter::Nearness::nearer)
                return true;
        }
        return false;
    }
    return arbiter_.anyNearer(
        query, *listed, [&](uint32_t k) { return setups_[k].triangle(); }, irrelevant);
}

std::vector<uint32_t>* CpuOracle::Impl::arbitrationList(QueryContext& context, uint32_t triangle,
                                                        uint32_t cell) {
    ArbitrationLists& lists = *context.lists;
    if (lists.generation != arbitration_generation_ || lists.triangle != triangle ||
        lists.time != context.time) {
        lists.generation = arbitration_generation_;
        lists.triangle = triangle;
        lists.time = context.time;
        lists.used = 0;
    }
    for (std::size_t i = 0; i < lists.used; ++i) {
        CellList& found = lists.cells[i];
        if (found.cell != cell)
            continue;
        if (!found.built) {
            found.built = true;
            std::vector<uint32_t>& list = found.setups;
            list.clear();
            for (uint32_t j = cell_starts_[cell]; j < cell_starts_[cell + 1]; ++j) {
                const uint32_t k = cell_setups_[j];
                if (setups_[k].triangle() != triangle &&
                    drawnBefore(primitiveOfSetup(k), context.time))
                    list.push_back(k);
            }
        } else if (!found.deduplicated && ++found.scans >= kDedupeAfterScans) {
            dropCopies(found.setups);
            found.deduplicated = true;
        }
        return &found.setups;
    }
    if (lists.used == lists.cells.size())
        lists.cells.emplace_back();
    CellList& noted = lists.cells[lists.used++];
    noted.cell = cell;
    noted.scans = 1;
    noted.built = noted.deduplicated = false;
    return nullptr;
}

void CpuOracle::Impl::dropCopies(std::vector<uint32_t>& list) const {
    // Copies of a triangle (the same corners in the same order) have the same set-ups but for
    // the triangle and its band list's place, and answer alike: one of each is enough.
    const auto bytes = [&](uint32_t k) {
        return reinterpret_cast<const unsigned char*>(&setups_[k]);
    };
    const auto less = [&](uint32_t a, uint32_t b) {
        const int c = std::memcmp(bytes(a), bytes(b), kSetupShapeBytes);
        return c != 0 ? c < 0 : a < b;
    };
    std::sort(list.begin(), list.end(), less);
    list.erase(std::unique(list.begin(), list.end(),
                           [&](uint32_t a, uint32_t b) {
                               return std::memcmp(bytes(a), bytes(b), kSetupShapeBytes) == 0;
                           }),
               list.end());
}

bool CpuOracle::Impl::setupCovers(const StoredSetup& s, uint32_t px, uint32_t py) const {
    if (certainlyCovers(s, px, py))
        return true;
    if (s.band_first == 0)
        return false;
    const uint32_t count = band_pixels_[s.band_first];
    const uint32_t* pixels = band_pixels_.data() + s.band_first + 1;
    return std::find(pixels, pixels + count, py << 16 | px) != pixels + count;
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
            return behindSomethingDrawn(s.triangle(), px, py, context, fragment, errors_[k], stats);
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
            const StoredSetup& s = setups_[u.what];
            const uint32_t tx = u.where % tiles_x_, ty = u.where / tiles_x_;
            for (uint32_t py = std::max(ty << kTileShift, row_first);
                 !behind && py < std::min((ty + 1) << kTileShift, row_end); ++py)
                for (uint32_t px = tx << kTileShift;
                     !behind && px < std::min((tx + 1) << kTileShift, width_); ++px)
                    behind = certainlyCovers(s, px, py) && setupBehind(u.what, px, py);
        } else {
            // A far image's tile: each pixel whose image depth is undecided, against every
            // triangle of the primitive the exact model says covers it.
            const detail::DepthImages& far = far_images_;
            const uint32_t tile = far.tile(u.where);
            const uint32_t slot = slotOf(u.what);
            const TileState& state = tiles_[tile];
            const float band_width = bandOf(image_errors_[slot], storedError(state));
            const uint32_t tx = tile % tiles_x_, ty = tile / tiles_x_;
            const float* image = far.depths(u.where);
            for (uint32_t py = std::max(ty << kTileShift, row_first);
                 !behind && py < std::min((ty + 1) << kTileShift, row_end); ++py)
                for (uint32_t px = tx << kTileShift;
                     !behind && px < std::min((tx + 1) << kTileShift, width_); ++px) {
                    const float depth =
                        image[(py & (kTileSize - 1)) * kTileSize + (px & (kTileSize - 1))];
                    if (detail::decide(depth, *pixel(px, py), band_width) !=
                        detail::Decision::undecided)
                        continue;
                    const detail::ExactFragments& model = arbiter_.model();
                    const detail::PixelRay ray = model.rays().centre(px, py);
                    uint32_t last = std::numeric_limits<uint32_t>::max();
                    for (uint32_t k = primitive_setups_[u.what];
                         !behind && k < primitive_setups_[u.what + 1]; ++k) {
                        const StoredSetup& s = setups_[k];
                        if (s.triangle() == last || px < s.px_min || px > s.px_max ||
                            py < s.py_min || py > s.py_max)
                            continue;
                        last = s.triangle();
                        behind = model.covers(
                                     ray, detail::TriangleCorners::of(positions_, s.triangle())) &&
                                 behindSomethingDrawn(s.triangle(), px, py, context,
                                                      fragmentAt(s, px, py), errors_[k], stats);
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
