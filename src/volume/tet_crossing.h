#pragma once
// Where a ray crosses a tetrahedron, and the scalar there: what the ray caster's walk and the
// rasterizing methods' per-pixel segments share, so that both cut a ray into the very same
// segments (the methods differ only in the order they composite them). Internal to src/volume/.

#include <limits>
#include <vector>

#include "geometry/pixel_rays.h"
#include "vissort/camera.h"
#include "vissort/tet_grid.h"

namespace vissort::detail {

/// A tetrahedron's four face planes, each n . p >= offset on the inner side (face i opposite
/// corner i, n unnormalized), and its scalar as a linear function: corner 0's value plus the
/// gradient's dot product with the offset from corner 0.
struct TetPlanes {
    Vec3 normal[4];
    double offset[4];
    Vec3 origin;    // corner 0
    double scalar0; // the scalar there
    Vec3 gradient{0, 0, 0};

    TetPlanes(const TetGrid& grid, const Tet& tet) {
        origin = grid.points[tet[0]];
        scalar0 = grid.scalars.empty() ? 0.0 : grid.scalars[tet[0]];
        for (int f = 0; f < 4; ++f) {
            const Vec3& a = grid.points[tet[kTetFaceCorners[f][0]]];
            normal[f] = cross(grid.points[tet[kTetFaceCorners[f][1]]] - a,
                              grid.points[tet[kTetFaceCorners[f][2]]] - a);
            offset[f] = dot(normal[f], a);
            // Barycentric coordinate f is corner f's height over face f, normalized: its
            // gradient is the face's normal over the corner's height.
            const double corner_height = dot(normal[f], grid.points[tet[f]]) - offset[f];
            const double value = grid.scalars.empty() ? 0.0 : grid.scalars[tet[f]];
            gradient = gradient + normal[f] * (value / corner_height);
        }
    }

    /// The scalar at p (linear in the cell: its corners' values interpolated barycentrically).
    double scalarAt(const Vec3& p) const { return scalar0 + dot(gradient, p - origin); }
};

/// Where the ray o + t d is inside a tetrahedron: [t_in, t_out] (empty when t_in >= t_out),
/// and the face it leaves by (-1 when none: a degenerate ray).
struct Crossing {
    double t_in = -std::numeric_limits<double>::infinity();
    double t_out = std::numeric_limits<double>::infinity();
    int exit_face = -1;
};

/// crossTet from each face's numerator, offset - n . o, and n . d: where the ray meets plane f is
/// numerator / along (callers whose rays share an origin or a direction compute one of the two
/// once, with the same bits).
inline Crossing crossPlanes(const double numerator[4], const double along[4]) {
    Crossing c;
    for (int f = 0; f < 4; ++f) {
        const double at = numerator[f] / along[f]; // meets the plane
        if (along[f] > 0) {
            c.t_in = std::max(c.t_in, at); // entering the face's inner side
        } else if (along[f] < 0 && at < c.t_out) {
            c.t_out = at;
            c.exit_face = f;
        } else if (along[f] == 0 && numerator[f] > 0) {
            c.t_in = std::numeric_limits<double>::infinity(); // parallel to the face, outside it
        }
    }
    return c;
}

inline Crossing crossTet(const TetPlanes& planes, const Vec3& o, const Vec3& d) {
    double numerator[4], along[4];
    for (int f = 0; f < 4; ++f) {
        numerator[f] = planes.offset[f] - dot(planes.normal[f], o);
        along[f] = dot(planes.normal[f], d);
    }
    return crossPlanes(numerator, along);
}

/// The ray through each pixel centre of a view (PixelRays: ViewProjection::pixelRay's very
/// doubles, the view's inverse computed once) and the part of it in view: from the near plane
/// (to the far plane, orthographic). Filled once a frame, its memory kept for the next.
struct PixelRayTable {
    uint32_t width = 0, height = 0;
    std::vector<Vec3> origin, direction;
    std::vector<double> t_low, t_high;

    PixelRayTable() = default;
    explicit PixelRayTable(const ViewProjection& view) { fill(view); }

    void fill(const ViewProjection& view) {
        width = view.width;
        height = view.height;
        const std::size_t n = std::size_t(width) * height;
        origin.resize(n);
        direction.resize(n);
        t_low.resize(n);
        t_high.resize(n);
        const PixelRays rays(view);
        const double row[4] = {view.view[2], view.view[6], view.view[10], view.view[14]};
        const auto eye = [&](const Vec3& p) {
            return -(row[0] * p.x + row[1] * p.y + row[2] * p.z + row[3]);
        };
        for (uint32_t py = 0; py < height; ++py)
            for (uint32_t px = 0; px < width; ++px) {
                const std::size_t i = std::size_t(py) * width + px;
                const PixelRay ray = rays.centre(px, py);
                origin[i] = ray.origin;
                direction[i] = ray.direction;
                const double z0 = eye(origin[i]), dz = eye(origin[i] + direction[i]) - z0;
                t_low[i] = 0;
                t_high[i] = std::numeric_limits<double>::infinity();
                if (dz > 0) {
                    t_low[i] = std::max(0.0, (view.near - z0) / dz);
                    if (view.projection == Projection::orthographic)
                        t_high[i] = (view.far - z0) / dz;
                }
            }
    }
};

} // namespace vissort::detail
