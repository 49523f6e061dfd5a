#pragma once
// Independent references for the rasterizer tests: exact integer point-in-triangle on snapped
// coordinates, and double-precision ray casting. Written from the definitions in
// cpu_reference_oracle.h, sharing no code with src/raster.

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "vissort/camera.h"

namespace vissort::test {

/// Screen position in 24.8 fixed point of a clip-space point (cpu_reference_oracle.h, rule 4).
inline std::array<int64_t, 2> snappedScreen(const std::array<double, 4>& clip, uint32_t width,
                                            uint32_t height) {
    const double sx = (clip[0] / clip[3] + 1.0) * 0.5 * double(width);
    const double sy = (1.0 - clip[1] / clip[3]) * 0.5 * double(height);
    return {std::llround(sx * 256.0), std::llround(sy * 256.0)};
}

inline int sign(int64_t v) {
    return (v > 0) - (v < 0);
}

/// Whether the snapped triangle covers the centre of pixel (px, py), by the top-left rule stated
/// geometrically: a centre on an edge is covered when stepping from it by +x (for a sloped or
/// vertical edge) or by +y (for a horizontal edge, y down) enters the triangle.
inline bool referenceCovers(const std::array<std::array<int64_t, 2>, 3>& v, int64_t px,
                            int64_t py) {
    const int64_t cx = px * 256 + 128, cy = py * 256 + 128;
    for (int i = 0; i < 3; ++i) {
        const auto& a = v[i];
        const auto& b = v[(i + 1) % 3];
        const auto& c = v[(i + 2) % 3];
        const int64_t dx = b[0] - a[0], dy = b[1] - a[1];
        const auto side = [&](int64_t x, int64_t y) { return dx * (y - a[1]) - dy * (x - a[0]); };
        const int inside_sign = sign(side(c[0], c[1]));
        if (inside_sign == 0)
            return false; // degenerate: no area
        const int s = sign(side(cx, cy));
        if (s == inside_sign)
            continue;
        if (s != 0)
            return false;
        // On the edge's line: the side a step of +x (or +y if horizontal) leads to.
        const int step_sign = dy != 0 ? sign(-dy) : sign(dx);
        if (step_sign != inside_sign)
            return false;
    }
    return true;
}

/// Moller-Trumbore ray/triangle intersection in double: the distance t > 0, if any.
inline std::optional<double> rayTriangle(const Vec3& origin, const Vec3& dir, const Vec3& p0,
                                         const Vec3& p1, const Vec3& p2) {
    const auto sub = [](const Vec3& a, const Vec3& b) {
        return Vec3{a.x - b.x, a.y - b.y, a.z - b.z};
    };
    const auto cross = [](const Vec3& a, const Vec3& b) {
        return Vec3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    };
    const auto dot = [](const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    const Vec3 e1 = sub(p1, p0), e2 = sub(p2, p0);
    const Vec3 p = cross(dir, e2);
    const double det = dot(e1, p);
    if (det == 0)
        return std::nullopt;
    const double inv = 1.0 / det;
    const Vec3 s = sub(origin, p0);
    const double u = dot(s, p) * inv;
    if (u < 0 || u > 1)
        return std::nullopt;
    const Vec3 q = cross(s, e1);
    const double v = dot(dir, q) * inv;
    if (v < 0 || u + v > 1)
        return std::nullopt;
    const double t = dot(e2, q) * inv;
    if (!(t > 0))
        return std::nullopt;
    return t;
}

/// Depth d of the world point where the ray through (sx, sy) (in pixels) meets the triangle and
/// the view volume (0 <= d <= 1), if it does.
inline std::optional<double> castDepth(const ViewProjection& vp, double sx, double sy,
                                       const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    Vec3 origin, dir;
    vp.pixelRay(sx, sy, origin, dir);
    const std::optional<double> t = rayTriangle(origin, dir, p0, p1, p2);
    if (!t)
        return std::nullopt;
    const double d =
        vp.depthOf({origin.x + *t * dir.x, origin.y + *t * dir.y, origin.z + *t * dir.z});
    if (!(d >= 0 && d <= 1))
        return std::nullopt;
    return d;
}

/// Ray-cast coverage of pixel (px, py), or nullopt when the answer changes within margin pixels
/// of the centre (tested at the centre, the 4 corners and 4 edge midpoints of that square): the
/// rasterizer's snapping moves vertices by up to 1/512 pixel per axis, so edges are only known
/// to within sqrt(2)/512 < 3e-3 pixel.
inline std::optional<bool> castCoverage(const ViewProjection& vp, uint32_t px, uint32_t py,
                                        const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                        double margin = 4e-3) {
    const double cx = px + 0.5, cy = py + 0.5;
    const bool centre = castDepth(vp, cx, cy, p0, p1, p2).has_value();
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (castDepth(vp, cx + dx * margin, cy + dy * margin, p0, p1, p2).has_value() != centre)
                return std::nullopt;
    return centre;
}

} // namespace vissort::test
