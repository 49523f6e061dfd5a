// The scalar per-tile walk of CpuOracle (fast_rows.h) and the run-time choice of the AVX2 one.

#include "raster/fast_rows.h"

#include <algorithm>
#include <limits>

#include "vissort/geometry_oracle.h"

namespace vissort::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Calls pixel(depth, fragment) for every covered pixel of the walk, row by row, until it returns
// true; returns whether it did. The fragment is rule 6's float: the column term
// d0 + ddx ((px + 0.5) - x0), shared by every row, plus the row term, as in the reference, plus
// the walk's offset last.
template <class Pixel> bool forEachCovered(const TileWalk& w, Pixel&& pixel) {
    double column[8];
    for (int32_t k = w.lane_first; k <= w.lane_last; ++k)
        column[k] = w.d0 + w.ddx * ((double(w.vx0 + k) + 0.5) - w.x0);
    int64_t edge_row[3] = {w.edge[0], w.edge[1], w.edge[2]};
    for (int32_t r = 0; r < w.rows; ++r) {
        const double row_term = w.ddy * ((double(w.y0 + r) + 0.5) - w.y0_plane);
        float* row = w.origin + std::size_t(r) * kTileRowFloats;
        int64_t e0 = edge_row[0], e1 = edge_row[1], e2 = edge_row[2];
        for (int32_t k = w.lane_first; k <= w.lane_last; ++k) {
            const bool covered = w.all_covered || ((e0 > 0) & (e1 > 0) & (e2 > 0));
            e0 += w.step_x[0];
            e1 += w.step_x[1];
            e2 += w.step_x[2];
            if (covered && pixel(row[k], float((column[k] + row_term) + w.offset)))
                return true;
        }
        for (int e = 0; e < 3; ++e)
            edge_row[e] += w.step_y[e];
    }
    return false;
}

void drawTileScalar(const TileWalk& w, TileDraw& out) {
    float written_min = kInfinity, stored_max = -kInfinity;
    forEachCovered(w, [&](float& depth, float frag) {
        if (frag < depth) {
            depth = frag;
            written_min = std::min(written_min, frag);
        }
        stored_max = std::max(stored_max, depth);
        return false;
    });
    out = {written_min, stored_max};
}

void fillTileScalar(const TileWalk& w) {
    forEachCovered(w, [](float& depth, float frag) {
        depth = frag;
        return false;
    });
}

QueryResult queryTileScalar(const TileWalk& w) {
    bool undecided = false;
    const bool behind = forEachCovered(w, [&](float depth, float frag) {
        if (frag > depth + w.behind_above)
            return true;
        undecided |= frag > depth + w.undecided_above;
        return false;
    });
    return behind ? QueryResult::behind : undecided ? QueryResult::undecided : QueryResult::none;
}

// Calls pixel(depth, fragment) for every covered pixel of the live tiles of a small walk, row by
// row, until it returns true; returns whether it did. Exact int64_t edge functions, and rule 6's
// expression as in forEachCovered.
template <class Pixel> bool forEachSmallCovered(const SmallWalk& w, Pixel&& pixel) {
    const int32_t tx0 = w.px_min >> 3, ty0 = w.py_min >> 3;
    int64_t edge_row[3] = {w.edge[0], w.edge[1], w.edge[2]};
    for (int32_t py = w.py_min; py <= w.py_max; ++py) {
        const double row_term = w.ddy * ((double(py) + 0.5) - w.y0_plane);
        const int32_t tile_row = (py >> 3) - ty0;
        int64_t e0 = edge_row[0], e1 = edge_row[1], e2 = edge_row[2];
        for (int32_t px = w.px_min; px <= w.px_max; ++px) {
            const bool covered = (e0 > 0) & (e1 > 0) & (e2 > 0);
            e0 += w.step_x[0];
            e1 += w.step_x[1];
            e2 += w.step_x[2];
            const int32_t tile_column = (px >> 3) - tx0;
            if (!covered || !w.live[tile_row][tile_column])
                continue;
            float* tile = w.depth + (std::size_t(py >> 3) * w.tiles_x + std::size_t(px >> 3)) *
                                        (kTileRowFloats * kTileRowFloats);
            float& depth = tile[(py & 7) * kTileRowFloats + (px & 7)];
            const double column = w.d0 + w.ddx * ((double(px) + 0.5) - w.x0);
            if (pixel(depth, float((column + row_term) + w.offset), tile_row, tile_column))
                return true;
        }
        for (int e = 0; e < 3; ++e)
            edge_row[e] += w.step_y[e];
    }
    return false;
}

void drawSmallScalar(const SmallWalk& w, SmallDraw& out) {
    for (auto& row : out.written_min)
        std::fill(std::begin(row), std::end(row), kInfinity);
    forEachSmallCovered(w, [&](float& depth, float frag, int32_t tile_row, int32_t tile_column) {
        if (frag < depth) {
            depth = frag;
            float& least = out.written_min[tile_row][tile_column];
            least = std::min(least, frag);
        }
        return false;
    });
}

QueryResult querySmallScalar(const SmallWalk& w) {
    bool undecided = false;
    const bool behind = forEachSmallCovered(w, [&](float depth, float frag, int32_t, int32_t) {
        if (frag > depth + w.behind_above)
            return true;
        undecided |= frag > depth + w.undecided_above;
        return false;
    });
    return behind ? QueryResult::behind : undecided ? QueryResult::undecided : QueryResult::none;
}

bool cpuHasAvx2() {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
#else
    return false;
#endif
}

} // namespace

RowKernels scalarRowKernels() {
    return {drawTileScalar, queryTileScalar, fillTileScalar, drawSmallScalar, querySmallScalar};
}

RowKernels selectRowKernels(bool allow_simd, bool& uses_simd) {
    uses_simd = false;
    if (!allow_simd || !cpuHasAvx2())
        return scalarRowKernels();
    const RowKernels avx2{avx2DrawTile(), avx2QueryTile(), avx2FillTile(), avx2DrawSmall(),
                          avx2QuerySmall()};
    if (avx2.draw == nullptr || avx2.query == nullptr || avx2.fill == nullptr ||
        avx2.draw_small == nullptr || avx2.query_small == nullptr)
        return scalarRowKernels();
    uses_simd = true;
    return avx2;
}

} // namespace vissort::detail
