#include "harnesses/oracle_workloads.h"

#include <algorithm>
#include <random>

namespace vissort {
namespace {

// [0, 1) from 53 random bits: the same numbers from every standard library.
double unitRandom(std::mt19937_64& rng) {
    return double(rng() >> 11) * 0x1.0p-53;
}

void addTriangle(TrianglePositions& p, std::size_t t, const Vec3 (&corners)[3]) {
    for (int c = 0; c < 3; ++c) {
        p.x[t * 3 + c] = float(corners[c].x);
        p.y[t * 3 + c] = float(corners[c].y);
        p.z[t * 3 + c] = float(corners[c].z);
    }
}

} // namespace

ScreenTriangleWorkload makeRightTriangleWorkload(uint32_t count, double leg_px, uint32_t width,
                                                 uint32_t height, uint64_t seed) {
    ScreenTriangleWorkload w;
    w.positions.resize(std::size_t(count) + 2);
    std::mt19937_64 rng(seed);
    const double span_x = std::max(0.0, width - leg_px), span_y = std::max(0.0, height - leg_px);
    for (uint32_t i = 0; i < count; ++i) {
        const double x = unitRandom(rng) * span_x, y = unitRandom(rng) * span_y;
        // Depth falls with the id, in (0.05, 0.95): id order is back to front.
        const double d = 0.95 - 0.9 * (double(i) + 0.5) / count;
        const Vec3 corners[3] = {{x, y, d}, {x + leg_px, y, d}, {x, y + leg_px, d}};
        addTriangle(w.positions, i, corners);
        w.primitives.push_back({i, 1});
    }
    const double W = width, H = height, far = 0.99;
    addTriangle(w.positions, count, {{0, 0, far}, {W, 0, far}, {W, H, far}});
    addTriangle(w.positions, count + 1, {{0, 0, far}, {W, H, far}, {0, H, far}});
    w.background = count;
    w.primitives.push_back({count, 2});

    // Orthographic, looking along +z from z = 0, image x = world x and image row = world y:
    // eye space is (x - W/2, H/2 - y, -z), so the depth d = (z - near) / (far - near) = z.
    ViewProjection& v = w.view;
    v.projection = Projection::orthographic;
    v.width = width;
    v.height = height;
    v.view = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, -W / 2, H / 2, 0, 1};
    v.projection_matrix = {2.0 / W, 0, 0, 0, 0, 2.0 / H, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
    v.near = 0;
    v.far = 1;
    v.eye_position = {W / 2, H / 2, 0};
    v.forward = {0, 0, 1};
    return w;
}

} // namespace vissort
