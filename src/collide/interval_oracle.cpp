// The conservative interval oracle (interval_oracle.h): the paper's "fattened" primitives for
// collision culling (Govindaraju et al., I3D 2005, section 5.3, after CULLIDE, Graphics
// Hardware 2003), fattened to whole pixel rectangles and whole depth ranges.
//
// Number formats: projected intervals are double, computed from float box bounds; each end is
// within kRoundingBound times the coordinates' magnitude of the exact value (sums of three
// products), so intervals grow by that much before they become pixels (closed squares: a point
// on a border belongs to both neighbours) and depths round outwards to float. Along an axis the
// projection is exact: the box's own bounds.

#include "collide/interval_oracle.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace vissort::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Relative error bound of the projections (sums of six products of floats and unit vector
// components in double), with a wide safety factor (the exact bound is about 8 * 2^-53).
constexpr double kRoundingBound = 0x1p-44;

struct Axes {
    double u[3], v[3], w[3]; // image right, image down, view direction
};

Axes axesAlong(const Vec3& direction) {
    const Vec3 w = direction / length(direction);
    // Any right-handed frame will do; an axis maps to the two other axes exactly.
    const double ax = std::abs(w.x), ay = std::abs(w.y), az = std::abs(w.z);
    const int dominant = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    // u = normalize(helper x w), v = w x u, helper the axis after the dominant one.
    const Vec3 helper = dominant == 0   ? Vec3{0, 1, 0}
                        : dominant == 1 ? Vec3{0, 0, 1}
                                        : Vec3{1, 0, 0};
    const Vec3 u = normalized(cross(helper, w));
    const Vec3 v = cross(w, u);
    return {{u.x, u.y, u.z}, {v.x, v.y, v.z}, {w.x, w.y, w.z}};
}

// The float at or below v, and at or above v.
float floatDown(double v) {
    const float f = float(v);
    return double(f) > v ? std::nextafter(f, -kInfinity) : f;
}
float floatUp(double v) {
    const float f = float(v);
    return double(f) < v ? std::nextafter(f, kInfinity) : f;
}

} // namespace

void IntervalOracle::bind(std::span<const Box3f> boxes, std::span<const uint32_t> starts,
                          const Box3f& frame, const Vec3& direction, uint32_t width,
                          uint32_t height) {
    assert(width >= 1 && height >= 1 && !starts.empty());
    width_ = width;
    height_ = height;
    const Axes axes = axesAlong(direction);
    // Along an axis every unit vector is exactly +-1 or 0, and the projections below are exact.
    const bool along_axis =
        std::count(axes.w, axes.w + 3, 0.0) == 2 && std::count(axes.u, axes.u + 3, 0.0) == 2;
    // A box's interval along unit axis a: centre . a +- sum |a_k| half_k, within the rounding
    // bound of the coordinates' magnitude (nothing along an axis).
    double magnitude = 0;
    for (int k = 0; k < 3; ++k)
        magnitude =
            std::max({magnitude, std::abs(double(frame.min[k])), std::abs(double(frame.max[k]))});
    const auto interval = [&](const double a[3], const Box3f& b, double& low, double& high) {
        if (along_axis) {
            const int k = a[0] != 0 ? 0 : a[1] != 0 ? 1 : 2;
            low = a[k] > 0 ? b.min[k] : -b.max[k];
            high = a[k] > 0 ? b.max[k] : -b.min[k];
            return;
        }
        double centre = 0, reach = 0;
        for (int k = 0; k < 3; ++k) {
            centre += a[k] * (0.5 * double(b.min[k]) + 0.5 * double(b.max[k]));
            reach += std::abs(a[k]) * (0.5 * double(b.max[k]) - 0.5 * double(b.min[k]));
        }
        low = centre - reach;
        high = centre + reach;
    };
    double u_min, u_max, v_min, v_max;
    interval(axes.u, frame, u_min, u_max);
    interval(axes.v, frame, v_min, v_max);
    const double slack = along_axis ? 0.0 : kRoundingBound * 3 * std::max(magnitude, 1e-30);
    const double u_scale = double(width) / std::max(u_max - u_min, 1e-30);
    const double v_scale = double(height) / std::max(v_max - v_min, 1e-30);
    // Pixel index of a projected coordinate, closed squares: a value on a border (within the
    // rounding of the scaling) reaches both pixels. Clamped: what lies outside lands on the rim.
    const auto pixel_low = [](double t, uint32_t size) {
        const double widened = t - std::abs(t) * 0x1p-40 - 0x1p-30;
        return uint32_t(std::clamp(std::floor(widened), 0.0, double(size - 1)));
    };
    const auto pixel_high = [](double t, uint32_t size) {
        const double widened = t + std::abs(t) * 0x1p-40 + 0x1p-30;
        return uint32_t(std::clamp(std::floor(widened), 0.0, double(size - 1)));
    };

    footprints_.resize(starts.size() - 1);
    near_.clear();
    far_.clear();
    for (std::size_t p = 0; p + 1 < starts.size(); ++p) {
        splats_.clear();
        uint32_t fx0 = width, fy0 = height, fx1 = 0, fy1 = 0;
        for (uint32_t i = starts[p]; i < starts[p + 1]; ++i) {
            double lo[3], hi[3];
            interval(axes.u, boxes[i], lo[0], hi[0]);
            interval(axes.v, boxes[i], lo[1], hi[1]);
            interval(axes.w, boxes[i], lo[2], hi[2]);
            Splat s;
            s.x0 = pixel_low((lo[0] - slack - u_min) * u_scale, width);
            s.x1 = pixel_high((hi[0] + slack - u_min) * u_scale, width);
            s.y0 = pixel_low((lo[1] - slack - v_min) * v_scale, height);
            s.y1 = pixel_high((hi[1] + slack - v_min) * v_scale, height);
            s.near = floatDown(lo[2] - slack);
            s.far = floatUp(hi[2] + slack);
            fx0 = std::min(fx0, s.x0);
            fy0 = std::min(fy0, s.y0);
            fx1 = std::max(fx1, s.x1);
            fy1 = std::max(fy1, s.y1);
            splats_.push_back(s);
        }
        Footprint& f = footprints_[p];
        f.first = near_.size();
        if (splats_.empty()) {
            f.width = f.height = 0;
            continue;
        }
        f.x0 = fx0;
        f.y0 = fy0;
        f.width = fx1 - fx0 + 1;
        f.height = fy1 - fy0 + 1;
        near_.resize(f.first + std::size_t(f.width) * f.height, kInfinity);
        far_.resize(f.first + std::size_t(f.width) * f.height, -kInfinity);
        for (const Splat& s : splats_)
            for (uint32_t y = s.y0; y <= s.y1; ++y) {
                const std::size_t row = f.first + std::size_t(y - f.y0) * f.width - f.x0;
                for (uint32_t x = s.x0; x <= s.x1; ++x) {
                    near_[row + x] = std::min(near_[row + x], s.near);
                    far_[row + x] = std::max(far_[row + x], s.far);
                }
            }
    }
    stored_.assign(std::size_t(width) * height, kInfinity);
}

void IntervalOracle::clear() {
    std::fill(stored_.begin(), stored_.end(), kInfinity);
}

void IntervalOracle::draw(uint32_t primitive) {
    const Footprint& f = footprints_[primitive];
    for (uint32_t y = 0; y < f.height; ++y) {
        float* stored = stored_.data() + std::size_t(f.y0 + y) * width_ + f.x0;
        const float* nearest = near_.data() + f.first + std::size_t(y) * f.width;
        for (uint32_t x = 0; x < f.width; ++x)
            stored[x] = std::min(stored[x], nearest[x]);
    }
}

bool IntervalOracle::anyBehind(uint32_t primitive) {
    const Footprint& f = footprints_[primitive];
    for (uint32_t y = 0; y < f.height; ++y) {
        const float* stored = stored_.data() + std::size_t(f.y0 + y) * width_ + f.x0;
        const float* farthest = far_.data() + f.first + std::size_t(y) * f.width;
        bool behind = false;
        for (uint32_t x = 0; x < f.width; ++x)
            behind |= farthest[x] >= stored[x];
        if (behind)
            return true;
    }
    return false;
}

} // namespace vissort::detail
