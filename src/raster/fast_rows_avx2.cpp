// The AVX2 per-tile walk of CpuOracle (fast_rows.h): a row of 8 pixels per step, bit for bit
// the scalar loop's results.
//  - Edge tests: the three edge functions of 8 lanes as 8 x int32_t when every walked value fits
//    (TileWalk::narrow: exact; almost always), else as int64_t in two 4-lane halves compared with
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

#include <bit>
#include <cstdint>
#include <limits>

#include "vissort/geometry_oracle.h"

#define VISSORT_AVX2 __attribute__((target("avx2")))

namespace vissort::detail {
namespace {

struct Avx2Row {
    __m256d column_lo, column_hi;   // d0 + ddx ((px + 0.5) - x0) of lanes 0-3 and 4-7
    alignas(32) double row_term[8]; // ddy ((py + 0.5) - y0) of the tile's rows y0 .. y0 + 7
    __m256i edge_lo[3], edge_hi[3]; // E_e + bias_e of lanes 0-3 and 4-7, current row
    __m256i step_y[3];
    // When every walked value of every edge fits in int32_t (TileWalk::narrow; almost always: a
    // crossing edge is near zero over a small triangle), the same tests on 8 x 32-bit lanes.
    // Lanes and rows not walked may wrap around; wrapping is arithmetic modulo 2^32, so the walked
    // values are exact, and the others are masked out.
    bool narrow;
    __m256i edge32[3], step_y32[3];
    __m256i lanes_walked; // 32-bit lanes: all ones on [lane_first, lane_last]
};

VISSORT_AVX2 inline void start(const TileWalk& w, Avx2Row& a) {
    const __m256d half = _mm256_set1_pd(0.5);
    const __m256d four = _mm256_set1_pd(4.0);
    const __m256d x0 = _mm256_set1_pd(w.x0), ddx = _mm256_set1_pd(w.ddx);
    const __m256d d0 = _mm256_set1_pd(w.d0);
    // Small integers: every sum below is exact.
    const __m256d px_lo = _mm256_add_pd(_mm256_set1_pd(double(w.vx0)), _mm256_setr_pd(0, 1, 2, 3));
    const __m256d px_hi = _mm256_add_pd(px_lo, four);
    a.column_lo =
        _mm256_add_pd(d0, _mm256_mul_pd(ddx, _mm256_sub_pd(_mm256_add_pd(px_lo, half), x0)));
    a.column_hi =
        _mm256_add_pd(d0, _mm256_mul_pd(ddx, _mm256_sub_pd(_mm256_add_pd(px_hi, half), x0)));
    // Each row's term as the scalar loop computes it, eight rows in two vectors.
    const __m256d y0 = _mm256_set1_pd(w.y0_plane), ddy = _mm256_set1_pd(w.ddy);
    const __m256d py_lo = _mm256_add_pd(_mm256_set1_pd(double(w.y0)), _mm256_setr_pd(0, 1, 2, 3));
    const __m256d py_hi = _mm256_add_pd(py_lo, four);
    _mm256_store_pd(a.row_term, _mm256_mul_pd(ddy, _mm256_sub_pd(_mm256_add_pd(py_lo, half), y0)));
    _mm256_store_pd(a.row_term + 4,
                    _mm256_mul_pd(ddy, _mm256_sub_pd(_mm256_add_pd(py_hi, half), y0)));
    const __m256i index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    a.narrow = !w.all_covered && w.narrow;
    if (!w.all_covered)
        for (int e = 0; e < 3; ++e) {
            const int64_t s = w.step_x[e];
            // E at lane 0: exact, as every lane's value is (the walked lanes are the scalar
            // loop's).
            const int64_t lane0 = w.edge[e] - int64_t(w.lane_first) * s;
            if (a.narrow) {
                // lane0 + k s modulo 2^32, from both truncated to 32 bits.
                const __m256i s32 = _mm256_set1_epi32(int32_t(uint32_t(uint64_t(s))));
                a.edge32[e] =
                    _mm256_add_epi32(_mm256_set1_epi32(int32_t(uint32_t(uint64_t(lane0)))),
                                     _mm256_mullo_epi32(index, s32));
                a.step_y32[e] = _mm256_set1_epi32(int32_t(uint32_t(uint64_t(w.step_y[e]))));
            } else {
                const __m256i base = _mm256_set1_epi64x(lane0);
                a.edge_lo[e] = _mm256_add_epi64(base, _mm256_setr_epi64x(0, s, 2 * s, 3 * s));
                a.edge_hi[e] =
                    _mm256_add_epi64(base, _mm256_setr_epi64x(4 * s, 5 * s, 6 * s, 7 * s));
                a.step_y[e] = _mm256_set1_epi64x(w.step_y[e]);
            }
        }
    a.lanes_walked =
        _mm256_and_si256(_mm256_cmpgt_epi32(index, _mm256_set1_epi32(w.lane_first - 1)),
                         _mm256_cmpgt_epi32(_mm256_set1_epi32(w.lane_last + 1), index));
}

// Covered and walked lanes of the current row, as a float mask; then steps the edges down a row.
VISSORT_AVX2 inline __m256 coverage(const TileWalk& w, Avx2Row& a) {
    if (w.all_covered)
        return _mm256_castsi256_ps(a.lanes_walked);
    const __m256i zero = _mm256_setzero_si256();
    if (a.narrow) {
        __m256i in = _mm256_and_si256(_mm256_cmpgt_epi32(a.edge32[0], zero),
                                      _mm256_cmpgt_epi32(a.edge32[1], zero));
        in = _mm256_and_si256(in, _mm256_cmpgt_epi32(a.edge32[2], zero));
        for (int e = 0; e < 3; ++e)
            a.edge32[e] = _mm256_add_epi32(a.edge32[e], a.step_y32[e]);
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

// Rule 6 for the 8 lanes of row y0 + r: the row term added, then (kOffset) the offset, then
// rounded to float. Without kOffset the offset is -0.0, whose addition changes no value.
template <bool kOffset>
VISSORT_AVX2 inline __m256 fragments(const TileWalk& w, const Avx2Row& a, int32_t r) {
    const __m256d row_term = _mm256_broadcast_sd(&a.row_term[r]);
    __m256d lo = _mm256_add_pd(a.column_lo, row_term), hi = _mm256_add_pd(a.column_hi, row_term);
    if constexpr (kOffset) {
        const __m256d offset = _mm256_set1_pd(w.offset);
        lo = _mm256_add_pd(lo, offset);
        hi = _mm256_add_pd(hi, offset);
    }
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm256_cvtpd_ps(lo)), _mm256_cvtpd_ps(hi),
                                1);
}

// Whether the walk's offset differs from exact mode's -0.0, bit for bit (adding +0.0 would turn a
// -0.0 into +0.0).
template <class Walk> inline bool hasOffset(const Walk& w) {
    return std::bit_cast<uint64_t>(w.offset) != std::bit_cast<uint64_t>(-0.0);
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

template <bool kOffset> VISSORT_AVX2 void drawTile(const TileWalk& w, TileDraw& out) {
    Avx2Row a;
    start(w, a);
    const __m256 infinity = _mm256_set1_ps(std::numeric_limits<float>::infinity());
    const __m256 minus_infinity = _mm256_set1_ps(-std::numeric_limits<float>::infinity());
    __m256 written_min = infinity, stored_max = minus_infinity;
    float* row = w.origin;
    for (int32_t r = 0; r < w.rows; ++r, row += kTileRowFloats) {
        const __m256 covered = coverage(w, a);
        const __m256 frag = fragments<kOffset>(w, a, r);
        const __m256 stored = _mm256_loadu_ps(row);
        const __m256 pass = _mm256_and_ps(_mm256_cmp_ps(frag, stored, _CMP_LT_OQ), covered);
        const __m256 now = _mm256_blendv_ps(stored, frag, pass);
        _mm256_storeu_ps(row, now);
        written_min = _mm256_min_ps(written_min, _mm256_blendv_ps(infinity, frag, pass));
        stored_max = _mm256_max_ps(stored_max, _mm256_blendv_ps(minus_infinity, now, covered));
    }
    out = {horizontalMin(written_min), horizontalMax(stored_max)};
}

template <bool kOffset> VISSORT_AVX2 void fillTile(const TileWalk& w) {
    Avx2Row a;
    start(w, a);
    float* row = w.origin;
    if (w.all_covered && w.lane_first == 0 && w.lane_last == 7) {
        // Whole rows (the inside of a large triangle): stores only.
        for (int32_t r = 0; r < w.rows; ++r, row += kTileRowFloats)
            _mm256_storeu_ps(row, fragments<kOffset>(w, a, r));
        return;
    }
    for (int32_t r = 0; r < w.rows; ++r, row += kTileRowFloats) {
        const __m256 covered = coverage(w, a);
        const __m256 frag = fragments<kOffset>(w, a, r);
        _mm256_storeu_ps(row, _mm256_blendv_ps(_mm256_loadu_ps(row), frag, covered));
    }
}

template <bool kOffset> VISSORT_AVX2 QueryResult queryTile(const TileWalk& w) {
    Avx2Row a;
    start(w, a);
    const __m256 behind_above = _mm256_set1_ps(w.behind_above);
    const __m256 undecided_above = _mm256_set1_ps(w.undecided_above);
    __m256 undecided = _mm256_setzero_ps();
    const float* row = w.origin;
    for (int32_t r = 0; r < w.rows; ++r, row += kTileRowFloats) {
        const __m256 covered = coverage(w, a);
        const __m256 frag = fragments<kOffset>(w, a, r);
        const __m256 stored = _mm256_loadu_ps(row);
        const __m256 behind = _mm256_and_ps(
            _mm256_cmp_ps(frag, _mm256_add_ps(stored, behind_above), _CMP_GT_OQ), covered);
        if (_mm256_movemask_ps(behind) != 0)
            return QueryResult::behind;
        undecided = _mm256_or_ps(
            undecided,
            _mm256_and_ps(_mm256_cmp_ps(frag, _mm256_add_ps(stored, undecided_above), _CMP_GT_OQ),
                          covered));
    }
    return _mm256_movemask_ps(undecided) != 0 ? QueryResult::undecided : QueryResult::none;
}

// A small triangle's walk (fast_rows.h) over kChunks tile columns (a template argument, so that
// the loops over chunks unroll and their state stays in registers). Set up once: per chunk, the
// column terms and the edge functions of its 8 lanes on 32 bits (SmallWalk::narrow) less 1, so
// that a lane is covered iff the sign bit of E0 - 1 | E1 - 1 | E2 - 1 is clear; per walk, every
// row's term. Per tile row, each chunk's blocked lanes (outside the bounds, or the whole chunk
// when its tile is not live), OR-ed into the same sign bits. Then per row and chunk with a
// covered lane: rule 6's fragments and visit(row of depths, fragments, uncovered lanes' sign bits,
// chunk), which returns true to stop the walk; after_tile_row(tile row) after each tile row.
template <int32_t kChunks, bool kOffset, class Visit, class AfterTileRow>
VISSORT_AVX2 inline bool walkSmall(const SmallWalk& w, Visit&& visit,
                                   AfterTileRow&& after_tile_row) {
    const int32_t cx0 = w.px_min & ~int32_t(7), ty0 = w.py_min >> 3;
    const __m256i index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i ones = _mm256_set1_epi32(-1);
    const __m256d half = _mm256_set1_pd(0.5), four = _mm256_set1_pd(4.0);
    __m256i edge[kChunks][3], step_y[3];
    __m256i outside[kChunks], blocked[kChunks];
    __m256d column_lo[kChunks], column_hi[kChunks];
    for (int e = 0; e < 3; ++e)
        step_y[e] = _mm256_set1_epi32(int32_t(uint32_t(uint64_t(w.step_y[e]))));
    for (int32_t c = 0; c < kChunks; ++c) {
        const int32_t cx = cx0 + 8 * c;
        for (int e = 0; e < 3; ++e) {
            // Lane k of the chunk: E at (px_min, py_min) + (cx + k - px_min) step_x - 1, modulo
            // 2^32: exact on the walked lanes, whose E lies in [-INT32_MAX, INT32_MAX]; the others
            // are blocked.
            const int64_t lane0 = w.edge[e] + int64_t(cx - w.px_min) * w.step_x[e] - 1;
            const __m256i s32 = _mm256_set1_epi32(int32_t(uint32_t(uint64_t(w.step_x[e]))));
            edge[c][e] = _mm256_add_epi32(_mm256_set1_epi32(int32_t(uint32_t(uint64_t(lane0)))),
                                          _mm256_mullo_epi32(index, s32));
        }
        const int32_t first = w.px_min > cx ? w.px_min - cx : 0;
        const int32_t last = w.px_max - cx < 7 ? w.px_max - cx : 7;
        outside[c] = _mm256_or_si256(_mm256_cmpgt_epi32(_mm256_set1_epi32(first), index),
                                     _mm256_cmpgt_epi32(index, _mm256_set1_epi32(last)));
        // Small integers: exact sums.
        const __m256d px_lo = _mm256_add_pd(_mm256_set1_pd(double(cx)), _mm256_setr_pd(0, 1, 2, 3));
        const __m256d px_hi = _mm256_add_pd(px_lo, four);
        const __m256d x0 = _mm256_set1_pd(w.x0), ddx = _mm256_set1_pd(w.ddx),
                      d0 = _mm256_set1_pd(w.d0);
        column_lo[c] =
            _mm256_add_pd(d0, _mm256_mul_pd(ddx, _mm256_sub_pd(_mm256_add_pd(px_lo, half), x0)));
        column_hi[c] =
            _mm256_add_pd(d0, _mm256_mul_pd(ddx, _mm256_sub_pd(_mm256_add_pd(px_hi, half), x0)));
    }
    // Each row's term as the scalar walk computes it, four rows at a time.
    alignas(32) double row_terms[kSmallTiles * 8];
    {
        const __m256d y0 = _mm256_set1_pd(w.y0_plane), ddy = _mm256_set1_pd(w.ddy);
        __m256d py = _mm256_add_pd(_mm256_set1_pd(double(w.py_min)), _mm256_setr_pd(0, 1, 2, 3));
        for (int32_t i = 0; i <= w.py_max - w.py_min; i += 4, py = _mm256_add_pd(py, four))
            _mm256_store_pd(row_terms + i,
                            _mm256_mul_pd(ddy, _mm256_sub_pd(_mm256_add_pd(py, half), y0)));
    }
    // Row py of chunk c: the tile (ty0 + tile_row, (cx0 >> 3) + c), row py & 7; tiles are stored
    // one after another, kTileRowFloats rows of kTileRowFloats floats each.
    constexpr std::size_t kTileFloats = kTileRowFloats * kTileRowFloats;
    float* row = w.depth + (std::size_t(ty0) * w.tiles_x + std::size_t(cx0 >> 3)) * kTileFloats +
                 std::size_t(w.py_min & 7) * kTileRowFloats;
    const auto block = [&](int32_t tile_row) VISSORT_AVX2 {
        for (int32_t c = 0; c < kChunks; ++c)
            blocked[c] = w.live[tile_row][c] ? outside[c] : ones;
    };
    block(0);
    for (int32_t py = w.py_min;; ++py) {
        const int32_t tile_row = (py >> 3) - ty0;
        if ((py & 7) == 0)
            block(tile_row);
        const __m256d row_term = _mm256_broadcast_sd(&row_terms[py - w.py_min]);
        for (int32_t c = 0; c < kChunks; ++c) {
            const __m256i uncovered = _mm256_or_si256(_mm256_or_si256(edge[c][0], edge[c][1]),
                                                      _mm256_or_si256(edge[c][2], blocked[c]));
            for (int e = 0; e < 3; ++e)
                edge[c][e] = _mm256_add_epi32(edge[c][e], step_y[e]);
            if (_mm256_movemask_ps(_mm256_castsi256_ps(uncovered)) == 0xFF)
                continue;
            __m256d lo = _mm256_add_pd(column_lo[c], row_term);
            __m256d hi = _mm256_add_pd(column_hi[c], row_term);
            if constexpr (kOffset) {
                const __m256d offset = _mm256_set1_pd(w.offset);
                lo = _mm256_add_pd(lo, offset);
                hi = _mm256_add_pd(hi, offset);
            }
            const __m256 frag = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm256_cvtpd_ps(lo)),
                                                     _mm256_cvtpd_ps(hi), 1);
            if (visit(row + std::size_t(c) * kTileFloats, frag, _mm256_castsi256_ps(uncovered), c))
                return true;
        }
        const bool last_row = py == w.py_max;
        if ((py & 7) == 7 || last_row)
            after_tile_row(tile_row);
        if (last_row)
            return false;
        // The next row: in the same tiles, or the first row of the tile row below (one row of
        // tiles on, back 7 rows).
        row += (py & 7) == 7 ? w.tiles_x * kTileFloats - 7 * kTileRowFloats : kTileRowFloats;
    }
}

template <int32_t kChunks, bool kOffset>
VISSORT_AVX2 void drawSmall(const SmallWalk& w, SmallDraw& out) {
    const __m256 infinity = _mm256_set1_ps(std::numeric_limits<float>::infinity());
    __m256 written_min[kChunks];
    for (int32_t c = 0; c < kChunks; ++c)
        written_min[c] = infinity;
    walkSmall<kChunks, kOffset>(
        w,
        [&](float* row, __m256 frag, __m256 uncovered, int32_t c) VISSORT_AVX2 {
            // blendv and movemask read sign bits only: pass = covered and frag < stored.
            const __m256 stored = _mm256_loadu_ps(row);
            const __m256 pass =
                _mm256_andnot_ps(uncovered, _mm256_cmp_ps(frag, stored, _CMP_LT_OQ));
            _mm256_storeu_ps(row, _mm256_blendv_ps(stored, frag, pass));
            written_min[c] = _mm256_min_ps(written_min[c], _mm256_blendv_ps(infinity, frag, pass));
            return false;
        },
        [&](int32_t tile_row) VISSORT_AVX2 {
            for (int32_t c = 0; c < kChunks; ++c) {
                out.written_min[tile_row][c] = horizontalMin(written_min[c]);
                written_min[c] = infinity;
            }
        });
}

template <int32_t kChunks, bool kOffset> VISSORT_AVX2 QueryResult querySmall(const SmallWalk& w) {
    const __m256 behind_above = _mm256_set1_ps(w.behind_above);
    const __m256 undecided_above = _mm256_set1_ps(w.undecided_above);
    __m256 undecided = _mm256_setzero_ps();
    const bool behind = walkSmall<kChunks, kOffset>(
        w,
        [&](float* row, __m256 frag, __m256 uncovered, int32_t) VISSORT_AVX2 {
            const __m256 stored = _mm256_loadu_ps(row);
            const __m256 behind = _mm256_andnot_ps(
                uncovered, _mm256_cmp_ps(frag, _mm256_add_ps(stored, behind_above), _CMP_GT_OQ));
            undecided = _mm256_or_ps(
                undecided,
                _mm256_andnot_ps(
                    uncovered,
                    _mm256_cmp_ps(frag, _mm256_add_ps(stored, undecided_above), _CMP_GT_OQ)));
            return _mm256_movemask_ps(behind) != 0;
        },
        [](int32_t) {});
    if (behind)
        return QueryResult::behind;
    return _mm256_movemask_ps(undecided) != 0 ? QueryResult::undecided : QueryResult::none;
}

// Tile columns of a small walk: 1 to kSmallTiles.
inline int32_t chunksOf(const SmallWalk& w) {
    return ((w.px_max - (w.px_min & ~int32_t(7))) >> 3) + 1;
}

template <bool kOffset> VISSORT_AVX2 void drawSmallWith(const SmallWalk& w, SmallDraw& out) {
    switch (chunksOf(w)) {
    case 1:
        drawSmall<1, kOffset>(w, out);
        break;
    case 2:
        drawSmall<2, kOffset>(w, out);
        break;
    default:
        drawSmall<3, kOffset>(w, out);
        break;
    }
}

template <bool kOffset> VISSORT_AVX2 QueryResult querySmallWith(const SmallWalk& w) {
    switch (chunksOf(w)) {
    case 1:
        return querySmall<1, kOffset>(w);
    case 2:
        return querySmall<2, kOffset>(w);
    default:
        return querySmall<3, kOffset>(w);
    }
}

VISSORT_AVX2 void drawSmallAvx2(const SmallWalk& w, SmallDraw& out) {
    static_assert(kSmallTiles == 3, "drawSmallWith and querySmallWith dispatch 1 to 3 chunks");
    // Tiles of rows the walk never reaches keep +infinity (the caller reads only walked ones).
    for (auto& row : out.written_min)
        for (float& least : row)
            least = std::numeric_limits<float>::infinity();
    hasOffset(w) ? drawSmallWith<true>(w, out) : drawSmallWith<false>(w, out);
}
VISSORT_AVX2 QueryResult querySmallAvx2(const SmallWalk& w) {
    return hasOffset(w) ? querySmallWith<true>(w) : querySmallWith<false>(w);
}

VISSORT_AVX2 void drawTileAvx2(const TileWalk& w, TileDraw& out) {
    hasOffset(w) ? drawTile<true>(w, out) : drawTile<false>(w, out);
}
VISSORT_AVX2 void fillTileAvx2(const TileWalk& w) {
    hasOffset(w) ? fillTile<true>(w) : fillTile<false>(w);
}
VISSORT_AVX2 QueryResult queryTileAvx2(const TileWalk& w) {
    return hasOffset(w) ? queryTile<true>(w) : queryTile<false>(w);
}

} // namespace

DrawTileFn avx2DrawTile() {
    return drawTileAvx2;
}
QueryTileFn avx2QueryTile() {
    return queryTileAvx2;
}
FillTileFn avx2FillTile() {
    return fillTileAvx2;
}
DrawSmallFn avx2DrawSmall() {
    return drawSmallAvx2;
}
QuerySmallFn avx2QuerySmall() {
    return querySmallAvx2;
}

} // namespace vissort::detail

#else

namespace vissort::detail {
DrawTileFn avx2DrawTile() {
    return nullptr;
}
QueryTileFn avx2QueryTile() {
    return nullptr;
}
FillTileFn avx2FillTile() {
    return nullptr;
}
DrawSmallFn avx2DrawSmall() {
    return nullptr;
}
QuerySmallFn avx2QuerySmall() {
    return nullptr;
}
} // namespace vissort::detail

#endif
