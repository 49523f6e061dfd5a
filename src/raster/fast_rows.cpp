// The scalar per-tile walk of FastCpuOracle (fast_rows.h) and the run-time choice of the AVX2 one.

#include "raster/fast_rows.h"

#include <algorithm>
#include <limits>

#include "vissort/geometry_oracle.h"

namespace vissort::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Column terms d0 + ddx ((px + 0.5) - x0) of the walked lanes: the first two roundings of rule 6,
// shared by every row (the row term is added last, as in the reference).
void columnTerms(const TileWalk& w, double (&column)[8]) {
    for (int32_t k = w.lane_first; k <= w.lane_last; ++k)
        column[k] = w.d0 + w.ddx * ((double(w.vx0 + k) + 0.5) - w.x0);
}

void drawTileScalar(const TileWalk& w, TileDraw& out) {
    double column[8];
    columnTerms(w, column);
    float written_min = kInfinity, stored_max = -kInfinity;
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
            if (!covered) continue;
            const float frag = float(column[k] + row_term);
            if (frag < row[k]) {
                row[k] = frag;
                written_min = std::min(written_min, frag);
            }
            stored_max = std::max(stored_max, row[k]);
        }
        for (int e = 0; e < 3; ++e) edge_row[e] += w.step_y[e];
    }
    out = {written_min, stored_max};
}

void fillTileScalar(const TileWalk& w) {
    double column[8];
    columnTerms(w, column);
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
            if (covered) row[k] = float(column[k] + row_term);
        }
        for (int e = 0; e < 3; ++e) edge_row[e] += w.step_y[e];
    }
}

bool queryTileScalar(const TileWalk& w) {
    double column[8];
    columnTerms(w, column);
    int64_t edge_row[3] = {w.edge[0], w.edge[1], w.edge[2]};
    for (int32_t r = 0; r < w.rows; ++r) {
        const double row_term = w.ddy * ((double(w.y0 + r) + 0.5) - w.y0_plane);
        const float* row = w.origin + std::size_t(r) * kTileRowFloats;
        int64_t e0 = edge_row[0], e1 = edge_row[1], e2 = edge_row[2];
        for (int32_t k = w.lane_first; k <= w.lane_last; ++k) {
            const bool covered = w.all_covered || ((e0 > 0) & (e1 > 0) & (e2 > 0));
            e0 += w.step_x[0];
            e1 += w.step_x[1];
            e2 += w.step_x[2];
            if (covered && float(column[k] + row_term) > row[k] + kDepthTolerance) return true;
        }
        for (int e = 0; e < 3; ++e) edge_row[e] += w.step_y[e];
    }
    return false;
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

RowKernels scalarRowKernels() { return {drawTileScalar, queryTileScalar, fillTileScalar}; }

RowKernels selectRowKernels(bool allow_simd, bool& uses_simd) {
    uses_simd = false;
    if (!allow_simd || !cpuHasAvx2()) return scalarRowKernels();
    const DrawTileFn draw = avx2DrawTile();
    const QueryTileFn query = avx2QueryTile();
    const FillTileFn fill = avx2FillTile();
    if (draw == nullptr || query == nullptr || fill == nullptr) return scalarRowKernels();
    uses_simd = true;
    return {draw, query, fill};
}

} // namespace vissort::detail
