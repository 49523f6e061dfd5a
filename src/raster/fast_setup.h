#pragma once
// Triangle set-up for CpuOracle (cpu_oracle.h), once per bind: clip, snap, orient, and the
// integer edge functions and depth plane that the tile walks step through. Two implementations
// give the same bits: the scalar one, built on the reference's own functions (cpu_rasterizer.h,
// rules 1-6 of cpu_reference_oracle.h), and an AVX2 one (fast_setup_avx2.cpp) that sets up four
// triangles at a time and hands back to the scalar one every triangle it does not finish.
//
// Number formats: edge functions are exact int64_t values in 24.8 fixed point; the depth plane
// and the screen positions are double.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/cpu_rasterizer.h"
#include "vissort/geometry.h"

namespace vissort::detail {

/// One fan triangle, ready to walk: covered iff edge + bias > 0 for all three edges (the bias is
/// folded into edge_at_origin: the exact rule's -margin; the blending rule adds blendingBias at
/// walk time).
struct FastSetup {
    int64_t edge_at_origin[3];   // E_i + bias_i at the centre of pixel (0, 0)
    int64_t edge_step_x[3];      // change of E_i from pixel px to px + 1
    int64_t edge_step_y[3];      // change of E_i from row py to py + 1
    double x0, y0, d0, ddx, ddy; // depth plane, as in TriangleSetup
    double spread;               // TriangleSetup::spread: the snap slack
    double error;                // TriangleSetup::error: the exact rule's bound
    int64_t margin[3];           // TriangleSetup::margin
    bool flat;                   // TriangleSetup::flat
    // The exact rule's band, as forEachFastBandPixel finds it: the edges it walks (bit e: edge
    // e), and the centres within the margin of the others (every one of them), which the batch
    // set-up's screen found exactly: at most kMaxScreenHits (where it finds more, it hands the
    // edges that had them to the walk instead).
    uint8_t band_walk;
    uint8_t screen_hit_count;
    struct ScreenHit {
        uint16_t px, py;
        uint8_t edge;
    };
    static constexpr int kMaxScreenHits = 4;
    ScreenHit screen_hits[kMaxScreenHits];
    // For the band decisions at bind (screenCoverage), not kept: the unsnapped corners in edge
    // order, whether this fan triangle is its whole triangle (clipping cut nothing), and the
    // least and greatest corner depth.
    double ux[3], uy[3];
    bool whole;
    double d_min, d_max;
    int32_t px_min, px_max, py_min, py_max; // inclusive, clamped to the viewport
    // Every edge function fits in int32_t over the pixel bounds (edgesFitInt32), so the AVX2
    // walks may test edges on 32-bit lanes. Decided once per bind, not per draw or query.
    bool narrow;
};

/// What the blending rule adds to edge e of a set-up whose edge_at_origin carries the exact
/// rule's -margin: the margin back, and the top-left rule's 1 on a top edge (dy == 0, dx > 0)
/// or a left edge (dy < 0), read from the steps (step_x = -256 dy, step_y = 256 dx).
inline int64_t blendingBias(int64_t margin, int64_t step_x, int64_t step_y) {
    return margin + ((step_x == 0 && step_y > 0) || step_x > 0 ? 1 : 0);
}

/// The exact rule's margins (edgeMargins of cpu_rasterizer.h) from a set-up's steps.
inline std::array<int64_t, 3> marginsFromSteps(const int64_t step_x[3], const int64_t step_y[3],
                                               const ScreenErrors& errors) {
    int64_t dx[3], dy[3];
    for (int e = 0; e < 3; ++e) {
        dx[e] = step_y[e] / kSubpixelScale;
        dy[e] = -step_x[e] / kSubpixelScale;
    }
    return edgeMargins(dx, dy, errors);
}

/// The exact rule's band pixels of a set-up (forEachBandPixel of cpu_rasterizer.h, on the fast
/// form of the edge functions): calls visit(px, py) for each.
template <class Visit> void forEachFastBandPixel(const FastSetup& s, Visit&& visit);

/// Whether every edge function of s (edge_at_origin, steps, pixel bounds) fits in int32_t over
/// the pixel bounds, under the exact rule's bias and the blending rule's (up to margin + 1 more):
/// an edge function is affine, so its extremes are at the bounds' corners.
bool edgesFitInt32(const FastSetup& s);

/// Clips, snaps and sets up triangle t of positions (corners 3t .. 3t + 2) for a width x height
/// viewport, clip being projection * view (rule 1); appends its fan triangles to out (none when
/// it covers no pixel): the exact and blending rules' set-up (cpu_reference_oracle.h) with the
/// bind's screen errors.
void appendFastSetups(const Matrix4& clip, PositionsView positions, std::size_t t, uint32_t width,
                      uint32_t height, const ScreenErrors& errors, std::vector<FastSetup>& out);

/// What a batch set-up did with each of its triangles.
enum class LaneSetup : uint8_t {
    empty,  // finished: the triangle covers no pixel centre (appendFastSetups appends nothing)
    ready,  // finished: one fan triangle, equal to what appendFastSetups appends
    scalar, // not attempted (clipping needed, non-finite or out-of-range input): use the scalar
};

/// Exact-mode set-up of the four triangles triangles[0..3] (ids into the corner arrays x, y, z of
/// a TrianglePositions) as appendFastSetups would do it, for those that lie inside every clipping
/// plane and keep some snapped area; out[i] is written where lanes[i] is ready, all but its
/// narrow flag (edgesFitInt32).
using SetupQuadFn = void (*)(const Matrix4& clip, const float* x, const float* y, const float* z,
                             const uint32_t* triangles, uint32_t width, uint32_t height,
                             const ScreenErrors& errors, FastSetup* out, LaneSetup* lanes);

/// The AVX2 batch: only to be called on a CPU with AVX2. Null where the compiler or the target
/// cannot build it.
SetupQuadFn avx2SetupQuad();

/// A centre found by bandAlongEdge: index i along the edge's major axis, at across it.
struct BandHit {
    int64_t i, at;
};
inline constexpr int kMaxBandHits = 16;

/// One edge's walk for forEachFastBandPixel: along its major axis from index `from` to `last`,
/// E at the first centre `start` (raw, per major step `along`, per cross step `cross`, with
/// |cross| > 2 m), the cross index where |E| is least and E there (Bresenham's line in the edge
/// function's values: no division per step, at most one wrap, since |along| <= |cross|); writes
/// the centres with |E| <= m, at most kMaxBandHits of them, and returns how many; `next` is
/// where to resume (last + 1 when done).
int bandAlongEdge(int64_t start, int64_t along, int64_t cross, int64_t m, int64_t from,
                  int64_t last, BandHit* hits, int64_t& next);

/// A quick screen for bandAlongEdge over `steps` steps from start: false when no step's value
/// comes within m of a multiple of cross (then there is no band centre along this edge).
bool mayHaveBand(int64_t start, int64_t along, int64_t cross, int64_t m, int64_t steps);

template <class Visit> void forEachFastBandPixel(const FastSetup& s, Visit&& visit) {
    const int edges = s.flat ? 1 : 3;
    // The raw edge function (without the exact rule's -margin) at a pixel.
    const auto edgeAt = [&](int e, int64_t px, int64_t py) {
        return s.edge_at_origin[e] + s.margin[e] + px * s.edge_step_x[e] + py * s.edge_step_y[e];
    };
    // A band pixel of edge e not reported by an earlier edge, nor certainly outside another.
    const auto take = [&](int e, int64_t px, int64_t py) {
        for (int i = 0; i < edges && !s.flat; ++i) {
            if (i == e)
                continue;
            const int64_t value = edgeAt(i, px, py);
            if (value < -s.margin[i] || (i < e && value <= s.margin[i]))
                return false;
        }
        return true;
    };
    for (int h = 0; h < s.screen_hit_count; ++h) {
        const FastSetup::ScreenHit& hit = s.screen_hits[h];
        if (take(hit.edge, hit.px, hit.py))
            visit(uint32_t(hit.px), uint32_t(hit.py));
    }
    for (int e = 0; e < edges; ++e) {
        if ((s.band_walk & (1u << e)) == 0)
            continue; // screened: its centres are among the hits
        const int64_t m = s.margin[e];
        const int64_t step_x = s.edge_step_x[e], step_y = s.edge_step_y[e];
        // Walk the edge along its major axis, a column (or row) at a time, keeping the row (or
        // column) where |E_e| is least and E_e there, |E_e| <= half the cross step: Bresenham's
        // line in the edge function's values, no division per step. Where the cross step is
        // more than 2 m, that centre is the only one of its column that can be in the band.
        const bool columns = std::abs(step_y) >= std::abs(step_x);
        const int64_t cross = columns ? step_y : step_x, along = columns ? step_x : step_y;
        const int64_t cross_size = std::abs(cross);
        const int64_t first = columns ? s.px_min : s.py_min, last = columns ? s.px_max : s.py_max;
        const int64_t low = columns ? s.py_min : s.px_min, high = columns ? s.py_max : s.px_max;
        if (cross_size > 2 * m) {
            const int64_t start = columns ? edgeAt(e, first, 0) : edgeAt(e, 0, first);
            if (!mayHaveBand(start, along, cross, m, last - first + 1))
                continue;
            BandHit hits[kMaxBandHits];
            int found = 0;
            int64_t from = first;
            do { // in runs of at most kMaxBandHits hits (a long edge along a row of centres)
                found = bandAlongEdge(start + (from - first) * along, along, cross, m, from, last,
                                      hits, from);
                for (int h = 0; h < found; ++h) {
                    if (hits[h].at < low || hits[h].at > high)
                        continue;
                    const int64_t px = columns ? hits[h].i : hits[h].at;
                    const int64_t py = columns ? hits[h].at : hits[h].i;
                    if (take(e, px, py))
                        visit(uint32_t(px), uint32_t(py));
                }
            } while (from <= last);
            continue;
        }
        // A wide band (an edge shorter than its margin): each row's interval of centres.
        for (int64_t py = s.py_min; py <= s.py_max; ++py) {
            const int64_t base = edgeAt(e, 0, py);
            int64_t from = s.px_min, to = s.px_max;
            if (step_x != 0) {
                const int64_t magnitude = std::abs(step_x);
                const int64_t lo = step_x > 0 ? -m - base : base - m;
                const int64_t hi = step_x > 0 ? m - base : base + m;
                from = std::max(from, -floorDiv(-lo, magnitude));
                to = std::min(to, floorDiv(hi, magnitude));
            } else if (base < -m || base > m) {
                continue;
            }
            for (int64_t px = from; px <= to; ++px)
                if (take(e, px, py))
                    visit(uint32_t(px), uint32_t(py));
        }
    }
}

} // namespace vissort::detail
