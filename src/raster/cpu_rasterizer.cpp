// This work is based on: Juan Pineda. A Parallel Algorithm for Polygon Rasterization. 1988
// (edge functions); and the top-left fill rule of Direct3D 10 / OpenGL rasterization.

#include "raster/cpu_rasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

std::array<int64_t, 3> edgeMargins(const int64_t dx[3], const int64_t dy[3],
                                   const ScreenErrors& errors) {
    // The corners relative to the first: 0, u0, u0 + u1; their box's width plus height.
    const int64_t xs[3] = {0, dx[0], dx[0] + dx[1]}, ys[3] = {0, dy[0], dy[0] + dy[1]};
    const int64_t width = std::max({xs[0], xs[1], xs[2]}) - std::min({xs[0], xs[1], xs[2]});
    const int64_t height = std::max({ys[0], ys[1], ys[2]}) - std::min({ys[0], ys[1], ys[2]});
    const double p = errors.position_px * double(kSubpixelScale);
    const int64_t reach_units = width + height + 4 * rangeGrowth(errors);
    std::array<int64_t, 3> margins;
    if (p <= 0x1p-10) {
        // The bound below in integers, for a position error of at most 2^-10 units (every
        // honest scene): e (|u| + 4 e) <= |u| / 2 + |u| / 1024 + 1.01, 2 e (reach + 2 e) <=
        // reach + reach / 512 + 1.01 and 4 e^2 <= 1.01, with e = 1/2 + p.
        for (int i = 0; i < 3; ++i) {
            const int64_t edge = std::abs(dx[i]) + std::abs(dy[i]);
            margins[i] = (edge >> 1) + (edge >> 10) + reach_units + (reach_units >> 9) + 8;
        }
        return margins;
    }
    const double e = 0.5 + p;
    const double reach = double(reach_units);
    for (int i = 0; i < 3; ++i) {
        const double edge = double(std::abs(dx[i]) + std::abs(dy[i]));
        const double bound =
            e * (edge + 4 * e) + 2 * e * (reach + 2 * e) + 4 * e * e + 1; // +1: rounding
        // Absurd errors saturate: every centre then a band pixel, decided exactly.
        margins[i] = bound < 0x1p60 ? int64_t(std::ceil(bound)) : int64_t(1) << 60;
    }
    return margins;
}

int64_t rangeGrowthOf(double position_units) {
    const double units = std::ceil(position_units) + 1;
    return units < double(kMaxSnapped) ? int64_t(units) : kMaxSnapped;
}

int screenCoverage(const std::array<double, 3>& ux, const std::array<double, 3>& uy, uint32_t px,
                   uint32_t py, const ScreenErrors& errors) {
    const double cx = double(px) + 0.5, cy = double(py) + 0.5;
    const double width = std::max({ux[0], ux[1], ux[2]}) - std::min({ux[0], ux[1], ux[2]});
    const double height = std::max({uy[0], uy[1], uy[2]}) - std::min({uy[0], uy[1], uy[2]});
    // The closed triangle holds the centre iff its three edge values are all >= 0 or all <= 0,
    // whichever way the corners turn: those of a sliver may turn the other way than its snapped
    // corners, which the set-up oriented.
    bool positive = false, negative = false, unsure = false;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const double dx = ux[j] - ux[i], dy = uy[j] - uy[i];
        const double a = dx * (cy - uy[i]), b = dy * (cx - ux[i]);
        const double value = a - b;
        // Moving each corner and the centre by the position error p changes the value by at
        // most 2 p (|dx| + |dy|) + 2 p (|cx - x_i| + |cy - y_i|) + 8 p^2; the centre lies within
        // the box grown by a pixel, or the value is far from 0 anyway. Rounding: a few units in
        // the last place of |a| + |b|, taken at 2^-48.
        const double p = errors.position_px;
        const double bound = 2 * p * (std::abs(dx) + std::abs(dy) + width + height + 4) +
                             8 * p * p + 0x1p-48 * (std::abs(a) + std::abs(b)) + 1e-300;
        if (value > bound)
            positive = true;
        else if (value < -bound)
            negative = true;
        else
            unsure = true; // this edge cannot tell (NaN too)
    }
    if (positive && negative)
        return -1; // strictly on both sides of two edges: not covered
    return unsure ? 0 : 1;
}

double fragmentError(const ScreenVertex v[3], double ddx, double ddy, double extent,
                     const ScreenErrors& errors) {
    const double e1x = v[1].x - v[0].x, e1y = v[1].y - v[0].y, e1d = v[1].d - v[0].d;
    const double e2x = v[2].x - v[0].x, e2y = v[2].y - v[0].y, e2d = v[2].d - v[0].d;
    const double det = std::abs(e1x * e2y - e2x * e1y);
    if (!(det > 0) || !std::isfinite(ddx) || !std::isfinite(ddy) || !std::isfinite(v[0].d))
        return std::numeric_limits<double>::infinity();
    // How much the slopes can move under rounding: the magnitudes of their numerators, and the
    // determinant's condition, over |det|.
    const double condition = (std::abs(e1x * e2y) + std::abs(e2x * e1y)) / det;
    const double slopes = std::abs(ddx) + std::abs(ddy);
    const double numerators =
        (std::abs(e1d * e2y) + std::abs(e2d * e1y) + std::abs(e2d * e1x) + std::abs(e1d * e2x)) /
        det;
    const double reach = extent + 2; // |cx - x0| and |cy - y0| over the bounds, in pixels
    const double error = 0x1p-40 * (std::abs(v[0].d) + reach * (numerators + slopes * condition)) +
                         errors.depth + 2 * errors.position_px * slopes + 0x1p-24;
    return std::isfinite(error) ? error : std::numeric_limits<double>::infinity();
}

float decisionBand(double error, double stored_error) {
    // Rounded up to float, plus 2^-22: a float sum stored +- B then errs by at most half a unit
    // of a value below 4 (2^-23), which the extra 2^-22 more than covers.
    const double band = (error + stored_error) * (1 + 0x1p-20) + 0x1p-22;
    return band < 1e30 ? float(band) * (1 + 0x1p-20f) : std::numeric_limits<float>::infinity();
}

ScreenErrors screenErrorsOf(const Matrix4& clip, const ViewProjection& view,
                            PositionsView positions, std::span<const PrimitiveRange> primitives) {
    // The largest finite coordinate magnitude (non-finite corners are never drawn).
    float largest = 0;
    for (const PrimitiveRange& range : primitives) {
        const std::size_t first = 3 * std::size_t(range.first_triangle);
        const std::size_t end = first + 3 * std::size_t(range.triangle_count);
        for (const std::span<const float> axis : {positions.x, positions.y, positions.z})
            for (std::size_t i = first; i < end; ++i) {
                const float a = std::abs(axis[i]);
                largest = a <= 3.0e38f && a > largest ? a : largest;
            }
    }
    const double extent = double(largest) + length(view.eye_position) + 1.0;
    // The largest row sum of |clip|: each clip coordinate's rounding is a few units in the last
    // place of that times the coordinates.
    double norm = 0;
    for (int r = 0; r < 4; ++r)
        norm = std::max(norm, std::abs(clip[r]) + std::abs(clip[4 + r]) + std::abs(clip[8 + r]) +
                                  std::abs(clip[12 + r]));
    // The divide by w magnifies it: w is at least near in perspective (after clipping at z = 0,
    // the near plane), 1 in an orthographic view. Positions also carry the guard band's |x/w| <=
    // 32 times w's error, and the rays' own rounding (their origin's size for an orthographic
    // view), which the eye's distance in `extent` bounds.
    const double least_w = view.projection == Projection::perspective ? view.near : 1.0;
    const double magnification = norm * extent / least_w;
    ScreenErrors errors;
    errors.position_px =
        0x1p-44 * magnification * double(std::max(view.width, view.height)) * (1 + kGuardBand);
    errors.depth = 0x1p-44 * magnification;
    if (!std::isfinite(errors.position_px) || !std::isfinite(errors.depth))
        errors = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return errors;
}

namespace {

bool setupImpl(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, uint32_t width,
               uint32_t height, const ScreenErrors& errors, TriangleSetup& s) {
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
    s.flat = doubled_area == 0;
    if (doubled_area < 0) {
        // Both windings are drawn: reorder so that the interior is where edge functions are > 0.
        std::swap(v[1], v[2]);
        std::swap(s.x[1], s.x[2]);
        std::swap(s.y[1], s.y[2]);
    }
    if (s.flat) {
        // No snapped area: edge 0 the longest, whose line the exact model's centres lie near.
        int longest = 0;
        int64_t best = -1;
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            const int64_t length = std::abs(s.x[j] - s.x[i]) + std::abs(s.y[j] - s.y[i]);
            if (length > best) {
                best = length;
                longest = i;
            }
        }
        std::rotate(v.begin(), v.begin() + longest, v.end());
        std::rotate(s.x.begin(), s.x.begin() + longest, s.x.end());
        std::rotate(s.y.begin(), s.y.begin() + longest, s.y.end());
    }
    for (int i = 0; i < 3; ++i) {
        s.ux[i] = v[i].x;
        s.uy[i] = v[i].y;
    }
    int64_t dx[3], dy[3];
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        dx[i] = s.x[j] - s.x[i];
        dy[i] = s.y[j] - s.y[i];
        s.bias[i] = topLeftBias(dx[i], dy[i]);
    }
    s.margin = edgeMargins(dx, dy, errors);

    // Pixel centres sit at 256 px + 128 in 24.8 fixed point. The range holds every centre the
    // unsnapped triangle can cover: the snapped box grown by the half unit snapping moves a
    // corner, and the screen error, both rounded up.
    const int64_t half = kSubpixelScale / 2;
    const int64_t grow = rangeGrowth(errors);
    const int64_t min_x = std::min({s.x[0], s.x[1], s.x[2]}) - grow;
    const int64_t max_x = std::max({s.x[0], s.x[1], s.x[2]}) + grow;
    const int64_t min_y = std::min({s.y[0], s.y[1], s.y[2]}) - grow;
    const int64_t max_y = std::max({s.y[0], s.y[1], s.y[2]}) + grow;
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
    const double extent = double(std::max(s.px_max - s.px_min, s.py_max - s.py_min) + 1);
    if (det == 0 || !std::isfinite(slack)) {
        // Snapping gave area to a triangle that had none (edge-on), or the plane is too steep
        // to evaluate: the middle of the vertex depths everywhere, slack half their range, and
        // every exact comparison left to the exact model.
        const double d_min = std::min({v[0].d, v[1].d, v[2].d});
        const double d_max = std::max({v[0].d, v[1].d, v[2].d});
        s.d0 = 0.5 * d_min + 0.5 * d_max;
        s.ddx = s.ddy = 0;
        s.spread = 0.5 * d_max - 0.5 * d_min;
        s.error = std::numeric_limits<double>::infinity();
        return true;
    }
    s.d0 = v[0].d;
    s.ddx = ddx;
    s.ddy = ddy;
    s.spread = slack;
    s.error = fragmentError(v.data(), ddx, ddy, extent, errors);
    return true;
}

} // namespace

bool setupTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                   uint32_t width, uint32_t height, const ScreenErrors& errors,
                   TriangleSetup& setup) {
    return setupImpl(a, b, c, width, height, errors, setup);
}

} // namespace vissort::detail
