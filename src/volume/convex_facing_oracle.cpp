// ConvexFacingOracle (convex_facing_oracle.h).

#include "volume/convex_facing_oracle.h"

#include <algorithm>
#include <cmath>

namespace vissort::detail {
namespace {

// A facing closer to edge-on than this (the cosine between the face's normal and the direction
// to the eye) is not called: the float corners the rasterizer sees could turn it either way.
constexpr double kEdgeOnCosine = 1e-7;

enum class Facing : uint8_t { front, back, both };

Facing facingOf(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& inside,
                const ViewProjection& view) {
    Vec3 normal = cross(b - a, c - a);
    if (dot(normal, inside - a) > 0)
        normal = normal * -1.0; // outwards
    const Vec3 to_eye =
        view.projection == Projection::perspective ? view.eye_position - a : view.forward * -1.0;
    const double along = dot(normal, to_eye);
    if (!(along * along >
          kEdgeOnCosine * kEdgeOnCosine * dot(normal, normal) * dot(to_eye, to_eye)))
        return Facing::both;
    return along > 0 ? Facing::front : Facing::back;
}

} // namespace

void ConvexFacingOracle::bind(PositionsView positions, const ViewProjection& view,
                              std::span<const PrimitiveRange> primitives) {
    count_ = uint32_t(primitives.size());
    // First each face's facing (and the triangles that makes), then the split itself, sized
    // exactly: it is the largest of the order's buffers.
    std::size_t faces = 0;
    for (const PrimitiveRange& range : primitives)
        faces += range.triangle_count;
    facing_.resize(faces);
    std::size_t used = 0; // triangles the split needs
    // A corner's distance in front of the eye plane, along the view (either projection clips
    // where it falls below the near plane's; negative behind the eye).
    const auto& m = view.view;
    const double near_margin = view.near * (1 + 1e-6);
    std::size_t at = 0; // the first of the primitive's faces in facing_
    for (const PrimitiveRange& range : primitives) {
        const std::size_t first = range.first_triangle, end = first + range.triangle_count;
        Vec3 inside{0, 0, 0};
        bool near_plane = false;
        for (std::size_t k = 3 * first; k < 3 * end; ++k) {
            const Vec3 corner = positions.corner(k);
            inside = inside + corner;
            const double ahead = -(m[2] * corner.x + m[6] * corner.y + m[10] * corner.z + m[14]);
            near_plane = near_plane || !(ahead > near_margin);
        }
        inside = inside * (1.0 / double(3 * std::max<std::size_t>(range.triangle_count, 1)));
        for (std::size_t t = first; t < end; ++t, ++at) {
            const Facing f = near_plane
                                 ? Facing::both
                                 : facingOf(positions.corner(3 * t), positions.corner(3 * t + 1),
                                            positions.corner(3 * t + 2), inside, view);
            facing_[at] = uint8_t(f);
            used += f == Facing::both ? 2 : 1;
        }
    }
    split_.resize(used);
    ranges_.resize(2 * primitives.size());
    front_faces_ = back_faces_ = 0;
    std::size_t written = 0;
    at = 0;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        const PrimitiveRange range = primitives[p];
        const std::size_t first = range.first_triangle, end = first + range.triangle_count;
        for (const Facing wanted : {Facing::front, Facing::back}) {
            PrimitiveRange& out = ranges_[2 * p + (wanted == Facing::back ? 1 : 0)];
            out.first_triangle = uint32_t(written);
            for (std::size_t t = first; t < end; ++t) {
                const Facing f = Facing(facing_[at + (t - first)]);
                if (f != wanted && f != Facing::both)
                    continue;
                std::copy_n(&positions.x[3 * t], 3, &split_.x[3 * written]);
                std::copy_n(&positions.y[3 * t], 3, &split_.y[3 * written]);
                std::copy_n(&positions.z[3 * t], 3, &split_.z[3 * written]);
                ++written;
            }
            out.triangle_count = uint32_t(written) - out.first_triangle;
        }
        at += range.triangle_count;
        front_faces_ += ranges_[2 * p].triangle_count;
        back_faces_ += ranges_[2 * p + 1].triangle_count;
    }
    inner_.bind(split_, view, ranges_);
}

} // namespace vissort::detail
