#pragma once
// The reference occlusion oracle: answers from ray casting rather than rasterization, so that
// every other backend can be checked against it.
//
// bind() casts one ray through the centre of every pixel and keeps ALL its hits (Embree finds
// them; depth and barycentrics are recomputed in double precision), then regroups them by
// primitive as fragments (pixel, nearest depth, farthest depth) over the primitive's triangles
// hit at that pixel. Hits on triangle edges count, so shared edges never leave holes.
// The depth buffer holds doubles, cleared to +infinity:
//   draw(p):      buffer[pixel] = min(buffer[pixel], nearest + o_n)    for each fragment of p;
//   anyBehind(p): some fragment of p has farthest - o_f > buffer[pixel] + t,
// t the depth tolerance (kDepthTolerance unless set) and o = s when t >= 0, -s when negative,
// s the snap slack of the triangle hit (nearest or farthest): max(|dd/dx|, |dd/dy|) / 256, its
// plane's depth slopes per pixel. The rasterizing oracles move depths by that much where
// snapping may extrapolate a plane (cpu_oracle.h, rules 6 and 7); the same bound here makes the
// answers agree: touching and coplanar faces are never behind each other, surfaces apart by more
// than t + s + s always are. Answers are exact to double precision at pixel centres up to that
// bound and independent of any rasterizer.
// After bind(), draw, anyBehind and clear allocate nothing.

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

    /// One primitive's coverage of one pixel: the nearest and farthest of its hits there, and
    /// the snap slack of the triangles hit there.
    struct Fragment {
        uint32_t pixel; // py * width + px
        double nearest, farthest;
        double nearest_slack, farthest_slack;
    };
    /// The fragments of a primitive, in ascending pixel order. primitive < primitiveCount().
    std::span<const Fragment> fragments(uint32_t primitive) const;

private:
    unsigned thread_count_;
    uint32_t primitive_count_ = 0;
    std::vector<uint64_t> fragment_offsets_; // primitive p owns [offsets[p], offsets[p + 1])
    std::vector<Fragment> fragments_;
    std::vector<double> depth_buffer_; // one per pixel, +infinity when clear
};

} // namespace vissort
