// The scalar set-up of FastCpuOracle's fan triangles (fast_setup.h): the reference's clipping,
// snapping and set-up (cpu_rasterizer.h), turned into the edge functions at pixel (0, 0) and
// their steps, the form the tile walks use.

#include "raster/fast_setup.h"

#include <algorithm>
#include <array>
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
        const int64_t highest =
            corner + std::max<int64_t>(span_x, 0) + std::max<int64_t>(span_y, 0);
        fit &= lowest >= -int64_t(INT32_MAX) && highest <= int64_t(INT32_MAX);
    }
    return fit;
}

void appendFastSetups(const Matrix4& clip, PositionsView positions, std::size_t t, uint32_t width,
                      uint32_t height, bool conservative, std::vector<FastSetup>& out) {
    std::array<ClipVertex, 3> corners;
    std::array<ClipVertex, kMaxPolygonVertices> polygon;
    std::array<ScreenVertex, kMaxPolygonVertices> screen;
    for (int k = 0; k < 3; ++k) {
        const std::size_t i = 3 * t + std::size_t(k);
        corners[k] = toClipSpace(clip, positions.x[i], positions.y[i], positions.z[i]);
    }
    // Rules 2-4 and the set-up of rules 5-6, by the reference's own functions.
    const int count = clipTriangle(corners[0], corners[1], corners[2], polygon);
    if (count < 3)
        return;
    for (int i = 0; i < count; ++i)
        screen[i] = toScreen(polygon[i], width, height);
    TriangleSetup ts;
    for (int i = 1; i + 1 < count; ++i) {
        const ScreenVertex& a = screen[0];
        const ScreenVertex& b = screen[i];
        const ScreenVertex& c = screen[i + 1];
        const bool set_up = conservative ? setupConservative(a, b, c, width, height, ts)
                                         : setupTriangle(a, b, c, width, height, ts);
        if (!set_up)
            continue;
        FastSetup s;
        constexpr int64_t half = kSubpixelScale / 2;
        for (int e = 0; e < 3; ++e) {
            const int j = (e + 1) % 3;
            const int64_t dx = ts.x[j] - ts.x[e], dy = ts.y[j] - ts.y[e];
            // Conservative: covered when E + reach >= 0, reach = the edge function's rise over
            // half a pixel and the margin on each axis (cpu_oracle.h), i.e. E + reach + 1 > 0.
            // Below 2^39.
            const int64_t bias =
                conservative ? (std::abs(dx) + std::abs(dy)) * (half + kConservativeMargin) + 1
                             : ts.bias[e];
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
        // Conservative: every square the grown box touches, as setupConservative computed.
        s.px_min = int32_t(ts.px_min);
        s.px_max = int32_t(ts.px_max);
        s.py_min = int32_t(ts.py_min);
        s.py_max = int32_t(ts.py_max);
        s.narrow = edgesFitInt32(s);
        out.push_back(s);
    }
}

} // namespace vissort::detail
