// The scalar set-up of CpuOracle's fan triangles (fast_setup.h): the reference's clipping,
// snapping and set-up (cpu_rasterizer.h), turned into the edge functions at pixel (0, 0) and
// their steps, the form the tile walks use.

#include "raster/fast_setup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace vissort::detail {

bool edgesFitInt32(const FastSetup& s) {
    bool fit = true;
    for (int e = 0; e < 3; ++e) {
        // Every term is below 2^62: no overflow.
        const int64_t corner = s.edge_at_origin[e] + int64_t(s.px_min) * s.edge_step_x[e] +
                               int64_t(s.py_min) * s.edge_step_y[e];
        const int64_t span_x = int64_t(s.px_max - s.px_min) * s.edge_step_x[e];
        const int64_t span_y = int64_t(s.py_max - s.py_min) * s.edge_step_y[e];
        const int64_t lowest = corner + std::min<int64_t>(span_x, 0) + std::min<int64_t>(span_y, 0);
        // The blending rule's walks add blendingBias (at most margin + 1) to these values.
        const int64_t highest =
            corner + std::max<int64_t>(span_x, 0) + std::max<int64_t>(span_y, 0) + s.margin[e] + 1;
        fit &= lowest >= -int64_t(INT32_MAX) && highest <= int64_t(INT32_MAX);
    }
    return fit;
}

bool mayHaveBand(int64_t start, int64_t along, int64_t cross, int64_t m, int64_t steps) {
    // Where values and products stay below 2^52, doubles compute them exactly: every step's
    // value v, the nearest multiple of cross (rounded with the 2^52 + 2^51 shift, which rounds to
    // nearest) and the remainder, with no dependence between steps (the loop vectorizes).
    const double largest =
        double(std::abs(start)) + double(std::abs(along)) * double(steps) + double(std::abs(cross));
    if (!(largest < 0x1p50))
        return true; // too large to screen: the exact walk decides
    constexpr double kShift = 0x1.8p52;
    const double s = double(start), a = double(along), c = double(cross), inverse = 1.0 / c;
    const double bound = double(m) + 1; // the rounding of the quotient may pick a neighbour
    bool any = false;
    for (int64_t i = 0; i < steps; ++i) {
        const double value = s + double(i) * a;
        const double k = (value * inverse + kShift) - kShift;
        const double remainder = value - k * c;
        // The nearest multiple or its neighbour: either way within a cross step of the least.
        any |= std::abs(remainder) <= bound || std::abs(remainder) >= std::abs(c) - bound;
    }
    return any;
}

int bandAlongEdge(int64_t start, int64_t along, int64_t cross, int64_t m, int64_t from,
                  int64_t last, BandHit* hits, int64_t& next) {
    const int64_t size = cross < 0 ? -cross : cross;
    const int64_t direction = cross > 0 ? 1 : -1;
    const int64_t upper = size - size / 2, lower = -(size / 2);
    // The cross index nearest to where E is 0, from a division in double (pipelined, unlike an
    // integer one: it cost most of the walk), then E there, brought exactly into [lower,
    // upper): the quotient of values below 2^62 is off by far less than a step.
    const double quotient = -double(start) / double(cross);
    int64_t at = int64_t(quotient + (quotient >= 0 ? 0.5 : -0.5));
    int64_t value = start + at * cross;
    while (value >= upper) {
        value -= size;
        at -= direction;
    }
    while (value < lower) {
        value += size;
        at += direction;
    }
    int found = 0;
    for (int64_t i = from; i <= last; ++i) {
        if (value >= -m && value <= m) {
            hits[found++] = {i, at};
            if (found == kMaxBandHits) {
                next = i + 1;
                return found;
            }
        }
        value += along;
        // Back into [lower, upper): at most one wrap (|along| <= size), without branches (a
        // wrap comes at every other step or so: branches mispredicted half the time cost more
        // than the whole step).
        const int64_t over = -int64_t(value >= upper), under = -int64_t(value < lower);
        value += (under & size) - (over & size);
        at += (under & direction) - (over & direction);
    }
    next = last + 1;
    return found;
}

void appendFastSetups(const Matrix4& clip, PositionsView positions, std::size_t t, uint32_t width,
                      uint32_t height, const ScreenErrors& errors, std::vector<FastSetup>& out) {
    std::array<ClipVertex, 3> corners;
    std::array<ClipVertex, kMaxPolygonVertices> polygon;
    std::array<ScreenVertex, kMaxPolygonVertices> screen;
    for (int k = 0; k < 3; ++k) {
        const std::size_t i = 3 * t + std::size_t(k);
        corners[k] = toClipSpace(clip, positions.x[i], positions.y[i], positions.z[i]);
    }
    // Rules 2-4 and the set-up of rules 5-6, by the reference's own functions.
    const int count = clipTriangle(corners[0], corners[1], corners[2], polygon);
    // Whether clipping kept the triangle whole: every corner inside every plane (rule 2).
    const auto inside = [](const ClipVertex& v) {
        return v.w > 0 && v.z >= 0 && v.z <= v.w && std::abs(v.x) <= kGuardBand * v.w &&
               std::abs(v.y) <= kGuardBand * v.w;
    };
    const bool whole = inside(corners[0]) && inside(corners[1]) && inside(corners[2]);
    if (count < 3)
        return;
    for (int i = 0; i < count; ++i)
        screen[i] = toScreen(polygon[i], width, height);
    TriangleSetup ts;
    for (int i = 1; i + 1 < count; ++i) {
        const ScreenVertex& a = screen[0];
        const ScreenVertex& b = screen[i];
        const ScreenVertex& c = screen[i + 1];
        if (!setupTriangle(a, b, c, width, height, errors, ts))
            continue;
        FastSetup s;
        constexpr int64_t half = kSubpixelScale / 2;
        for (int e = 0; e < 3; ++e) {
            const int j = (e + 1) % 3;
            const int64_t dx = ts.x[j] - ts.x[e], dy = ts.y[j] - ts.y[e];
            // The exact rule's: covered when E > margin.
            const int64_t bias = -ts.margin[e];
            // E_e at the centre of pixel (0, 0), (128, 128) in 24.8 fixed point: below 2^61.
            s.edge_at_origin[e] = dx * (half - ts.y[e]) - dy * (half - ts.x[e]) + bias;
            s.edge_step_x[e] = -dy * kSubpixelScale;
            s.edge_step_y[e] = dx * kSubpixelScale;
        }
        s.x0 = ts.x0;
        s.y0 = ts.y0;
        s.d0 = ts.d0;
        s.ddx = ts.ddx;
        s.ddy = ts.ddy;
        s.spread = ts.spread;
        s.error = ts.error;
        for (int k = 0; k < 3; ++k) {
            s.ux[k] = ts.ux[k];
            s.uy[k] = ts.uy[k];
        }
        s.whole = whole;
        s.d_min = std::min({a.d, b.d, c.d});
        s.d_max = std::max({a.d, b.d, c.d});
        for (int e = 0; e < 3; ++e)
            s.margin[e] = ts.margin[e];
        s.flat = ts.flat;
        s.band_walk = 7;
        s.screen_hit_count = 0;
        s.px_min = int32_t(ts.px_min);
        s.px_max = int32_t(ts.px_max);
        s.py_min = int32_t(ts.py_min);
        s.py_max = int32_t(ts.py_max);
        s.narrow = edgesFitInt32(s);
        out.push_back(s);
    }
}

} // namespace vissort::detail
