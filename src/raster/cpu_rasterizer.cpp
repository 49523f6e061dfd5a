// This work is based on: Juan Pineda. A Parallel Algorithm for Polygon Rasterization. 1988
// (edge functions); and the top-left fill rule of Direct3D 10 / OpenGL rasterization.

#include "raster/cpu_rasterizer.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vissort::detail {
namespace {

// Floor and ceiling of v / 2^kSubpixelBits; >> on a negative int64_t is arithmetic since C++20.
int64_t floorToPixels(int64_t v) {
    return v >> kSubpixelBits;
}
int64_t ceilToPixels(int64_t v) {
    return -((-v) >> kSubpixelBits);
}

// With the vertices ordered for a positive doubled area and y pointing down, the interior lies
// where every edge function is positive. A top edge is horizontal with the interior below it:
// it runs towards +x (dy == 0, dx > 0). A left edge has the interior on its right: it runs
// upwards on screen (dy < 0). Pixel centres exactly on those edges belong to the triangle.
int64_t topLeftBias(int64_t dx, int64_t dy) {
    return (dy == 0 && dx > 0) || dy < 0 ? 1 : 0;
}

} // namespace

ScreenVertex toScreen(const ClipVertex& v, uint32_t width, uint32_t height) {
    return {(v.x / v.w + 1.0) * 0.5 * double(width), (1.0 - v.y / v.w) * 0.5 * double(height),
            v.z / v.w};
}

// std::llround (half away from zero), without the library call that cost 1.6% of a bunnies
// frame: callers keep |v| * kSubpixelScale within kMaxSnapped, far inside int64_t, so the
// truncation is exact and so is the fraction left (a double minus its integer part).
int64_t snapToFixed(double v) {
    const double scaled = v * double(kSubpixelScale);
    int64_t whole = int64_t(scaled);
    const double fraction = scaled - double(whole);
    whole += int64_t(fraction >= 0.5) - int64_t(fraction <= -0.5);
    return whole;
}

namespace {

bool setupImpl(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, uint32_t width,
               uint32_t height, TriangleSetup& s) {
    std::array<ScreenVertex, 3> v{a, b, c};
    const double limit = double(kMaxSnapped) / double(kSubpixelScale);
    for (const ScreenVertex& p : v)
        if (!(std::abs(p.x) <= limit && std::abs(p.y) <= limit))
            return false; // also NaN
    for (int i = 0; i < 3; ++i) {
        s.x[i] = snapToFixed(v[i].x);
        s.y[i] = snapToFixed(v[i].y);
    }
    const int64_t doubled_area =
        (s.x[1] - s.x[0]) * (s.y[2] - s.y[0]) - (s.y[1] - s.y[0]) * (s.x[2] - s.x[0]);
    if (doubled_area == 0)
        return false;
    if (doubled_area < 0) {
        // Both windings are drawn: reorder so that the interior is where edge functions are > 0.
        std::swap(v[1], v[2]);
        std::swap(s.x[1], s.x[2]);
        std::swap(s.y[1], s.y[2]);
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        s.bias[i] = topLeftBias(s.x[j] - s.x[i], s.y[j] - s.y[i]);
    }

    // Pixel centres sit at 256 px + 128 in 24.8 fixed point.
    const int64_t half = kSubpixelScale / 2;
    const int64_t min_x = std::min({s.x[0], s.x[1], s.x[2]});
    const int64_t max_x = std::max({s.x[0], s.x[1], s.x[2]});
    const int64_t min_y = std::min({s.y[0], s.y[1], s.y[2]});
    const int64_t max_y = std::max({s.y[0], s.y[1], s.y[2]});
    s.px_min = std::max<int64_t>(ceilToPixels(min_x - half), 0);
    s.px_max = std::min<int64_t>(floorToPixels(max_x - half), int64_t(width) - 1);
    s.py_min = std::max<int64_t>(ceilToPixels(min_y - half), 0);
    s.py_max = std::min<int64_t>(floorToPixels(max_y - half), int64_t(height) - 1);
    if (s.px_min > s.px_max || s.py_min > s.py_max)
        return false;

    // The depth plane goes through the unsnapped vertices: d is affine in screen space for both
    // projections (camera.h), so this is exact up to rounding.
    const double e1x = v[1].x - v[0].x, e1y = v[1].y - v[0].y, e1d = v[1].d - v[0].d;
    const double e2x = v[2].x - v[0].x, e2y = v[2].y - v[0].y, e2d = v[2].d - v[0].d;
    const double det = e1x * e2y - e2x * e1y;
    const double ddx = det != 0 ? (e1d * e2y - e2d * e1y) / det : 0.0;
    const double ddy = det != 0 ? (e2d * e1x - e1d * e2x) / det : 0.0;
    const double slack = snapSlack(ddx, ddy);
    s.x0 = v[0].x;
    s.y0 = v[0].y;
    if (det == 0 || !std::isfinite(slack)) {
        // Snapping gave area to a triangle that had none (edge-on), or the plane is too steep
        // to evaluate: the middle of the vertex depths everywhere, slack half their range.
        const double d_min = std::min({v[0].d, v[1].d, v[2].d});
        const double d_max = std::max({v[0].d, v[1].d, v[2].d});
        s.d0 = 0.5 * d_min + 0.5 * d_max;
        s.ddx = s.ddy = 0;
        s.spread = 0.5 * d_max - 0.5 * d_min;
        return true;
    }
    s.d0 = v[0].d;
    s.ddx = ddx;
    s.ddy = ddy;
    s.spread = slack;
    return true;
}

} // namespace

bool setupTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                   uint32_t width, uint32_t height, TriangleSetup& setup) {
    return setupImpl(a, b, c, width, height, setup);
}

// Conservative set-up (cpu_oracle.h, conservative mode). What it must guarantee: every pixel
// whose square the unsnapped triangle touches is walked, with a depth range holding the
// triangle's depths there. Snapping moves each vertex by at most half a sub-pixel unit per axis,
// so the unsnapped triangle lies within that of the snapped one: squares grown by
// kConservativeMargin sub-pixel units catch it. The depth plane goes through the unsnapped
// vertices, so its range over the square holds the triangle's depths there. Where the plane is
// undefined (no unsnapped area: an edge-on triangle) or the snapped triangle has no area, the
// range is that of the vertex depths, which bound the triangle's depths (d is affine on it).
bool setupConservative(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                       uint32_t width, uint32_t height, TriangleSetup& s) {
    std::array<ScreenVertex, 3> v{a, b, c};
    const double limit = double(kMaxSnapped) / double(kSubpixelScale);
    for (const ScreenVertex& p : v)
        if (!(std::abs(p.x) <= limit && std::abs(p.y) <= limit && std::isfinite(p.d)))
            return false; // also NaN
    for (int i = 0; i < 3; ++i) {
        s.x[i] = snapToFixed(v[i].x);
        s.y[i] = snapToFixed(v[i].y);
    }
    constexpr int64_t m = kConservativeMargin;
    const int64_t min_x = std::min({s.x[0], s.x[1], s.x[2]}) - m;
    const int64_t max_x = std::max({s.x[0], s.x[1], s.x[2]}) + m;
    const int64_t min_y = std::min({s.y[0], s.y[1], s.y[2]}) - m;
    const int64_t max_y = std::max({s.y[0], s.y[1], s.y[2]}) + m;
    // Pixels whose square [p, p + 1] meets the grown box (touching counts).
    s.px_min = std::max<int64_t>(ceilToPixels(min_x) - 1, 0);
    s.px_max = std::min<int64_t>(floorToPixels(max_x), int64_t(width) - 1);
    s.py_min = std::max<int64_t>(ceilToPixels(min_y) - 1, 0);
    s.py_max = std::min<int64_t>(floorToPixels(max_y), int64_t(height) - 1);
    if (s.px_min > s.px_max || s.py_min > s.py_max)
        return false; // off screen
    s.bias = {0, 0, 0};

    const double d_min = std::min({v[0].d, v[1].d, v[2].d});
    const double d_max = std::max({v[0].d, v[1].d, v[2].d});
    const auto flat = [&] {
        s.x0 = v[0].x;
        s.y0 = v[0].y;
        s.d0 = 0.5 * d_min + 0.5 * d_max;
        s.ddx = s.ddy = 0;
        s.spread = 0.5 * d_max - 0.5 * d_min;
    };
    const int64_t doubled_area =
        (s.x[1] - s.x[0]) * (s.y[2] - s.y[0]) - (s.y[1] - s.y[0]) * (s.x[2] - s.x[0]);
    if (doubled_area == 0) {
        // A segment or a point on screen: every square of its grown box, vertex depth range.
        // Equal corners make every edge function 0, so the box alone decides coverage.
        s.x = {s.x[0], s.x[0], s.x[0]};
        s.y = {s.y[0], s.y[0], s.y[0]};
        flat();
        return true;
    }
    if (doubled_area < 0) {
        std::swap(v[1], v[2]);
        std::swap(s.x[1], s.x[2]);
        std::swap(s.y[1], s.y[2]);
    }
    const double e1x = v[1].x - v[0].x, e1y = v[1].y - v[0].y, e1d = v[1].d - v[0].d;
    const double e2x = v[2].x - v[0].x, e2y = v[2].y - v[0].y, e2d = v[2].d - v[0].d;
    const double det = e1x * e2y - e2x * e1y;
    const double ddx = det != 0 ? (e1d * e2y - e2d * e1y) / det : 0.0;
    const double ddy = det != 0 ? (e2d * e1x - e1d * e2x) / det : 0.0;
    const double spread = std::abs(ddx) * 0.5 + std::abs(ddy) * 0.5;
    if (det == 0 || !std::isfinite(spread)) {
        flat();
        return true;
    }
    s.x0 = v[0].x;
    s.y0 = v[0].y;
    s.d0 = v[0].d;
    s.ddx = ddx;
    s.ddy = ddy;
    s.spread = spread;
    return true;
}

} // namespace vissort::detail
