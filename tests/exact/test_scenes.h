#pragma once
// Small scenes and an independent brute-force ray caster for the exact-oracle tests. The caster
// is a plain double-precision Moller-Trumbore loop over every triangle, with depths from
// ViewProjection::depthOf: it shares no code with the Embree caster under test.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::test {

inline void addTriangle(TrianglePositions& positions, Vec3 a, Vec3 b, Vec3 c) {
    for (const Vec3& v : {a, b, c}) {
        positions.x.push_back(float(v.x));
        positions.y.push_back(float(v.y));
        positions.z.push_back(float(v.z));
    }
}

/// The square [-h, h]^2 at height z, as the triangles (a, b, c) and (a, c, d) sharing the
/// diagonal x = y.
inline void addQuad(TrianglePositions& positions, double h, double z) {
    addTriangle(positions, {-h, -h, z}, {h, -h, z}, {h, h, z});
    addTriangle(positions, {-h, -h, z}, {h, h, z}, {-h, h, z});
}

inline PrimitiveRange range(uint32_t first, uint32_t count) {
    return {first, count};
}

/// Triangles that never intersect: each lies in its own slab of z, the slabs in random order.
inline TrianglePositions randomLayeredSoup(uint32_t triangle_count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<uint32_t> layer(triangle_count);
    for (uint32_t i = 0; i < triangle_count; ++i)
        layer[i] = i;
    std::shuffle(layer.begin(), layer.end(), rng);
    const double slab = 2.0 / triangle_count;
    TrianglePositions positions;
    for (uint32_t i = 0; i < triangle_count; ++i) {
        const double cx = -0.7 + 1.4 * unit(rng), cy = -0.7 + 1.4 * unit(rng);
        const double size = 0.8 + 1.0 * unit(rng);
        Vec3 corners[3];
        for (Vec3& v : corners) {
            v = {cx + size * (unit(rng) - 0.5), cy + size * (unit(rng) - 0.5),
                 -1.0 + slab * (layer[i] + 0.1 + 0.7 * unit(rng))};
        }
        addTriangle(positions, corners[0], corners[1], corners[2]);
    }
    return positions;
}

struct BruteHit {
    uint32_t triangle;
    double depth;
    bool robust; // barycentrics > 1e-6 and the 0.01 px square around the centre covered
};

// Barycentric coordinates (u, v, 1 - u - v) and distance of a ray's hit with a triangle's plane;
// false when the ray is parallel to it.
inline bool barycentricHit(const TrianglePositions& positions, uint32_t t, const Vec3& o,
                           const Vec3& d, double& u, double& v, double& dist) {
    const Vec3 a = positions.corner(3 * t), b = positions.corner(3 * t + 1),
               c = positions.corner(3 * t + 2);
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = cross(d, e2);
    const double det = dot(e1, p);
    if (det == 0 || !std::isfinite(det))
        return false;
    const Vec3 s = o - a;
    u = dot(s, p) / det;
    const Vec3 q = cross(s, e1);
    v = dot(d, q) / det;
    dist = dot(e2, q) / det;
    return true;
}

/// All hits (edges included, 0 <= d <= 1) of each pixel's ray, in triangle order. A hit is
/// robust when its barycentrics exceed 1e-6 and the rays 0.01 px away diagonally hit it too.
inline std::vector<std::vector<BruteHit>> bruteForceHits(const TrianglePositions& positions,
                                                         const ViewProjection& view) {
    std::vector<std::vector<BruteHit>> pixels(std::size_t(view.width) * view.height);
    for (uint32_t py = 0; py < view.height; ++py) {
        for (uint32_t px = 0; px < view.width; ++px) {
            Vec3 o, d;
            view.pixelRay(px + 0.5, py + 0.5, o, d);
            for (uint32_t t = 0; t < positions.triangleCount(); ++t) {
                double u, v, dist;
                if (!barycentricHit(positions, t, o, d, u, v, dist))
                    continue;
                const double w = 1 - u - v;
                if (u < 0 || v < 0 || w < 0 || dist < 0)
                    continue;
                const double depth =
                    view.depthOf({o.x + dist * d.x, o.y + dist * d.y, o.z + dist * d.z});
                if (depth < 0 || depth > 1)
                    continue;
                bool robust = u > 1e-6 && v > 1e-6 && w > 1e-6;
                for (double dx : {-0.01, 0.01})
                    for (double dy : {-0.01, 0.01}) {
                        Vec3 o2, d2;
                        view.pixelRay(px + 0.5 + dx, py + 0.5 + dy, o2, d2);
                        double u2, v2, dist2;
                        robust = robust && barycentricHit(positions, t, o2, d2, u2, v2, dist2) &&
                                 u2 > 0 && v2 > 0 && 1 - u2 - v2 > 0;
                    }
                pixels[std::size_t(py) * view.width + px].push_back({t, depth, robust});
            }
        }
    }
    return pixels;
}

inline ViewProjection perspectiveView(const TrianglePositions& positions, Vec3 eye, uint32_t width,
                                      uint32_t height) {
    CameraSpec camera;
    camera.eye = eye;
    camera.target = {0, 0, 0};
    return frameCamera(camera, positions.bounds(), width, height);
}

inline ViewProjection orthographicView(const TrianglePositions& positions, Vec3 direction,
                                       uint32_t width, uint32_t height) {
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.ortho_direction = direction;
    return frameCamera(camera, positions.bounds(), width, height);
}

} // namespace vissort::test
