// ConvexFacingOracle (convex_facing_oracle.h).

#include "volume/convex_facing_oracle.h"

#include <algorithm>
#include <cmath>

namespace vissort::detail {
namespace {

// A facing closer to edge-on than this (the cosine between the face's normal and the direction
// to the eye) is not called: the float corners the rasterizer sees could turn it either way.
constexpr double kEdgeOnCosine = 1e-7;

// Whether a corner reaches the near plane, where the rasterizer clips (perspective: its eye
// distance w, which is negative behind the eye, within a margin of the plane's; orthographic:
// its depth).
bool atNearPlane(const Vec3& corner, const ViewProjection& view) {
    if (view.projection == Projection::perspective)
        return !(view.toClip(corner)[3] > view.near * (1 + 1e-6));
    return !(view.depthOf(corner) > 1e-9);
}

enum class Facing { front, back, both };

Facing facingOf(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& inside,
                const ViewProjection& view) {
    Vec3 normal = cross(b - a, c - a);
    if (dot(normal, inside - a) > 0)
        normal = normal * -1.0; // outwards
    const Vec3 to_eye =
        view.projection == Projection::perspective ? view.eye_position - a : view.forward * -1.0;
    const double along = dot(normal, to_eye);
    const double scale = length(normal) * length(to_eye);
    if (!(std::abs(along) > kEdgeOnCosine * scale))
        return Facing::both;
    return along > 0 ? Facing::front : Facing::back;
}

void append(TrianglePositions& to, PositionsView from, std::size_t triangle) {
    for (std::size_t k = 3 * triangle; k < 3 * triangle + 3; ++k) {
        to.x.push_back(from.x[k]);
        to.y.push_back(from.y[k]);
        to.z.push_back(from.z[k]);
    }
}

} // namespace

void ConvexFacingOracle::bind(PositionsView positions, const ViewProjection& view,
                              std::span<const PrimitiveRange> primitives) {
    count_ = uint32_t(primitives.size());
    split_.x.clear();
    split_.y.clear();
    split_.z.clear();
    ranges_.resize(2 * primitives.size());
    front_faces_ = back_faces_ = 0;
    std::vector<Facing> facing;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        const PrimitiveRange range = primitives[p];
        const std::size_t first = range.first_triangle, end = first + range.triangle_count;
        Vec3 inside{0, 0, 0};
        bool near_plane = range.triangle_count == 0;
        for (std::size_t k = 3 * first; k < 3 * end; ++k) {
            const Vec3 corner = positions.corner(k);
            inside = inside + corner;
            near_plane = near_plane || atNearPlane(corner, view);
        }
        inside = inside * (1.0 / double(3 * std::max<std::size_t>(range.triangle_count, 1)));
        facing.assign(range.triangle_count, Facing::both);
        if (!near_plane)
            for (std::size_t t = first; t < end; ++t)
                facing[t - first] = facingOf(positions.corner(3 * t), positions.corner(3 * t + 1),
                                             positions.corner(3 * t + 2), inside, view);
        for (const Facing wanted : {Facing::front, Facing::back}) {
            PrimitiveRange& out = ranges_[2 * p + (wanted == Facing::back ? 1 : 0)];
            out.first_triangle = uint32_t(split_.triangleCount());
            for (std::size_t t = first; t < end; ++t)
                if (facing[t - first] == wanted || facing[t - first] == Facing::both)
                    append(split_, positions, t);
            out.triangle_count = uint32_t(split_.triangleCount()) - out.first_triangle;
        }
        front_faces_ += ranges_[2 * p].triangle_count;
        back_faces_ += ranges_[2 * p + 1].triangle_count;
    }
    inner_.bind(split_, view, ranges_);
}

} // namespace vissort::detail
