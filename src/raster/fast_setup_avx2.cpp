// The AVX2 set-up of CpuOracle (fast_setup.h): four triangles at a time, one per 64-bit lane,
// bit for bit what the scalar set-up computes, because every step is the reference's operation in
// the reference's order (cpu_reference_oracle.h, rules 1-6):
//  - rule 1 in double: ((((0 + m_r x) + m_r+4 y) + m_r+8 z) + m_r+12 * 1), no FMA (the file is
//    compiled with -ffp-contract=off and the functions target AVX2 only);
//  - rule 2 only as its shortcut: a triangle with every corner finite, inside every plane and at
//    w > 0 is its own polygon; any other triangle goes back to the scalar set-up, which clips;
//  - rule 4: the perspective divide in double, and the snap as snapToFixed does it (truncate,
//    then step by the fraction), exact in 32-bit integers: clipped screen coordinates stay far
//    below the 2^29 the set-up allows (cpu_rasterizer.h, kMaxSnapped); larger ones go back too;
//  - rule 5: differences of snapped coordinates fit in 31 bits, so every product is an exact
//    _mm256_mul_epi32 and every edge function an exact int64_t, as in the scalar code;
//  - rule 6: the depth plane from the unsnapped vertices in double, the same expressions.
// Only the function below carries the AVX2 target, and it calls nothing outside this file but
// intrinsics, so no AVX2 code can be shared with (or picked by the linker for) portable callers.

#include "raster/fast_setup.h"

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))

#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#define VISSORT_AVX2 __attribute__((target("avx2")))

namespace vissort::detail {
namespace {

// A 64-bit lane mask as 32-bit lanes (lane i of the result is lane i of the mask).
VISSORT_AVX2 inline __m128i narrowMask(__m256i mask) {
    return _mm256_castsi256_si128(
        _mm256_permutevar8x32_epi32(mask, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));
}

// Exact products of 32-bit lanes as 64-bit lanes.
VISSORT_AVX2 inline __m256i product(__m128i a, __m128i b) {
    return _mm256_mul_epi32(_mm256_cvtepi32_epi64(a), _mm256_cvtepi32_epi64(b));
}

// snapToFixed (cpu_rasterizer.cpp) for |v * 256| below 2^31: truncate, then add 1 when the
// fraction left is >= 0.5 and subtract 1 when it is <= -0.5.
VISSORT_AVX2 inline __m128i snap(__m256d v) {
    const __m256d scaled = _mm256_mul_pd(v, _mm256_set1_pd(double(kSubpixelScale)));
    const __m256d whole = _mm256_cvtepi32_pd(_mm256_cvttpd_epi32(scaled));
    const __m256d fraction = _mm256_sub_pd(scaled, whole);
    const __m256d one = _mm256_set1_pd(1.0);
    const __m256d up = _mm256_and_pd(_mm256_cmp_pd(fraction, _mm256_set1_pd(0.5), _CMP_GE_OQ), one);
    const __m256d down =
        _mm256_and_pd(_mm256_cmp_pd(fraction, _mm256_set1_pd(-0.5), _CMP_LE_OQ), one);
    // Small integers: every sum is exact, and so is the conversion back.
    return _mm256_cvttpd_epi32(_mm256_sub_pd(_mm256_add_pd(whole, up), down));
}

// ceilToPixels(v - 128) and floorToPixels(v - 128) of cpu_rasterizer.cpp: the first and last pixel
// whose centre (256 p + 128) is >= v, <= v. Arithmetic shifts, as there.
VISSORT_AVX2 inline __m128i firstCentreFrom(__m128i v) {
    const __m128i half = _mm_set1_epi32(int32_t(kSubpixelScale / 2));
    return _mm_sub_epi32(_mm_setzero_si128(),
                         _mm_srai_epi32(_mm_sub_epi32(half, v), kSubpixelBits));
}
VISSORT_AVX2 inline __m128i lastCentreTo(__m128i v) {
    const __m128i half = _mm_set1_epi32(int32_t(kSubpixelScale / 2));
    return _mm_srai_epi32(_mm_sub_epi32(v, half), kSubpixelBits);
}

VISSORT_AVX2 void setupQuadAvx2(const Matrix4& m, const float* x, const float* y, const float* z,
                                const uint32_t* triangles, uint32_t width, uint32_t height,
                                const ScreenErrors& errors, FastSetup* out, LaneSetup* lanes) {
    const __m256d zero = _mm256_setzero_pd();
    const __m256d one = _mm256_set1_pd(1.0);
    const __m256d sign = _mm256_set1_pd(-0.0);
    const __m256d limit = _mm256_set1_pd(double(kMaxSnapped) / double(kSubpixelScale));
    __m256d ok = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    __m256d sx[3], sy[3], sd[3]; // screen vertices (rule 4), corner k of the four triangles
    for (int k = 0; k < 3; ++k) {
        alignas(32) double in[3][4];
        for (int l = 0; l < 4; ++l) {
            const std::size_t i = 3 * std::size_t(triangles[l]) + std::size_t(k);
            in[0][l] = x[i];
            in[1][l] = y[i];
            in[2][l] = z[i];
        }
        const __m256d px = _mm256_load_pd(in[0]), py = _mm256_load_pd(in[1]),
                      pz = _mm256_load_pd(in[2]);
        __m256d clip[4];
        for (int r = 0; r < 4; ++r) {
            __m256d sum = zero;
            sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(m[r]), px));
            sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(m[4 + r]), py));
            sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(m[8 + r]), pz));
            clip[r] = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(m[12 + r]), one));
        }
        const __m256d cx = clip[0], cy = clip[1], cz = clip[2], cw = clip[3];
        // Finite (v - v is 0 only then), inside every plane, and w > 0: clipping keeps it whole.
        for (__m256d v : {cx, cy, cz, cw})
            ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_sub_pd(v, v), zero, _CMP_EQ_OQ));
        const __m256d guard = _mm256_mul_pd(_mm256_set1_pd(kGuardBand), cw);
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(cz, zero, _CMP_GE_OQ));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_sub_pd(cw, cz), zero, _CMP_GE_OQ));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_add_pd(guard, cx), zero, _CMP_GE_OQ));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_sub_pd(guard, cx), zero, _CMP_GE_OQ));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_add_pd(guard, cy), zero, _CMP_GE_OQ));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_sub_pd(guard, cy), zero, _CMP_GE_OQ));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(cw, zero, _CMP_GT_OQ));
        // toScreen: ((x / w + 1) * 0.5) * width, ((1 - y / w) * 0.5) * height, z / w.
        const __m256d half = _mm256_set1_pd(0.5);
        sx[k] = _mm256_mul_pd(_mm256_mul_pd(_mm256_add_pd(_mm256_div_pd(cx, cw), one), half),
                              _mm256_set1_pd(double(width)));
        sy[k] = _mm256_mul_pd(_mm256_mul_pd(_mm256_sub_pd(one, _mm256_div_pd(cy, cw)), half),
                              _mm256_set1_pd(double(height)));
        sd[k] = _mm256_div_pd(cz, cw);
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_andnot_pd(sign, sx[k]), limit, _CMP_LE_OQ));
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(_mm256_andnot_pd(sign, sy[k]), limit, _CMP_LE_OQ));
    }

    // Rule 5: snap, and orient for a positive doubled area (swap vertices 1 and 2 otherwise).
    __m128i fx[3], fy[3];
    for (int k = 0; k < 3; ++k) {
        fx[k] = snap(sx[k]);
        fy[k] = snap(sy[k]);
    }
    const __m256i area =
        _mm256_sub_epi64(product(_mm_sub_epi32(fx[1], fx[0]), _mm_sub_epi32(fy[2], fy[0])),
                         product(_mm_sub_epi32(fy[1], fy[0]), _mm_sub_epi32(fx[2], fx[0])));
    const __m256i zero64 = _mm256_setzero_si256();
    const __m256i no_area = _mm256_cmpeq_epi64(area, zero64);
    const __m256i negative = _mm256_cmpgt_epi64(zero64, area);
    const __m128i swap32 = narrowMask(negative);
    const __m256d swap64 = _mm256_castsi256_pd(negative);
    {
        const __m128i x1 = fx[1], y1 = fy[1];
        fx[1] = _mm_blendv_epi8(x1, fx[2], swap32);
        fx[2] = _mm_blendv_epi8(fx[2], x1, swap32);
        fy[1] = _mm_blendv_epi8(y1, fy[2], swap32);
        fy[2] = _mm_blendv_epi8(fy[2], y1, swap32);
        for (__m256d* v : {sx, sy, sd}) {
            const __m256d v1 = v[1];
            v[1] = _mm256_blendv_pd(v1, v[2], swap64);
            v[2] = _mm256_blendv_pd(v[2], v1, swap64);
        }
    }

    // Edge functions at the centre of pixel (0, 0), without bias (the exact rule's -margin is
    // subtracted per lane below), and their steps.
    const __m128i zero32 = _mm_setzero_si128();
    const __m128i half32 = _mm_set1_epi32(int32_t(kSubpixelScale / 2));
    __m256i edge[3], step_x[3], step_y[3];
    for (int e = 0; e < 3; ++e) {
        const int j = (e + 1) % 3;
        const __m128i dx = _mm_sub_epi32(fx[j], fx[e]), dy = _mm_sub_epi32(fy[j], fy[e]);
        edge[e] = _mm256_sub_epi64(product(dx, _mm_sub_epi32(half32, fy[e])),
                                   product(dy, _mm_sub_epi32(half32, fx[e])));
        step_x[e] =
            _mm256_slli_epi64(_mm256_cvtepi32_epi64(_mm_sub_epi32(zero32, dy)), kSubpixelBits);
        step_y[e] = _mm256_slli_epi64(_mm256_cvtepi32_epi64(dx), kSubpixelBits);
    }

    // Pixels whose centres the snapped bounding box, grown as setupTriangle grows it, may hold:
    // ceil and floor of (v - 128) / 256. (A growth past 2^20 units goes to the scalar set-up.)
    const int64_t grow_units = rangeGrowth(errors);
    const __m128i grow = _mm_set1_epi32(grow_units < (1 << 20) ? int32_t(grow_units) : 0);
    const __m128i min_x = _mm_sub_epi32(_mm_min_epi32(_mm_min_epi32(fx[0], fx[1]), fx[2]), grow);
    const __m128i max_x = _mm_add_epi32(_mm_max_epi32(_mm_max_epi32(fx[0], fx[1]), fx[2]), grow);
    const __m128i min_y = _mm_sub_epi32(_mm_min_epi32(_mm_min_epi32(fy[0], fy[1]), fy[2]), grow);
    const __m128i max_y = _mm_add_epi32(_mm_max_epi32(_mm_max_epi32(fy[0], fy[1]), fy[2]), grow);
    const __m128i px_min = _mm_max_epi32(firstCentreFrom(min_x), zero32);
    const __m128i px_max = _mm_min_epi32(lastCentreTo(max_x), _mm_set1_epi32(int32_t(width) - 1));
    const __m128i py_min = _mm_max_epi32(firstCentreFrom(min_y), zero32);
    const __m128i py_max = _mm_min_epi32(lastCentreTo(max_y), _mm_set1_epi32(int32_t(height) - 1));
    const __m128i no_centres =
        _mm_or_si128(_mm_cmpgt_epi32(px_min, px_max), _mm_cmpgt_epi32(py_min, py_max));

    // Rule 6: the depth plane through the unsnapped vertices (ddx = ddy = 0 where det == 0).
    const __m256d e1x = _mm256_sub_pd(sx[1], sx[0]), e1y = _mm256_sub_pd(sy[1], sy[0]),
                  e1d = _mm256_sub_pd(sd[1], sd[0]);
    const __m256d e2x = _mm256_sub_pd(sx[2], sx[0]), e2y = _mm256_sub_pd(sy[2], sy[0]),
                  e2d = _mm256_sub_pd(sd[2], sd[0]);
    const __m256d det = _mm256_sub_pd(_mm256_mul_pd(e1x, e2y), _mm256_mul_pd(e2x, e1y));
    const __m256d has_det = _mm256_cmp_pd(det, zero, _CMP_NEQ_UQ);
    const __m256d ddx = _mm256_and_pd(
        has_det,
        _mm256_div_pd(_mm256_sub_pd(_mm256_mul_pd(e1d, e2y), _mm256_mul_pd(e2d, e1y)), det));
    const __m256d ddy = _mm256_and_pd(
        has_det,
        _mm256_div_pd(_mm256_sub_pd(_mm256_mul_pd(e2d, e1x), _mm256_mul_pd(e1d, e2x)), det));

    // The exact rule's margins (edgeMargins' integer form, for a position error of at most
    // 2^-10 units; otherwise the lanes take the scalar form), in double: every value an integer
    // below 2^53, floor exact.
    const double position_units = errors.position_px * double(kSubpixelScale);
    const bool integer_margins = position_units <= 0x1p-10;
    const __m256d reach =
        _mm256_add_pd(_mm256_cvtepi32_pd(_mm_sub_epi32(max_x, min_x)),
                      _mm256_cvtepi32_pd(_mm_sub_epi32(max_y, min_y))); // W + H + 4 grow
    const __m256d eight = _mm256_set1_pd(8.0);
    const __m256d reach_part = _mm256_add_pd(
        reach,
        _mm256_add_pd(_mm256_floor_pd(_mm256_mul_pd(reach, _mm256_set1_pd(1.0 / 512))), eight));
    __m256d margin[3];
    for (int e = 0; e < 3; ++e) {
        const int j = (e + 1) % 3;
        const __m256d length =
            _mm256_add_pd(_mm256_andnot_pd(sign, _mm256_cvtepi32_pd(_mm_sub_epi32(fx[j], fx[e]))),
                          _mm256_andnot_pd(sign, _mm256_cvtepi32_pd(_mm_sub_epi32(fy[j], fy[e]))));
        margin[e] = _mm256_add_pd(
            _mm256_add_pd(_mm256_floor_pd(_mm256_mul_pd(length, _mm256_set1_pd(0.5))),
                          _mm256_floor_pd(_mm256_mul_pd(length, _mm256_set1_pd(1.0 / 1024)))),
            reach_part);
    }

    // fragmentError (cpu_rasterizer.cpp), the same operations in the same order.
    __m256d error;
    {
        const __m256d abs_det = _mm256_andnot_pd(sign, det);
        const __m256d condition =
            _mm256_div_pd(_mm256_add_pd(_mm256_andnot_pd(sign, _mm256_mul_pd(e1x, e2y)),
                                        _mm256_andnot_pd(sign, _mm256_mul_pd(e2x, e1y))),
                          abs_det);
        const __m256d slopes =
            _mm256_add_pd(_mm256_andnot_pd(sign, ddx), _mm256_andnot_pd(sign, ddy));
        const __m256d numerators = _mm256_div_pd(
            _mm256_add_pd(
                _mm256_add_pd(_mm256_add_pd(_mm256_andnot_pd(sign, _mm256_mul_pd(e1d, e2y)),
                                            _mm256_andnot_pd(sign, _mm256_mul_pd(e2d, e1y))),
                              _mm256_andnot_pd(sign, _mm256_mul_pd(e2d, e1x))),
                _mm256_andnot_pd(sign, _mm256_mul_pd(e1d, e2x))),
            abs_det);
        const __m128i extent32 = _mm_add_epi32(
            _mm_max_epi32(_mm_sub_epi32(px_max, px_min), _mm_sub_epi32(py_max, py_min)),
            _mm_set1_epi32(1));
        const __m256d span = _mm256_add_pd(_mm256_cvtepi32_pd(extent32), _mm256_set1_pd(2.0));
        const __m256d inner = _mm256_add_pd(
            _mm256_andnot_pd(sign, sd[0]),
            _mm256_mul_pd(span, _mm256_add_pd(numerators, _mm256_mul_pd(slopes, condition))));
        error = _mm256_add_pd(
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(0x1p-40), inner),
                                        _mm256_set1_pd(errors.depth)),
                          _mm256_mul_pd(_mm256_set1_pd(2 * errors.position_px), slopes)),
            _mm256_set1_pd(0x1p-24));
        // Not usable (no area, a slope or depth not finite, an error not finite): infinite.
        const __m256d infinity = _mm256_set1_pd(std::numeric_limits<double>::infinity());
        const __m256d finite_error =
            _mm256_cmp_pd(_mm256_andnot_pd(sign, error), infinity, _CMP_LT_OQ);
        const __m256d usable = _mm256_and_pd(
            _mm256_and_pd(_mm256_cmp_pd(abs_det, zero, _CMP_GT_OQ), finite_error),
            _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(_mm256_sub_pd(ddx, ddx), zero, _CMP_EQ_OQ),
                                        _mm256_cmp_pd(_mm256_sub_pd(ddy, ddy), zero, _CMP_EQ_OQ)),
                          _mm256_cmp_pd(_mm256_sub_pd(sd[0], sd[0]), zero, _CMP_EQ_OQ)));
        error = _mm256_blendv_pd(infinity, error, usable);
    }

    // The band screen of forEachFastBandPixel (fast_setup.h), per edge: along its major axis,
    // at each step the nearest multiple of the cross step, and whether the edge function there
    // is within the margin: the band centres of that edge, found exactly. In double: the values
    // are integers below 2^50, so every value and remainder is exact, and with the cross step
    // above 2 m the rounded quotient is the nearest multiple wherever the remainder is within m
    // (it is off by at most 2^50 / |cross| 2^-52 of a step, less than the 1 / (2 |cross|) that
    // separates such a quotient from a half). A lane with more than kScreenSteps steps, a wide
    // band or values beyond the limit walks that edge instead.
    constexpr int kScreenSteps = 64;
    uint8_t walk_edges[4] = {}, hit_edges[4] = {}, hit_count[4] = {};
    FastSetup::ScreenHit hits[4][FastSetup::kMaxScreenHits];
    {
        const __m256d first_x = _mm256_cvtepi32_pd(px_min), first_y = _mm256_cvtepi32_pd(py_min);
        const __m256d steps_x = _mm256_cvtepi32_pd(_mm_sub_epi32(px_max, px_min));
        const __m256d steps_y = _mm256_cvtepi32_pd(_mm_sub_epi32(py_max, py_min));
        const __m256d limit = _mm256_set1_pd(0x1p50);
        const __m256d half = _mm256_set1_pd(double(kSubpixelScale / 2));
        const __m256d scale = _mm256_set1_pd(double(kSubpixelScale));
        alignas(16) int32_t first_px[4], first_py[4], last_px[4], last_py[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(first_px), px_min);
        _mm_store_si128(reinterpret_cast<__m128i*>(first_py), py_min);
        _mm_store_si128(reinterpret_cast<__m128i*>(last_px), px_max);
        _mm_store_si128(reinterpret_cast<__m128i*>(last_py), py_max);
        for (int e = 0; e < 3; ++e) {
            // The raw edge function at the centre of pixel (0, 0) and its steps, in double from
            // the snapped corners: exact while the products stay below 2^53 (the limit test
            // below walks the edge otherwise).
            const int j = (e + 1) % 3;
            const __m256d dx = _mm256_cvtepi32_pd(_mm_sub_epi32(fx[j], fx[e]));
            const __m256d dy = _mm256_cvtepi32_pd(_mm_sub_epi32(fy[j], fy[e]));
            const __m256d origin =
                _mm256_sub_pd(_mm256_mul_pd(dx, _mm256_sub_pd(half, _mm256_cvtepi32_pd(fy[e]))),
                              _mm256_mul_pd(dy, _mm256_sub_pd(half, _mm256_cvtepi32_pd(fx[e]))));
            const __m256d sxd = _mm256_mul_pd(_mm256_sub_pd(zero, dy), scale);
            const __m256d syd = _mm256_mul_pd(dx, scale);
            const __m256d columns =
                _mm256_cmp_pd(_mm256_andnot_pd(sign, syd), _mm256_andnot_pd(sign, sxd), _CMP_GE_OQ);
            const __m256d along = _mm256_blendv_pd(syd, sxd, columns);
            const __m256d cross = _mm256_blendv_pd(sxd, syd, columns);
            const __m256d first = _mm256_blendv_pd(first_y, first_x, columns);
            const __m256d last_step = _mm256_blendv_pd(steps_y, steps_x, columns); // steps - 1
            const __m256d start = _mm256_add_pd(origin, _mm256_mul_pd(first, along));
            const __m256d inverse = _mm256_div_pd(_mm256_set1_pd(1.0), cross);
            // Walked instead: too many steps, a wide band, values beyond the limit.
            const __m256d largest = _mm256_add_pd(
                _mm256_add_pd(_mm256_andnot_pd(sign, start),
                              _mm256_mul_pd(_mm256_andnot_pd(sign, along), last_step)),
                _mm256_andnot_pd(sign, cross));
            const __m256d walk = _mm256_or_pd(
                _mm256_or_pd(_mm256_cmp_pd(last_step, _mm256_set1_pd(kScreenSteps - 1), _CMP_GT_OQ),
                             _mm256_cmp_pd(_mm256_andnot_pd(sign, cross),
                                           _mm256_mul_pd(_mm256_set1_pd(2.0), margin[e]),
                                           _CMP_LE_OQ)),
                _mm256_cmp_pd(largest, limit, _CMP_NLT_UQ));
            const int walk_mask = _mm256_movemask_pd(walk);
            const int column_mask = _mm256_movemask_pd(columns);
            for (int l = 0; l < 4; ++l)
                walk_edges[l] |= uint8_t(((walk_mask >> l) & 1) << e);
            // The screened lanes' steps: i <= last_step.
            const __m256d screened_steps = _mm256_blendv_pd(last_step, _mm256_set1_pd(-1.0), walk);
            alignas(32) double lasts[4];
            _mm256_store_pd(lasts, screened_steps);
            const int steps = int(std::max({lasts[0], lasts[1], lasts[2], lasts[3]}));
            __m256d value = start;
            for (int i = 0; i <= steps; ++i) {
                const __m256d active =
                    _mm256_cmp_pd(_mm256_set1_pd(double(i)), screened_steps, _CMP_LE_OQ);
                const __m256d k = _mm256_round_pd(_mm256_mul_pd(value, inverse),
                                                  _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
                const __m256d remainder = _mm256_sub_pd(value, _mm256_mul_pd(k, cross));
                const int hit_mask = _mm256_movemask_pd(
                    _mm256_and_pd(active, _mm256_cmp_pd(_mm256_andnot_pd(sign, remainder),
                                                        margin[e], _CMP_LE_OQ)));
                value = _mm256_add_pd(value, along);
                if (hit_mask == 0)
                    continue;
                // Rare (a centre within about a hundredth of a pixel of the edge): E is the
                // remainder at cross index -k, a centre inside the bounds or none.
                alignas(32) double at[4];
                _mm256_store_pd(at, k);
                for (int l = 0; l < 4; ++l) {
                    if ((hit_mask >> l & 1) == 0)
                        continue;
                    const bool by_columns = (column_mask >> l & 1) != 0;
                    const int64_t across = -int64_t(at[l]);
                    const int64_t low = by_columns ? first_py[l] : first_px[l];
                    const int64_t high = by_columns ? last_py[l] : last_px[l];
                    if (across < low || across > high)
                        continue;
                    hit_edges[l] |= uint8_t(1u << e);
                    if (hit_count[l] < FastSetup::kMaxScreenHits) {
                        const int64_t major = (by_columns ? first_px[l] : first_py[l]) + i;
                        hits[l][hit_count[l]] = {uint16_t(by_columns ? major : across),
                                                 uint16_t(by_columns ? across : major), uint8_t(e)};
                    }
                    ++hit_count[l]; // past kMaxScreenHits: the edges with hits are walked
                }
            }
        }
    }

    alignas(32) int64_t edge_out[3][4], step_x_out[3][4], step_y_out[3][4];
    alignas(32) double plane[5][4], vertex[3][3][4]; // vertex[corner][x, y, d][lane]
    alignas(32) double margins_out[3][4], error_out[4];
    for (int e = 0; e < 3; ++e)
        _mm256_store_pd(margins_out[e], margin[e]);
    _mm256_store_pd(error_out, error);
    alignas(16) int32_t bounds[4][4], empty[4], okay[4], flat[4];
    alignas(32) int64_t planar[4];
    _mm256_store_si256(reinterpret_cast<__m256i*>(planar), _mm256_castpd_si256(has_det));
    for (int e = 0; e < 3; ++e) {
        _mm256_store_si256(reinterpret_cast<__m256i*>(edge_out[e]), edge[e]);
        _mm256_store_si256(reinterpret_cast<__m256i*>(step_x_out[e]), step_x[e]);
        _mm256_store_si256(reinterpret_cast<__m256i*>(step_y_out[e]), step_y[e]);
    }
    for (int k = 0; k < 3; ++k) {
        _mm256_store_pd(vertex[k][0], sx[k]);
        _mm256_store_pd(vertex[k][1], sy[k]);
        _mm256_store_pd(vertex[k][2], sd[k]);
    }
    _mm256_store_pd(plane[0], sx[0]);
    _mm256_store_pd(plane[1], sy[0]);
    _mm256_store_pd(plane[2], sd[0]);
    _mm256_store_pd(plane[3], ddx);
    _mm256_store_pd(plane[4], ddy);
    _mm_store_si128(reinterpret_cast<__m128i*>(bounds[0]), px_min);
    _mm_store_si128(reinterpret_cast<__m128i*>(bounds[1]), px_max);
    _mm_store_si128(reinterpret_cast<__m128i*>(bounds[2]), py_min);
    _mm_store_si128(reinterpret_cast<__m128i*>(bounds[3]), py_max);
    _mm_store_si128(reinterpret_cast<__m128i*>(empty), no_centres);
    _mm_store_si128(reinterpret_cast<__m128i*>(flat), narrowMask(no_area));
    _mm_store_si128(reinterpret_cast<__m128i*>(okay), narrowMask(_mm256_castpd_si256(ok)));
    for (int l = 0; l < 4; ++l) {
        // No snapped area: the exact rule's band along the longest edge, set up by the scalar
        // code (rare). Likewise a growth too large for the vector bounds.
        if (okay[l] == 0 || flat[l] != 0 || grow_units >= (1 << 20)) {
            lanes[l] = LaneSetup::scalar;
            continue;
        }
        if (empty[l] != 0) {
            lanes[l] = LaneSetup::empty;
            continue;
        }
        // snapSlack, written out (nothing outside this file is called), and the scalar
        // set-up's flat case: no plane, or a plane too steep for its slack.
        const double slack =
            std::max(std::abs(plane[3][l]), std::abs(plane[4][l])) * (1.0 / double(kSubpixelScale));
        if (planar[l] == 0 || !std::isfinite(slack)) {
            lanes[l] = LaneSetup::scalar;
            continue;
        }
        lanes[l] = LaneSetup::ready;
        FastSetup& s = out[l];
        s.spread = slack;
        for (int e = 0; e < 3; ++e) {
            s.edge_step_x[e] = step_x_out[e][l];
            s.edge_step_y[e] = step_y_out[e][l];
        }
        std::array<int64_t, 3> margins;
        if (integer_margins)
            for (int e = 0; e < 3; ++e)
                margins[e] = int64_t(margins_out[e][l]);
        else
            margins = marginsFromSteps(s.edge_step_x, s.edge_step_y, errors);
        for (int e = 0; e < 3; ++e) {
            s.margin[e] = margins[e];
            s.edge_at_origin[e] = edge_out[e][l] - margins[e];
        }
        // The screen used the integer margins; otherwise every edge is walked.
        const bool hits_kept = integer_margins && hit_count[l] <= FastSetup::kMaxScreenHits;
        s.band_walk = !integer_margins ? 7 : walk_edges[l] | (hits_kept ? 0 : hit_edges[l]);
        s.screen_hit_count = hits_kept ? hit_count[l] : 0;
        std::copy_n(hits[l], s.screen_hit_count, s.screen_hits);
        s.flat = false;
        s.x0 = plane[0][l];
        s.y0 = plane[1][l];
        s.d0 = plane[2][l];
        s.ddx = plane[3][l];
        s.ddy = plane[4][l];
        s.px_min = bounds[0][l];
        s.px_max = bounds[1][l];
        s.py_min = bounds[2][l];
        s.py_max = bounds[3][l];
        const ScreenVertex v[3] = {{vertex[0][0][l], vertex[0][1][l], vertex[0][2][l]},
                                   {vertex[1][0][l], vertex[1][1][l], vertex[1][2][l]},
                                   {vertex[2][0][l], vertex[2][1][l], vertex[2][2][l]}};
        s.error = error_out[l];
        for (int k = 0; k < 3; ++k) {
            s.ux[k] = v[k].x;
            s.uy[k] = v[k].y;
        }
        s.whole = true; // inside every clipping plane
        s.d_min = std::min({v[0].d, v[1].d, v[2].d});
        s.d_max = std::max({v[0].d, v[1].d, v[2].d});
        s.narrow = false; // the caller's (edgesFitInt32)
    }
}

} // namespace

SetupQuadFn avx2SetupQuad() {
    return setupQuadAvx2;
}

} // namespace vissort::detail

#else

namespace vissort::detail {
SetupQuadFn avx2SetupQuad() {
    return nullptr;
}
} // namespace vissort::detail

#endif
