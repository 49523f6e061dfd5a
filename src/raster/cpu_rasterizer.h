#pragma once
// The reference depth rasterizer behind CpuReferenceOracle: clip, snap, cover, interpolate depth.
// Plain and exact rather than fast; a faster rasterizer must reproduce its coverage and depths bit
// for bit, so every rule is fixed here (the full list is in
// include/vissort/cpu_reference_oracle.h).
//
// Number formats: clip and screen coordinates are double; snapped screen coordinates are 24.8
// fixed point (kSubpixelBits) in int64_t; edge functions are exact int64_t products.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "raster/homogeneous_clip.h"
#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::detail {

/// Sub-pixel precision of snapped screen coordinates: 8 fractional bits.
inline constexpr int kSubpixelBits = 8;
inline constexpr int64_t kSubpixelScale = int64_t(1) << kSubpixelBits;

/// Largest width or height a viewport may have. With the guard band G = 32 (homogeneous_clip.h)
/// and 8 sub-pixel bits a snapped coordinate stays below M = 33/2 * 2^16 * 2^8 < 2^29, so an edge
/// function (two products of differences, each factor below 2M) stays below 8 M^2 < 2^61: exact
/// in int64_t with room to spare.
inline constexpr uint32_t kMaxViewportSize = 1u << 16;

/// Snapped coordinates beyond this are rejected (the triangle draws nothing). Only non-finite or
/// absurd input gets here: clipping keeps honest geometry far below it.
inline constexpr int64_t kMaxSnapped = int64_t(1) << 29;

/// How far the rasterizer's own numbers may lie from the exact fragment model's
/// (geometry/exact_fragments.h) for one bind, from rounding in the clip transform, the divide and
/// the pixel rays, which grows with the coordinates' size against the nearest depth drawn
/// (screenErrorsOf): a screen position by up to position_px pixels, a vertex depth by up to
/// depth. Tiny for honest scenes (about 1e-10 pixels); large coordinates far from the camera
/// widen the exact rule's margins with it, so its certain answers stay certain.
struct ScreenErrors {
    double position_px = 0;
    double depth = 0;
};

/// Column-major 4x4 matrix: element (row r, column c) at 4 c + r.
using Matrix4 = std::array<double, 16>;

/// Rule 1 (cpu_reference_oracle.h): projection * view, summed in this order, once per bind.
inline Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
    Matrix4 out{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            double sum = 0;
            for (int k = 0; k < 4; ++k)
                sum += a[4 * k + r] * b[4 * c + k];
            out[4 * c + r] = sum;
        }
    return out;
}

/// Rule 1: a world corner (float coordinates, w = 1) to clip space, summed in this order.
inline ClipVertex toClipSpace(const Matrix4& m, float x, float y, float z) {
    const double p[4] = {x, y, z, 1.0};
    double clip[4];
    for (int r = 0; r < 4; ++r) {
        double sum = 0;
        for (int k = 0; k < 4; ++k)
            sum += m[4 * k + r] * p[k];
        clip[r] = sum;
    }
    return {clip[0], clip[1], clip[2], clip[3]};
}

/// A vertex after the perspective divide: screen position in pixels (y down) and depth d.
struct ScreenVertex {
    double x = 0, y = 0, d = 0;
};

/// Everything needed to walk one fan triangle's pixels. Vertices are ordered so that the snapped
/// doubled area is positive; edge i runs from vertex i to vertex (i + 1) % 3.
struct TriangleSetup {
    std::array<int64_t, 3> x{}, y{}; // 24.8 fixed point
    std::array<int64_t, 3> bias{};   // 1 on top-left edges, 0 elsewhere: covered iff E + bias > 0
    // The exact rule's margins: a centre with every E_i > margin[i] lies inside the unsnapped
    // triangle, one with some E_i < -margin[i] outside it (edgeMargins).
    std::array<int64_t, 3> margin{};
    // Depth plane d(sx, sy) = d0 + ddx (sx - x0) + ddy (sy - y0), in double.
    double x0 = 0, y0 = 0, d0 = 0, ddx = 0, ddy = 0;
    // Inclusive pixel range whose centres may be covered, clamped to the viewport.
    int64_t px_min = 0, px_max = -1, py_min = 0, py_max = -1;
    // The snap slack (snapSlack): how far the plane's value at a covered
    // centre may be from the depth of the nearest point of the unsnapped triangle (the blending
    // rule moves fragments by it).
    double spread = 0;
    // The exact rule: a bound on the distance between a fragment (depthAt, a float) at a centre
    // inside the triangle and the exact model's depth there (fragmentError); +infinity where
    // the plane is not usable (no area, or too steep), so that every comparison with such a
    // fragment is decided exactly.
    double error = 0;
    // The unsnapped screen corners in edge order (x[i], y[i] snapped from them): what the exact
    // rule's band decisions start from (screenCoverage).
    std::array<double, 3> ux{}, uy{};
    // Snapping left no area (the corners are collinear on the 24.8 grid): no centre is certainly
    // covered, and the blending rule covers none, but the exact model may cover centres near the
    // segment. Edge 0 is then the longest edge, and the band is the centres within the margin
    // of its line (forEachBandPixel).
    bool flat = false;
};

/// Exact mode's snap slack of a depth plane with slopes ddx and ddy (rule 6,
/// cpu_reference_oracle.h). Snapping moves each vertex by at most half a sub-pixel unit per axis,
/// so the snapped triangle lies within the unsnapped one grown by that square: a covered centre is
/// at most 2^-9 pixels per axis from a point of the unsnapped triangle, where the plane's value
/// differs by at most
/// (|ddx| + |ddy|) 2^-9 <= max(|ddx|, |ddy|) 2^-8. The latter is what OpenGL's polygon offset
/// applies with factor 2^-8 (gl_oracle.h), so that both oracles move depths alike. Touching
/// faces meet only where one of them is extrapolated like that.
inline double snapSlack(double ddx, double ddy) {
    return std::max(std::abs(ddx), std::abs(ddy)) * (1.0 / double(kSubpixelScale));
}

/// Exact mode: what a draw or a query adds to a fragment's double depth before rounding (rule
/// 7): the slack towards "not behind" when the tolerance is >= 0 (draws farther, queries
/// nearer: touching faces never count as behind each other), towards "behind" when it is
/// negative (near ties count both ways, as a negative tolerance asks).
inline double exactFragmentOffset(double slack, bool draw, float tolerance) {
    return draw == (tolerance >= 0) ? slack : -slack;
}

/// The exact rule's margins of a set-up's edges, in edge-function units (24.8 fixed point
/// squared): how far snapping, and a screen position error of errors.position_px, can move edge
/// i's function at a pixel centre of the set-up's pixel range. Each snapped corner lies within
/// e = 1/2 + p units per axis of where the exact model's rays put it (p the position error in
/// units), so with u the snapped edge vector, a its first corner and P the centre,
/// E - E* = -(u* x da) + (du x (P - a*)) - (du x da), |du| <= 2 e, which is at most
/// e (|u|_1 + 4 e) + 2 e (|P - a|_1 + 2 e) + 4 e^2; |P - a|_1 is at most the range's width
/// plus height (the snapped corners' box, grown as the range is). Read from the edge vectors
/// alone (dx[i], dy[i], in units), so that a set-up's steps give them back (fast_setup.h).
std::array<int64_t, 3> edgeMargins(const int64_t dx[3], const int64_t dy[3],
                                   const ScreenErrors& errors);

/// How many sub-pixel units setupTriangle grows the snapped box by (a corner's snapping, and
/// the position error, rounded up).
int64_t rangeGrowthOf(double position_units);
inline int64_t rangeGrowth(const ScreenErrors& errors) {
    const double units = errors.position_px * double(kSubpixelScale);
    return units <= 1.0 ? (units > 0 ? 2 : 1) : rangeGrowthOf(units); // ceil(units) + 1
}

/// The exact rule's bound on |fragment - exact depth| for a fan triangle with unsnapped screen
/// vertices v (the plane's, in the order its d0, ddx, ddy were computed from) over pixel bounds
/// of the given extent (the larger side, in pixels): the rounding of the plane's slopes, which
/// grows with the conditioning of its 2 x 2 system (a sliver's), and of its evaluation, taken at
/// 2^-40 of the magnitudes involved (a thousand times what double rounding leaves); the screen
/// errors moved along the slopes; and the final rounding to float (2^-24, half a unit in the
/// last place of a depth below 2). +infinity where the plane is not finite or has no area.
double fragmentError(const ScreenVertex v[3], double ddx, double ddy, double extent,
                     const ScreenErrors& errors);

/// The exact rule's decision band for a fragment of error bound `error` against a stored depth
/// whose fragments had errors up to `stored_error`: a float B such that frag > stored + B
/// (float sum) proves the fragment exactly behind, and frag <= stored - B proves it exactly not
/// behind, whatever the two sums round to (B carries 2^-22 for that, depths being below 2).
float decisionBand(double error, double stored_error);

/// The exact rule's band decision in screen space, which settles almost every band pixel without
/// the exact model: +1 when pixel (px, py)'s centre lies inside the triangle with unsnapped
/// corners (ux, uy) by more than the screen error and the rounding can move it (so inside the
/// exact model's triangle), -1 when it lies that far outside (strictly on the inner side of one
/// edge and the outer side of another: the corners may turn either way), 0 when it cannot
/// tell. Valid for a fan triangle that is a whole triangle (not clipped): its edges are the
/// original's.
int screenCoverage(const std::array<double, 3>& ux, const std::array<double, 3>& uy, uint32_t px,
                   uint32_t py, const ScreenErrors& errors);

/// How a query fragment compares with the stored depth under the exact rule.
enum class Decision : uint8_t {
    not_behind, // exactly, whatever was drawn there
    behind,     // exactly
    undecided,  // within the band: the exact model decides (the oracle's arbitration)
};
inline Decision decide(float fragment, float stored, float band) {
    if (fragment > stored + band)
        return Decision::behind;
    return fragment > stored - band ? Decision::undecided : Decision::not_behind;
}

/// The screen errors of one bind: view through clip (projection * view) over the triangles of
/// positions that the primitives hold (a multi-stage group's few, not the whole scene's).
ScreenErrors screenErrorsOf(const Matrix4& clip, const ViewProjection& view,
                            PositionsView positions, std::span<const PrimitiveRange> primitives);

/// Screen mapping of a clip-space point: sx = (x / w + 1) * 0.5 * width,
/// sy = (1 - y / w) * 0.5 * height, d = z / w.
ScreenVertex toScreen(const ClipVertex& v, uint32_t width, uint32_t height);

/// Round to nearest (halves away from zero) in 24.8 fixed point: llround(v * 256). |v * 256|
/// must be at most kMaxSnapped (setupTriangle checks before snapping).
int64_t snapToFixed(double v);

/// Snaps, orients and sets up one screen triangle for the exact and blending rules (the margin
/// and error of the exact rule with errors). Returns false when it can cover no pixel centre:
/// zero snapped area, a non-finite or out-of-range coordinate, or off-screen bounds. (A
/// triangle of zero snapped area can have fragments in the exact model, at centres within the
/// snapping of its edges: the exact rule finds them as band pixels of the fan triangles around,
/// or, for a triangle all of whose fan triangles have none, setupBand.)
bool setupTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                   uint32_t width, uint32_t height, const ScreenErrors& errors,
                   TriangleSetup& setup);

/// Exact rule: calls visit(px, py) once for every pixel of s's range whose centre is neither
/// certainly inside (every E_i > margin) nor certainly outside (some E_i < -margin): a band
/// pixel, where only the exact model can say whether the triangle covers it. Rows top to bottom.
/// Finds them edge by edge, row by row, from where each edge function crosses the band (the
/// work is the rows and the band pixels, not the area). Stops, returning true, when visit does.
template <class Visit> bool forEachBandPixel(const TriangleSetup& s, Visit&& visit);

/// The edge function of edge i at a 24.8 fixed-point point: positive inside.
inline int64_t edgeFunction(const TriangleSetup& s, int i, int64_t px, int64_t py) {
    const int j = (i + 1) % 3;
    return (s.x[j] - s.x[i]) * (py - s.y[i]) - (s.y[j] - s.y[i]) * (px - s.x[i]);
}

/// Depth of the plane at the centre of pixel (px, py), evaluated in double, offset added (-0.0
/// changes nothing), rounded to float.
inline float depthAt(const TriangleSetup& s, int64_t px, int64_t py, double offset = -0.0) {
    const double cx = double(px) + 0.5, cy = double(py) + 0.5;
    return float((s.d0 + s.ddx * (cx - s.x0) + s.ddy * (cy - s.y0)) + offset);
}

/// Which centres a walk visits: those the top-left rule covers (the blending rule, and the GPU's
/// rasterization), or those certainly inside the unsnapped triangle (the exact rule: every
/// E_i > margin; its band pixels come from forEachBandPixel).
enum class Coverage : uint8_t { top_left, certain };

/// The bias of edge i under a coverage rule: covered iff E_i + bias > 0.
inline int64_t coverageBias(const TriangleSetup& s, int i, Coverage coverage) {
    return coverage == Coverage::top_left ? s.bias[i] : -s.margin[i];
}

/// Calls visit(px, py, depth) for every pixel whose centre the set-up triangle covers under the
/// rule, rows top to bottom, left to right, depth being depthAt(s, px, py, offset). Stops,
/// returning true, as soon as visit returns true.
template <class Visit>
bool walkTriangle(const TriangleSetup& s, Visit&& visit, double offset = -0.0,
                  Coverage coverage = Coverage::top_left) {
    const int64_t bias[3] = {coverageBias(s, 0, coverage), coverageBias(s, 1, coverage),
                             coverageBias(s, 2, coverage)};
    for (int64_t py = s.py_min; py <= s.py_max; ++py) {
        const int64_t cy = py * kSubpixelScale + kSubpixelScale / 2;
        for (int64_t px = s.px_min; px <= s.px_max; ++px) {
            const int64_t cx = px * kSubpixelScale + kSubpixelScale / 2;
            if (edgeFunction(s, 0, cx, cy) + bias[0] <= 0)
                continue;
            if (edgeFunction(s, 1, cx, cy) + bias[1] <= 0)
                continue;
            if (edgeFunction(s, 2, cx, cy) + bias[2] <= 0)
                continue;
            if (visit(uint32_t(px), uint32_t(py), depthAt(s, px, py, offset)))
                return true;
        }
    }
    return false;
}

// Floor of a / b for b > 0 (C++ division truncates towards zero).
inline int64_t floorDiv(int64_t a, int64_t b) {
    const int64_t q = a / b;
    return q - ((a % b != 0) && (a < 0));
}

template <class Visit> bool forEachBandPixel(const TriangleSetup& s, Visit&& visit) {
    const std::array<int64_t, 3>& margin = s.margin;
    const int edges = s.flat ? 1 : 3;
    constexpr int64_t half = kSubpixelScale / 2;
    for (int64_t py = s.py_min; py <= s.py_max; ++py) {
        const int64_t cy = py * kSubpixelScale + half;
        for (int e = 0; e < edges; ++e) {
            // E_e(px) = base + px * step over the row; the band is |E_e| <= m.
            const int64_t m = margin[e];
            const int j = (e + 1) % 3;
            const int64_t dx = s.x[j] - s.x[e], dy = s.y[j] - s.y[e];
            const int64_t step = -dy * kSubpixelScale;
            const int64_t base = dx * (cy - s.y[e]) - dy * (half - s.x[e]);
            int64_t first = s.px_min, last = s.px_max;
            if (step == 0) {
                if (base < -m || base > m)
                    continue;
            } else {
                // px with -m <= base + px step <= m.
                const int64_t lo = step > 0 ? -m - base : base - m;
                const int64_t hi = step > 0 ? m - base : base + m;
                const int64_t magnitude = step > 0 ? step : -step;
                first = std::max(first, -floorDiv(-lo, magnitude)); // ceil(lo / |step|)
                last = std::min(last, floorDiv(hi, magnitude));
            }
            for (int64_t px = first; px <= last; ++px) {
                const int64_t cx = px * kSubpixelScale + half;
                bool take = true;
                for (int i = 0; take && i < edges; ++i) {
                    const int64_t value = edgeFunction(s, i, cx, cy);
                    // Certainly outside another edge; or in an earlier edge's band, which
                    // visited it already.
                    take = !s.flat ? value >= -margin[i] && (i >= e || value > margin[i]) : true;
                }
                if (take && visit(uint32_t(px), uint32_t(py), depthAt(s, px, py)))
                    return true;
            }
        }
    }
    return false;
}

/// Clips a clip-space triangle, fans the polygon out from its first vertex as (p0, p_i, p_i+1)
/// and calls walk(setup) for each fan triangle that set up (setupTriangle with errors). Returns
/// true as soon as walk does.
template <class Walk>
bool forEachFanTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                        uint32_t width, uint32_t height, Walk&& walk,
                        const ScreenErrors& errors = {}) {
    std::array<ClipVertex, kMaxPolygonVertices> polygon;
    const int count = clipTriangle(a, b, c, polygon);
    if (count < 3)
        return false;
    std::array<ScreenVertex, kMaxPolygonVertices> screen;
    for (int i = 0; i < count; ++i)
        screen[i] = toScreen(polygon[i], width, height);
    TriangleSetup setup;
    for (int i = 1; i + 1 < count; ++i) {
        if (setupTriangle(screen[0], screen[i], screen[i + 1], width, height, errors, setup) &&
            walk(setup))
            return true;
    }
    return false;
}

/// Rasterizes one clip-space triangle into a width x height viewport, visit(px, py, depth) per
/// covered pixel centre (see walkTriangle), the plane's own depths. Returns true when visit
/// stopped the walk.
template <class Visit>
bool rasterizeTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                       uint32_t width, uint32_t height, Visit&& visit) {
    return forEachFanTriangle(a, b, c, width, height,
                              [&](const TriangleSetup& s) { return walkTriangle(s, visit); });
}

/// rasterizeTriangle for an oracle's draw or query under the blending rule (a negative
/// tolerance): each fan triangle's depths moved by exactFragmentOffset of its snap slack.
template <class Visit>
bool rasterizeTriangleBlending(bool draw, float tolerance, const ClipVertex& a, const ClipVertex& b,
                               const ClipVertex& c, uint32_t width, uint32_t height,
                               Visit&& visit) {
    return forEachFanTriangle(a, b, c, width, height, [&](const TriangleSetup& s) {
        return walkTriangle(s, visit, exactFragmentOffset(s.spread, draw, tolerance));
    });
}

/// The exact rule's fragments of one clip-space triangle: visit(px, py, depth, error) for every
/// centre certainly inside a fan triangle, and for every band pixel (forEachBandPixel) where
/// covered(px, py) holds (the exact model's decision for the original triangle); depth is the
/// fan triangle's depthAt, error its bound (TriangleSetup::error). A centre may be visited more
/// than once (by fan triangles sharing an edge). Returns true as soon as visit does.
template <class Covered, class Visit>
bool rasterizeTriangleExact(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                            uint32_t width, uint32_t height, const ScreenErrors& errors,
                            Covered&& covered, Visit&& visit) {
    return forEachFanTriangle(
        a, b, c, width, height,
        [&](const TriangleSetup& s) {
            const auto certain = [&](uint32_t px, uint32_t py, float depth) {
                return visit(px, py, depth, s.error);
            };
            if (walkTriangle(s, certain, -0.0, Coverage::certain))
                return true;
            return forEachBandPixel(s, [&](uint32_t px, uint32_t py, float depth) {
                return covered(px, py) && visit(px, py, depth, s.error);
            });
        },
        errors);
}

} // namespace vissort::detail
