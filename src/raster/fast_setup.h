#pragma once
// Triangle set-up for FastCpuOracle (fast_cpu_oracle.h), once per bind: clip, snap, orient, and the
// integer edge functions and depth plane that the tile walks step through. Two implementations
// give the same bits: the scalar one, built on the reference's own functions (cpu_rasterizer.h,
// rules 1-6 of cpu_oracle.h), and an AVX2 one (fast_setup_avx2.cpp) that sets up four
// triangles at a time and hands back to the scalar one every triangle it does not finish.
//
// Number formats: edge functions are exact int64_t values in 24.8 fixed point; the depth plane
// and the screen positions are double.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/cpu_rasterizer.h"
#include "vissort/geometry.h"

namespace vissort::detail {

/// One fan triangle, ready to walk: covered iff edge + bias > 0 for all three edges (the bias is
/// folded into edge_at_origin: the top-left rule's 0 or 1, or in conservative mode the edge's
/// rise over half a pixel and the margin, plus 1).
struct FastSetup {
    int64_t edge_at_origin[3];   // E_i + bias_i at the centre of pixel (0, 0)
    int64_t edge_step_x[3];      // change of E_i from pixel px to px + 1
    int64_t edge_step_y[3];      // change of E_i from row py to py + 1
    double x0, y0, d0, ddx, ddy; // depth plane, as in TriangleSetup
    double spread;               // TriangleSetup::spread: conservative spread or exact snap slack
    int32_t px_min, px_max, py_min, py_max; // inclusive, clamped to the viewport
    // Every edge function fits in int32_t over the pixel bounds (edgesFitInt32), so the AVX2
    // walks may test edges on 32-bit lanes. Decided once per bind, not per draw or query.
    bool narrow;
};

/// Whether every edge function of s (edge_at_origin, steps, pixel bounds) fits in int32_t over
/// the pixel bounds: an edge function is affine, so its extremes are at the bounds' corners.
bool edgesFitInt32(const FastSetup& s);

/// Clips, snaps and sets up triangle t of positions (corners 3t .. 3t + 2) for a width x height
/// viewport, clip being projection * view (rule 1); appends its fan triangles to out (none when
/// it covers no pixel). Conservative: CpuOracle's conservative rules (cpu_oracle.h).
void appendFastSetups(const Matrix4& clip, PositionsView positions, std::size_t t, uint32_t width,
                      uint32_t height, bool conservative, std::vector<FastSetup>& out);

/// What a batch set-up did with each of its triangles.
enum class LaneSetup : uint8_t {
    empty,  // finished: the triangle covers no pixel centre (appendFastSetups appends nothing)
    ready,  // finished: one fan triangle, equal to what appendFastSetups appends
    scalar, // not attempted (clipping needed, non-finite or out-of-range input): use the scalar
};

/// Exact-mode set-up of the four triangles triangles[0..3] (ids into the corner arrays x, y, z of
/// a TrianglePositions) as appendFastSetups would do it, for those that lie inside every clipping
/// plane; out[i] is written where lanes[i] is ready, all but its narrow flag (edgesFitInt32).
using SetupQuadFn = void (*)(const Matrix4& clip, const float* x, const float* y, const float* z,
                             const uint32_t* triangles, uint32_t width, uint32_t height,
                             FastSetup* out, LaneSetup* lanes);

/// The AVX2 batch: only to be called on a CPU with AVX2. Null where the compiler or the target
/// cannot build it.
SetupQuadFn avx2SetupQuad();

} // namespace vissort::detail
