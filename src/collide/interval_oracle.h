#pragma once
// A conservative occlusion oracle for collision culling along an orthographic direction, with
// no rasterizer: each box (of a triangle, or of a group of them) covers every pixel its projected
// rectangle touches, with its whole depth range. Coverage and depths only grow, so "behind" answers
// only grow: a triangle that touches another is always behind it and it behind the triangle
// (docs/collision.md). Sub-pixel triangles (a detailed mesh in a coarse view) cost a handful of
// pixel operations each; large ones are coarse but still conservative. Each primitive's pixels hold
// the nearest and farthest depth of its triangles there, computed once per bind, so a draw or a
// query costs the primitive's pixels, not its triangles. Internal.

#include <cstdint>
#include <span>
#include <vector>

#include "collide/triangle_boxes.h"
#include "vissort/geometry.h" // Vec3
#include "vissort/occlusion_oracle.h"

namespace vissort::detail {

class IntervalOracle final : public OcclusionOracle {
public:
    /// Binds primitive i to the boxes boxes[starts[i] .. starts[i + 1]) (each holding some of
    /// its triangles: triangle boxes, or nodes of a tree over them), seen along direction
    /// (finite, non-zero) in a width x height image framing the box frame (which should hold
    /// them; parts outside it are clamped to the border pixels, still conservatively). Along an
    /// axis a box's own bounds are its rectangle and depths, exactly.
    void bind(std::span<const Box3f> boxes, std::span<const uint32_t> starts, const Box3f& frame,
              const Vec3& direction, uint32_t width, uint32_t height);

    uint32_t primitiveCount() const override { return uint32_t(footprints_.size()); }
    void clear() override;
    /// The stored depth becomes the nearest of itself and the primitive's nearest depth.
    void draw(uint32_t primitive) override;
    /// True when the primitive's farthest depth reaches the stored depth at some pixel
    /// (closed: equal depths, touching surfaces, count as behind).
    bool anyBehind(uint32_t primitive) override;

private:
    // A primitive's pixels: a rectangle of the image and, per pixel, the nearest and farthest
    // depth of its triangles there (+inf and -inf where none covers it).
    struct Footprint {
        uint32_t x0 = 0, y0 = 0, width = 0, height = 0;
        std::size_t first = 0; // into near_ and far_
    };
    uint32_t width_ = 0, height_ = 0;
    std::vector<Footprint> footprints_;
    std::vector<float> near_, far_;
    std::vector<float> stored_; // the depth buffer, +inf when clear
    // Per box of the primitive being bound: its pixel rectangle and depth range.
    struct Splat {
        uint32_t x0, y0, x1, y1;
        float near, far;
    };
    std::vector<Splat> splats_;
};

} // namespace vissort::detail
