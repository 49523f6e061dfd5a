#pragma once
// The reference occlusion oracle: answers from ray casting rather than rasterization, so that
// every other backend can be checked against it.
//
// bind() casts one ray through the centre of every pixel and keeps ALL its hits, as the exact
// fragment model defines them (docs/robustness.md, "The exact model"): the closed triangles the
// ray meets, edges and corners included, within the depth range, ranked front to back at each
// pixel by exact arithmetic on the float corners (hits at exactly the same depth share a rank).
// It then regroups them by primitive as fragments (pixel, nearest rank, farthest rank). The depth
// buffer holds ranks, cleared to "nothing":
//   draw(p):      buffer[pixel] = min(buffer[pixel], nearest)    for each fragment of p;
//   anyBehind(p): some fragment of p has farthest > buffer[pixel],
// so with the default depth tolerance (0) a fragment is behind exactly when it lies farther than
// something drawn there: touching and coplanar faces never are, nothing else is a tie. Any other
// tolerance t compares depths rounded to double instead: behind when farthest > the nearest
// drawn + t, so that a negative t (the renderer's blending rule, kBlendingDepthTolerance)
// counts near ties both ways. Answers do not depend on any rasterizer.
// After bind(), draw, anyBehind and clear allocate nothing.
//
// Layer: vissort::exact (the package's `exact` component; docs/architecture.md).

#include <cstdint>
#include <span>
#include <vector>

#include "vissort/geometry_oracle.h"

namespace vissort {

class ExactOracle final : public GeometryOracle {
public:
    /// thread_count: threads for the ray casting in bind(); 0 uses the hardware concurrency.
    /// Answers do not depend on it.
    explicit ExactOracle(unsigned thread_count = 0);

    /// Casts the rays (the cost of this oracle) and builds the fragments. Triangles outside every
    /// range are ignored; ranges must lie inside positions and must not overlap.
    /// Keeps no reference to its arguments.
    void bind(PositionsView positions, const ViewProjection& view,
              std::span<const PrimitiveRange> primitives) override;

    uint32_t primitiveCount() const override { return primitive_count_; }
    void clear() override;
    /// primitive must be below primitiveCount().
    void draw(uint32_t primitive) override;
    /// primitive must be below primitiveCount().
    bool anyBehind(uint32_t primitive) override;

    /// One primitive's coverage of one pixel: the exact depth ranks of its nearest and farthest
    /// hits there (0 is the pixel's nearest hit of any triangle; equal ranks are equally deep),
    /// and their depths d, rounded to double.
    struct Fragment {
        uint32_t pixel; // py * width + px
        uint32_t nearest, farthest;
        double nearest_depth, farthest_depth;
    };
    /// The fragments of a primitive, in ascending pixel order. primitive < primitiveCount().
    std::span<const Fragment> fragments(uint32_t primitive) const;

private:
    unsigned thread_count_;
    uint32_t primitive_count_ = 0;
    std::vector<uint64_t> fragment_offsets_; // primitive p owns [offsets[p], offsets[p + 1])
    std::vector<Fragment> fragments_;
    std::vector<uint32_t> rank_buffer_; // one per pixel, kNothing when clear
    std::vector<double> depth_buffer_;  // one per pixel, +infinity when clear
};

} // namespace vissort
