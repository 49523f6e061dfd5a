#pragma once
// The reference depth rasterizer behind CpuOracle: clip, snap, cover, interpolate depth. Plain and
// exact rather than fast; a faster rasterizer must reproduce its coverage and depths bit for bit,
// so every rule is fixed here (the full list is in include/vissort/cpu_oracle.h).
//
// Number formats: clip and screen coordinates are double; snapped screen coordinates are 24.8
// fixed point (kSubpixelBits) in int64_t; edge functions are exact int64_t products.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "raster/homogeneous_clip.h"

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

/// Conservative mode grows each pixel square by this many sub-pixel units on every side: more
/// than the half unit that snapping moves a vertex, so a square the unsnapped triangle touches
/// is always walked.
inline constexpr int64_t kConservativeMargin = 1;

/// Column-major 4x4 matrix: element (row r, column c) at 4 c + r.
using Matrix4 = std::array<double, 16>;

/// Rule 1 (cpu_oracle.h): projection * view, summed in this order, once per bind.
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
    // Depth plane d(sx, sy) = d0 + ddx (sx - x0) + ddy (sy - y0), in double.
    double x0 = 0, y0 = 0, d0 = 0, ddx = 0, ddy = 0;
    // Inclusive pixel range whose centres may be covered (conservative mode: whose squares may
    // be touched), clamped to the viewport.
    int64_t px_min = 0, px_max = -1, py_min = 0, py_max = -1;
    // Conservative mode: half the range of depths over a pixel square about the plane's value at
    // its centre. Exact mode: the snap slack (snapSlack), how far the plane's value at a covered
    // centre may be from the depth of the nearest point of the unsnapped triangle.
    double spread = 0;
};

/// Exact mode's snap slack of a depth plane with slopes ddx and ddy (rule 6, cpu_oracle.h).
/// Snapping moves each vertex by at most half a sub-pixel unit per axis, so the snapped triangle
/// lies within the unsnapped one grown by that square: a covered centre is at most 2^-9 pixels
/// per axis from a point of the unsnapped triangle, where the plane's value differs by at most
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

/// Screen mapping of a clip-space point: sx = (x / w + 1) * 0.5 * width,
/// sy = (1 - y / w) * 0.5 * height, d = z / w.
ScreenVertex toScreen(const ClipVertex& v, uint32_t width, uint32_t height);

/// Round to nearest (halves away from zero) in 24.8 fixed point: llround(v * 256). |v * 256|
/// must be at most kMaxSnapped (setupTriangle checks before snapping).
int64_t snapToFixed(double v);

/// Snaps, orients and sets up one screen triangle. Returns false when it can cover no pixel
/// centre: zero snapped area, a non-finite or out-of-range coordinate, or off-screen bounds.
bool setupTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                   uint32_t width, uint32_t height, TriangleSetup& setup);

/// setupTriangle for conservative mode (cpu_oracle.h): the same snapping and orientation; the
/// pixel range is every square the snapped box grown by kConservativeMargin touches; the depth
/// plane and its spread bound the triangle's depths over each square (a flat range of the vertex
/// depths where there is no plane, or no snapped area: then every corner is the first, so every
/// edge function is 0). Returns false only for out-of-range coordinates or off-screen bounds.
bool setupConservative(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                       uint32_t width, uint32_t height, TriangleSetup& setup);

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

/// Calls visit(px, py, depth) for every pixel whose centre the set-up triangle covers, rows top
/// to bottom, left to right, depth being depthAt(s, px, py, offset). Stops, returning true, as
/// soon as visit returns true.
template <class Visit>
bool walkTriangle(const TriangleSetup& s, Visit&& visit, double offset = -0.0) {
    for (int64_t py = s.py_min; py <= s.py_max; ++py) {
        const int64_t cy = py * kSubpixelScale + kSubpixelScale / 2;
        for (int64_t px = s.px_min; px <= s.px_max; ++px) {
            const int64_t cx = px * kSubpixelScale + kSubpixelScale / 2;
            if (edgeFunction(s, 0, cx, cy) + s.bias[0] <= 0)
                continue;
            if (edgeFunction(s, 1, cx, cy) + s.bias[1] <= 0)
                continue;
            if (edgeFunction(s, 2, cx, cy) + s.bias[2] <= 0)
                continue;
            if (visit(uint32_t(px), uint32_t(py), depthAt(s, px, py, offset)))
                return true;
        }
    }
    return false;
}

/// Conservative walk (cpu_oracle.h): calls visit(px, py, nearest, farthest) for every pixel
/// whose square the set-up triangle may touch, with the plane's nearest and farthest depth over
/// that square. Stops, returning true, as soon as visit returns true.
template <class Visit> bool walkTriangleConservative(const TriangleSetup& s, Visit&& visit) {
    // An edge function's largest value over a pixel square grown by the margin.
    std::array<int64_t, 3> reach;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        reach[i] = (std::abs(s.x[j] - s.x[i]) + std::abs(s.y[j] - s.y[i])) *
                   (kSubpixelScale / 2 + kConservativeMargin);
    }
    for (int64_t py = s.py_min; py <= s.py_max; ++py) {
        const int64_t cy = py * kSubpixelScale + kSubpixelScale / 2;
        for (int64_t px = s.px_min; px <= s.px_max; ++px) {
            const int64_t cx = px * kSubpixelScale + kSubpixelScale / 2;
            if (edgeFunction(s, 0, cx, cy) + reach[0] < 0)
                continue;
            if (edgeFunction(s, 1, cx, cy) + reach[1] < 0)
                continue;
            if (edgeFunction(s, 2, cx, cy) + reach[2] < 0)
                continue;
            const double centre =
                s.d0 + s.ddx * ((double(px) + 0.5) - s.x0) + s.ddy * ((double(py) + 0.5) - s.y0);
            if (visit(uint32_t(px), uint32_t(py), float(centre - s.spread),
                      float(centre + s.spread)))
                return true;
        }
    }
    return false;
}

/// Clips a clip-space triangle, fans the polygon out from its first vertex as (p0, p_i, p_i+1)
/// and calls walk(setup) for each fan triangle that set up (setupTriangle, or setupConservative
/// when conservative). Returns true as soon as walk does.
template <class Walk>
bool forEachFanTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                        uint32_t width, uint32_t height, bool conservative, Walk&& walk) {
    std::array<ClipVertex, kMaxPolygonVertices> polygon;
    const int count = clipTriangle(a, b, c, polygon);
    if (count < 3)
        return false;
    std::array<ScreenVertex, kMaxPolygonVertices> screen;
    for (int i = 0; i < count; ++i)
        screen[i] = toScreen(polygon[i], width, height);
    TriangleSetup setup;
    for (int i = 1; i + 1 < count; ++i) {
        const bool ok =
            conservative
                ? setupConservative(screen[0], screen[i], screen[i + 1], width, height, setup)
                : setupTriangle(screen[0], screen[i], screen[i + 1], width, height, setup);
        if (ok && walk(setup))
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
    return forEachFanTriangle(a, b, c, width, height, false,
                              [&](const TriangleSetup& s) { return walkTriangle(s, visit); });
}

/// rasterizeTriangle for an oracle's draw or query: each fan triangle's depths moved by
/// exactFragmentOffset of its snap slack.
template <class Visit>
bool rasterizeTriangleFor(bool draw, float tolerance, const ClipVertex& a, const ClipVertex& b,
                          const ClipVertex& c, uint32_t width, uint32_t height, Visit&& visit) {
    return forEachFanTriangle(a, b, c, width, height, false, [&](const TriangleSetup& s) {
        return walkTriangle(s, visit, exactFragmentOffset(s.spread, draw, tolerance));
    });
}

/// rasterizeTriangle in conservative mode: visit(px, py, nearest, farthest).
template <class Visit>
bool rasterizeTriangleConservative(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                                   uint32_t width, uint32_t height, Visit&& visit) {
    return forEachFanTriangle(a, b, c, width, height, true, [&](const TriangleSetup& s) {
        return walkTriangleConservative(s, visit);
    });
}

} // namespace vissort::detail
