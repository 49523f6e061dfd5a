#pragma once
// Small models whose faces touch or coincide, as architecture and CAD models are full of (boxes
// sharing a face, walls standing on a slab, faces lying on faces), a true cycle for contrast, and
// grazing views of them in both projections. Shared by the oracles' touching-face tests.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::test {

struct Model {
    TrianglePositions positions;
    std::vector<PrimitiveRange> objects;
};

inline void addTriangle(TrianglePositions& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    for (const Vec3& v : {a, b, c}) {
        p.x.push_back(float(v.x));
        p.y.push_back(float(v.y));
        p.z.push_back(float(v.z));
    }
}

// A closed axis-aligned box as one object: 12 triangles, two per face.
inline void addBox(Model& m, const Vec3& lo, const Vec3& hi) {
    const uint32_t first = uint32_t(m.positions.triangleCount());
    const auto corner = [&](int i) {
        return Vec3{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
    };
    const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        addTriangle(m.positions, corner(f[0]), corner(f[1]), corner(f[2]));
        addTriangle(m.positions, corner(f[0]), corner(f[2]), corner(f[3]));
    }
    m.objects.push_back({first, 12});
}

// A quad in the plane y = height, as one object of two triangles.
inline void addFloorQuad(Model& m, double x0, double z0, double x1, double z1, double height) {
    const uint32_t first = uint32_t(m.positions.triangleCount());
    addTriangle(m.positions, {x0, height, z0}, {x1, height, z0}, {x1, height, z1});
    addTriangle(m.positions, {x0, height, z0}, {x1, height, z1}, {x0, height, z1});
    m.objects.push_back({first, 2});
}

// Nine boxes in a 3 x 3 grid, neighbours sharing whole faces (3DS/test1.3ds of assimp's models).
inline Model boxGrid() {
    Model m;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            addBox(m, {i - 1.5, 0, k - 1.5}, {i - 0.5, 1 + 0.25 * ((i + k) % 2), k - 0.5});
    return m;
}

// A slab with four walls standing on it, touching at the corners, and a roof plate lying on
// the walls: every contact a face on a face.
inline Model house() {
    Model m;
    addBox(m, {-2, -0.2, -2}, {2, 0, 2});        // slab
    addBox(m, {-2, 0, -2}, {2, 1.5, -1.8});      // back wall
    addBox(m, {-2, 0, 1.8}, {2, 1.5, 2});        // front wall
    addBox(m, {-2, 0, -1.8}, {-1.8, 1.5, 1.8});  // left wall
    addBox(m, {1.8, 0, -1.8}, {2, 1.5, 1.8});    // right wall
    addBox(m, {-2, 1.5, -2}, {2, 1.6, 2});       // roof plate
    addBox(m, {-0.5, 0, -0.5}, {0.5, 0.8, 0.5}); // a table on the floor
    return m;
}

// Quads lying in one plane and overlapping each other: coplanar faces of different objects.
inline Model coplanarQuads() {
    Model m;
    addFloorQuad(m, -1, -1, 0.5, 0.5, 0);
    addFloorQuad(m, -0.5, -0.5, 1, 1, 0);
    addFloorQuad(m, -0.2, -1, 0.3, 1, 0);
    addBox(m, {-0.3, 0, -0.3}, {0.3, 0.4, 0.3}); // standing on them
    return m;
}

// A stick of square section 2w x h whose bottom rises from height y0 at p to y1 at q (points in
// the plane y = 0), lengthened by e past both ends: one object of 12 triangles.
inline void addRisingStick(Model& m, const Vec3& p, const Vec3& q, double y0, double y1) {
    const double w = 0.06, h = 0.1, e = 0.35;
    const Vec3 along = q - p;
    const double length = std::sqrt(along.x * along.x + along.z * along.z);
    const Vec3 u{along.x / length, 0, along.z / length}, n{-u.z, 0, u.x};
    const auto corner = [&](int i) {
        const double t = i & 1 ? length + e : -e, side = i & 2 ? w : -w;
        const double y = y0 + (y1 - y0) * t / length + (i & 4 ? h : 0);
        return Vec3{p.x + u.x * t + n.x * side, y, p.z + u.z * t + n.z * side};
    };
    const uint32_t first = uint32_t(m.positions.triangleCount());
    const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        addTriangle(m.positions, corner(f[0]), corner(f[1]), corner(f[2]));
        addTriangle(m.positions, corner(f[0]), corner(f[2]), corner(f[3]));
    }
    m.objects.push_back({first, 12});
}

// Three sticks around a triangle, each rising along its length: where one ends (high) it lies
// over the next one's start (low), so each occludes the next from above: a true cycle, with
// gaps everywhere. The ordering must still report it.
inline Model stickRing() {
    Model m;
    const Vec3 a{-1, 0, -0.6}, b{1, 0, -0.6}, c{0, 0, 1.1};
    addRisingStick(m, a, b, 0, 0.6);
    addRisingStick(m, b, c, 0, 0.6);
    addRisingStick(m, c, a, 0, 0.6);
    return m;
}

struct View {
    std::string name;
    CameraSpec camera;
};

inline std::vector<View> grazingViews() {
    std::vector<View> out;
    for (const Vec3& d :
         {Vec3{-0.3, -0.5, -1}, Vec3{0.2, -0.12, -1}, Vec3{-1, -0.05, 0.3}, Vec3{0.01, -1, 0.02}}) {
        CameraSpec ortho;
        ortho.projection = Projection::orthographic;
        ortho.ortho_direction = d;
        out.push_back({"ortho(" + std::to_string(d.x) + "," + std::to_string(d.y) + "," +
                           std::to_string(d.z) + ")",
                       ortho});
    }
    for (const Vec3& eye : {Vec3{3.5, 0.4, 4.5}, Vec3{-4, 1.2, 0.7}, Vec3{0.3, 6, 0.2}}) {
        CameraSpec persp;
        persp.eye = eye;
        persp.target = {0, 0.3, 0};
        out.push_back({"eye(" + std::to_string(eye.x) + "," + std::to_string(eye.y) + "," +
                           std::to_string(eye.z) + ")",
                       persp});
    }
    return out;
}

} // namespace vissort::test
