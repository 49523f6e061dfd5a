#pragma once
// The tests' own picture of a grid, by brute force: every pixel's ray against every tetrahedron
// (the interval where it is inside all four faces' half-spaces, the half-spaces found from each
// face and its opposite corner, not from the grid's orientation), the intervals sorted by depth
// and composited by the law of volume.h written out again here. Nothing of src/volume/ (no
// Embree, no neighbours, no walk): what the ray caster and the rasterizing methods are held to.

#include <algorithm>
#include <cmath>
#include <limits>

#include "vissort/volume.h"

namespace vissort::test {

struct BruteSegment {
    double t_in, t_out;
    uint32_t tet;
};

inline Image bruteForceVolume(const TetGrid& grid, const VolumeSettings& settings,
                              const ViewProjection& view) {
    Bounds bounds;
    for (const Vec3& p : grid.points)
        bounds.add(p);
    const double unit = 2 * bounds.radius();
    double low = grid.scalars[0], high = grid.scalars[0];
    for (double s : grid.scalars) {
        low = std::min(low, s);
        high = std::max(high, s);
    }
    const auto normalized = [&](double s) {
        if (!settings.transfer.normalized)
            return s;
        return high > low ? (s - low) / (high - low) : 0.0;
    };
    const double row[4] = {view.view[2], view.view[6], view.view[10], view.view[14]};
    const auto eye = [&](const Vec3& p) {
        return -(row[0] * p.x + row[1] * p.y + row[2] * p.z + row[3]);
    };
    Image image{view.width, view.height,
                std::vector<float>(std::size_t(view.width) * view.height * 4)};
    std::vector<BruteSegment> segments;
    for (uint32_t py = 0; py < view.height; ++py)
        for (uint32_t px = 0; px < view.width; ++px) {
            Vec3 o, d;
            view.pixelRay(px + 0.5, py + 0.5, o, d);
            double clip_low = 0, clip_high = std::numeric_limits<double>::infinity();
            const double z0 = eye(o), dz = eye(o + d) - z0;
            clip_low = std::max(clip_low, (view.near - z0) / dz);
            if (view.projection == Projection::orthographic)
                clip_high = (view.far - z0) / dz;
            segments.clear();
            for (uint32_t t = 0; t < grid.tets.size(); ++t) {
                double t_in = clip_low, t_out = clip_high;
                for (int skip = 0; skip < 4 && t_in < t_out; ++skip) {
                    Vec3 corner[3];
                    for (int k = 0, m = 0; k < 4; ++k)
                        if (k != skip)
                            corner[m++] = grid.points[grid.tets[t][k]];
                    Vec3 n = cross(corner[1] - corner[0], corner[2] - corner[0]);
                    if (dot(n, grid.points[grid.tets[t][skip]] - corner[0]) < 0)
                        n = -n; // point inwards
                    // Inside where n . (o + t d - corner0) >= 0.
                    const double value = dot(n, o - corner[0]), slope = dot(n, d);
                    if (slope == 0) {
                        if (value < 0)
                            t_out = t_in; // parallel and outside
                    } else if (slope > 0) {
                        t_in = std::max(t_in, -value / slope);
                    } else {
                        t_out = std::min(t_out, -value / slope);
                    }
                }
                if (t_out > t_in)
                    segments.push_back({t_in, t_out, t});
            }
            std::sort(segments.begin(), segments.end(),
                      [](const BruteSegment& a, const BruteSegment& b) { return a.t_in < b.t_in; });
            // Back to front, "over".
            double r = settings.background.r * settings.background.a,
                   g = settings.background.g * settings.background.a,
                   b = settings.background.b * settings.background.a, a = settings.background.a;
            for (auto it = segments.rbegin(); it != segments.rend(); ++it) {
                const Tet& tet = grid.tets[it->tet];
                // The scalar at a point: barycentric coordinates by volumes.
                const auto scalar = [&](const Vec3& p) {
                    const auto volume = [&](const Vec3& a0, const Vec3& a1, const Vec3& a2,
                                            const Vec3& a3) {
                        return dot(cross(a1 - a0, a2 - a0), a3 - a0);
                    };
                    const Vec3 v[4] = {grid.points[tet[0]], grid.points[tet[1]],
                                       grid.points[tet[2]], grid.points[tet[3]]};
                    const double whole = volume(v[0], v[1], v[2], v[3]);
                    double s = 0;
                    for (int k = 0; k < 4; ++k) {
                        Vec3 w[4] = {v[0], v[1], v[2], v[3]};
                        w[k] = p;
                        s += volume(w[0], w[1], w[2], w[3]) / whole * grid.scalars[tet[k]];
                    }
                    return s;
                };
                const double s_mid = 0.5 * (scalar(o + d * it->t_in) + scalar(o + d * it->t_out));
                const TransferPoint tf = settings.transfer.at(normalized(s_mid));
                const double alpha =
                    1 - std::exp(-settings.density * tf.extinction * (it->t_out - it->t_in) / unit);
                r = tf.r * alpha + (1 - alpha) * r;
                g = tf.g * alpha + (1 - alpha) * g;
                b = tf.b * alpha + (1 - alpha) * b;
                a = alpha + (1 - alpha) * a;
            }
            float* out = &image.rgba[(std::size_t(py) * view.width + px) * 4];
            out[0] = float(r);
            out[1] = float(g);
            out[2] = float(b);
            out[3] = float(a);
        }
    return image;
}

} // namespace vissort::test
