// The AVX2 per-tile walk of FastCpuOracle (fast_rows.h): a row of 8 pixels per step, bit for bit
// the scalar loop's results.
//  - Edge tests: the three edge functions of 8 lanes as 8 x int32_t when every walked value fits
//    (exact; almost always), else as int64_t in two 4-lane halves compared with
//    _mm256_cmpgt_epi64 (exact, as in the reference), the masks packed to 8 x 32 bits.
//  - Depth: per lane, in double, ((d0 + ddx ((px + 0.5) - x0)) + row_term) + offset, the same
//    operations in the same order as the reference; _mm256_cvtpd_ps rounds to float by MXCSR, to
//    nearest, as the scalar conversion does. No FMA: the functions target AVX2 only, and the file
//    is compiled with -ffp-contract=off.
//  - Depth test: float compare, blend and store of a whole tile row; lanes not walked (outside the
//    bounding box, or the padding of a tile at the viewport's edge) are stored back unchanged.
// Only the functions below carry the AVX2 target, and they call nothing outside this file but
// intrinsics, so no AVX2 code can be shared with (or picked by the linker for) portable callers.

#include "raster/fast_rows.h"

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))

#include <immintrin.h>

#include <cstdint>
#include <limits>

#include "vissort/geometry_oracle.h"

#define VISSORT_AVX2 __attribute__((target("avx2")))

namespace vissort::detail {
namespace {

struct Avx2Row {
    __m256d column_lo, column_hi;  // d0 + ddx ((px + 0.5) - x0) of lanes 0-3 and 4-7
    __m256i edge_lo[3], edge_hi[3];  // E_e + bias_e of lanes 0-3 and 4-7, current row
    __m256i step_y[3];
    // When every walked value of every edge fits in int32_t (almost always: a tile is 8 pixels
    // and a crossing edge is near zero there), the same tests on 8 x 32-bit lanes. Lanes and rows
    // not walked may wrap around; wrapping is arithmetic modulo 2^32, so the walked values are
    // exact, and the others are masked out.
    bool narrow;
    __m256i edge32[3], step_y32[3];
    __m256i lanes_walked;  // 32-bit lanes: all ones on [lane_first, lane_last]
};

// Does every walked value of edge e fit in int32_t? Bounded by its value at the first walked
// pixel plus the steps to the farthest one (no overflow: steps are below 2^40).
inline bool fitsInt32(const TileWalk& w, int e) {
    const auto magnitude = [](int64_t v) { return v < 0 ? -v : v; };
    const int64_t reach = magnitude(w.edge[e]) + int64_t(w.lane_last - w.lane_first) * magnitude(w.step_x[e]) +
                          int64_t(w.rows - 1) * magnitude(w.step_y[e]);
    return reach <= INT32_MAX;
}

VISSORT_AVX2 inline void start(const TileWalk& w, Avx2Row& a) {
    const __m256d half = _mm256_set1_pd(0.5);
    const __m256d x0 = _mm256_set1_pd(w.x0), ddx = _mm256_set1_pd(w.ddx);
    const __m256d d0 = _mm256_set1_pd(w.d0);
    const __m256d px_lo = _mm256_setr_pd(double(w.vx0), double(w.vx0 + 1), double(w.vx0 + 2),
                                         double(w.vx0 + 3));
    const __m256d px_hi = _mm256_add_pd(px_lo, _mm256_set1_pd(4.0));  // exact: small integers
    a.column_lo = _mm256_add_pd(d0, _mm256_mul_pd(ddx, _mm256_sub_pd(_mm256_add_pd(px_lo, half), x0)));
    a.column_hi = _mm256_add_pd(d0, _mm256_mul_pd(ddx, _mm256_sub_pd(_mm256_add_pd(px_hi, half), x0)));
    const __m256i index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    a.narrow = !w.all_covered && fitsInt32(w, 0) && fitsInt32(w, 1) && fitsInt32(w, 2);
    if (!w.all_covered)
        for (int e = 0; e < 3; ++e) {
            const int64_t s = w.step_x[e];
            // E at lane 0: exact, as every lane's value is (the walked lanes are the scalar loop's).
            const int64_t lane0 = w.edge[e] - int64_t(w.lane_first) * s;
            if (a.narrow) {
                // lane0 + k s modulo 2^32, from both truncated to 32 bits.
                const __m256i s32 = _mm256_set1_epi32(int32_t(uint32_t(uint64_t(s))));
                a.edge32[e] = _mm256_add_epi32(_mm256_set1_epi32(int32_t(uint32_t(uint64_t(lane0)))),
                                               _mm256_mullo_epi32(index, s32));
                a.step_y32[e] = _mm256_set1_epi32(int32_t(uint32_t(uint64_t(w.step_y[e]))));
            } else {
                const __m256i base = _mm256_set1_epi64x(lane0);
                a.edge_lo[e] = _mm256_add_epi64(base, _mm256_setr_epi64x(0, s, 2 * s, 3 * s));
                a.edge_hi[e] = _mm256_add_epi64(base, _mm256_setr_epi64x(4 * s, 5 * s, 6 * s, 7 * s));
                a.step_y[e] = _mm256_set1_epi64x(w.step_y[e]);
            }
        }
    a.lanes_walked = _mm256_and_si256(_mm256_cmpgt_epi32(index, _mm256_set1_epi32(w.lane_first - 1)),
                                      _mm256_cmpgt_epi32(_mm256_set1_epi32(w.lane_last + 1), index));
}

// Covered and walked lanes of the current row, as a float mask; then steps the edges down a row.
VISSORT_AVX2 inline __m256 coverage(const TileWalk& w, Avx2Row& a) {
    if (w.all_covered) return _mm256_castsi256_ps(a.lanes_walked);
    const __m256i zero = _mm256_setzero_si256();
    if (a.narrow) {
        __m256i in = _mm256_and_si256(_mm256_cmpgt_epi32(a.edge32[0], zero),
                                      _mm256_cmpgt_epi32(a.edge32[1], zero));
        in = _mm256_and_si256(in, _mm256_cmpgt_epi32(a.edge32[2], zero));
        for (int e = 0; e < 3; ++e) a.edge32[e] = _mm256_add_epi32(a.edge32[e], a.step_y32[e]);
        return _mm256_castsi256_ps(_mm256_and_si256(in, a.lanes_walked));
    }
    __m256i lo = _mm256_cmpgt_epi64(a.edge_lo[0], zero);
    __m256i hi = _mm256_cmpgt_epi64(a.edge_hi[0], zero);
    lo = _mm256_and_si256(lo, _mm256_cmpgt_epi64(a.edge_lo[1], zero));
    hi = _mm256_and_si256(hi, _mm256_cmpgt_epi64(a.edge_hi[1], zero));
    lo = _mm256_and_si256(lo, _mm256_cmpgt_epi64(a.edge_lo[2], zero));
    hi = _mm256_and_si256(hi, _mm256_cmpgt_epi64(a.edge_hi[2], zero));
    for (int e = 0; e < 3; ++e) {
        a.edge_lo[e] = _mm256_add_epi64(a.edge_lo[e], a.step_y[e]);
        a.edge_hi[e] = _mm256_add_epi64(a.edge_hi[e], a.step_y[e]);
    }
    // 64-bit lanes [lo0 lo1 | lo2 lo3] [hi0 hi1 | hi2 hi3] to 32-bit lanes lo0..lo3 hi0..hi3.
    const __m256 packed = _mm256_shuffle_ps(_mm256_castsi256_ps(lo), _mm256_castsi256_ps(hi),
                                            _MM_SHUFFLE(2, 0, 2, 0));
    const __m256 ordered =
        _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(packed), _MM_SHUFFLE(3, 1, 2, 0)));
    return _mm256_and_ps(ordered, _mm256_castsi256_ps(a.lanes_walked));
}

// Rule 6 for the 8 lanes of row py: the row term added, then the offset, then rounded to float.
VISSORT_AVX2 inline __m256 fragments(const TileWalk& w, const Avx2Row& a, int32_t r) {
    const __m256d row_term = _mm256_set1_pd(w.ddy * ((double(w.y0 + r) + 0.5) - w.y0_plane));
    const __m256d offset = _mm256_set1_pd(w.offset);
    const __m128 lo = _mm256_cvtpd_ps(_mm256_add_pd(_mm256_add_pd(a.column_lo, row_term), offset));
    const __m128 hi = _mm256_cvtpd_ps(_mm256_add_pd(_mm256_add_pd(a.column_hi, row_term), offset));
    return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
}

VISSORT_AVX2 inline float horizontalMin(__m256 v) {
    __m128 m = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_min_ps(m, _mm_movehl_ps(m, m));
    m = _mm_min_ss(m, _mm_shuffle_ps(m, m, 1));
    return _mm_cvtss_f32(m);
}

VISSORT_AVX2 inline float horizontalMax(__m256 v) {
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    m = _mm_max_ss(m, _mm_shuffle_ps(m, m, 1));
    return _mm_cvtss_f32(m);
}

VISSORT_AVX2 void drawTileAvx2(const TileWalk& w, TileDraw& out) {
    Avx2Row a;
    start(w, a);
    const __m256 infinity = _mm256_set1_ps(std::numeric_limits<float>::infinity());
    const __m256 minus_infinity = _mm256_set1_ps(-std::numeric_limits<float>::infinity());
    __m256 written_min = infinity, stored_max = minus_infinity;
    float* row = w.origin;
    for (int32_t r = 0; r < w.rows; ++r, row += kTileRowFloats) {
        const __m256 covered = coverage(w, a);
        const __m256 frag = fragments(w, a, r);
        const __m256 stored = _mm256_loadu_ps(row);
        const __m256 pass = _mm256_and_ps(_mm256_cmp_ps(frag, stored, _CMP_LT_OQ), covered);
        const __m256 now = _mm256_blendv_ps(stored, frag, pass);
        _mm256_storeu_ps(row, now);
        written_min = _mm256_min_ps(written_min, _mm256_blendv_ps(infinity, frag, pass));
        stored_max = _mm256_max_ps(stored_max, _mm256_blendv_ps(minus_infinity, now, covered));
    }
    out = {horizontalMin(written_min), horizontalMax(stored_max)};
}

VISSORT_AVX2 void fillTileAvx2(const TileWalk& w) {
    Avx2Row a;
    start(w, a);
    const bool whole_rows = w.all_covered && w.lane_first == 0 && w.lane_last == 7;
    float* row = w.origin;
    for (int32_t r = 0; r < w.rows; ++r, row += kTileRowFloats) {
        const __m256 covered = coverage(w, a);
        const __m256 frag = fragments(w, a, r);
        if (whole_rows)
            _mm256_storeu_ps(row, frag);
        else
            _mm256_storeu_ps(row, _mm256_blendv_ps(_mm256_loadu_ps(row), frag, covered));
    }
}

VISSORT_AVX2 bool queryTileAvx2(const TileWalk& w) {
    Avx2Row a;
    start(w, a);
    const __m256 tolerance = _mm256_set1_ps(kDepthTolerance);
    const float* row = w.origin;
    for (int32_t r = 0; r < w.rows; ++r, row += kTileRowFloats) {
        const __m256 covered = coverage(w, a);
        const __m256 frag = fragments(w, a, r);
        const __m256 stored = _mm256_loadu_ps(row);
        const __m256 behind =
            _mm256_and_ps(_mm256_cmp_ps(frag, _mm256_add_ps(stored, tolerance), _CMP_GT_OQ), covered);
        if (_mm256_movemask_ps(behind) != 0) return true;
    }
    return false;
}

} // namespace

DrawTileFn avx2DrawTile() { return drawTileAvx2; }
QueryTileFn avx2QueryTile() { return queryTileAvx2; }
FillTileFn avx2FillTile() { return fillTileAvx2; }

} // namespace vissort::detail

#else

namespace vissort::detail {
DrawTileFn avx2DrawTile() { return nullptr; }
QueryTileFn avx2QueryTile() { return nullptr; }
FillTileFn avx2FillTile() { return nullptr; }
} // namespace vissort::detail

#endif
