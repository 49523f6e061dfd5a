#pragma once
// The OpenGL occlusion oracle: Vis-sort's comparisons (Govindaraju, Henson, Lin, Manocha, I3D 2005,
// section 4) as hardware occlusion queries, on any OpenGL 4.5 core driver through a headless EGL
// context (gl_context.h): Mesa's llvmpipe on a machine without a GPU, a GPU's driver where there
// is one.
//
// Common to every depth tolerance:
//  - one vertex buffer per scene holding the world-space corners (x, y and z each a float array,
//    as TrianglePositions stores them), uploaded by every bind, so a dynamic scene updates it
//    every frame;
//  - glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE): window depth is the d of camera.h and row 0
//    is the top of the image; pixel centres at (x + 0.5, y + 0.5);
//  - a depth-only framebuffer, GL_DEPTH_COMPONENT32F, colour writes off; cleared to 1.0, the
//    farthest depth there is (the CPU clears to +infinity);
//  - draw: depth test LESS, writes on. Query: depth test GREATER, writes off.
//
// Depth tolerance 0 (kDepthTolerance, the default): the exact fragment model (geometry_oracle.h,
// docs/robustness.md), which a driver cannot decide exactly, decided conservatively: every
// "behind" of the model is a "behind" here, and so is what the oracle cannot tell from one: a
// pixel centre within some 1e-13 pixel of an edge, or two fragments whose depths lie within the
// rounding of their computation (about one float step of the depth buffer). Touching and
// coplanar faces meet at exactly equal depths: such ties count as behind both ways here, where
// the exact model counts neither (an order through this oracle has larger cycles on them, never
// an occlusion backwards outside one); so does a primitive queried against its own fragments.
//  - coverage: a geometry shader draws, for each triangle, a polygon covering every pixel
//    centre the model could give it: the triangle with its edges pushed out by a margin (twice
//    what float positions and the driver's sub-pixel snapping can move an edge, at least 1/64
//    pixel), or its bounding box grown by the margin and cut to the viewport (slivers, and
//    triangles reaching far off-screen; for one crossing the near plane, the box of its part
//    beyond half the near distance); nothing for a triangle surely outside the depth range,
//    degenerate by a repeated corner, or with a non-finite corner;
//  - per fragment, in double: the pixel centre's ray as PixelRays computes it, the model's
//    three edge determinants and Q with error bounds (with slack for the driver rounding the
//    ray otherwise than the CPU); the fragment is discarded only where the model certainly has
//    none (an edge certainly against it, or the hit certainly outside the depth range). Its
//    depth d = camera.h's of the hit t = N / Q, bounded on both sides and within the depths of
//    the triangle's corners, is written as gl_FragDepth rounded outwards to float: the lower
//    bound by draws, the upper bound by queries. A query then passes GREATER wherever some drawn
//    fragment is exactly nearer, and where the two bounds overlap.
//
// Any other tolerance t: the approximate float rule of geometry_oracle.h, the GPU's coverage:
//  - clipping to 0 <= z <= w, the CPU's near and far planes; coverage and sub-pixel snapping are
//    the driver's (Mesa and the GPU vendors snap to 1/256 pixel, as the CPU rasterizer does);
//  - the vertex shader applies projection * view (computed in double, rounded to float), and
//    the driver interpolates depth in float; measured on llvmpipe against the CPU rasterizer
//    (which works in double): the same covered pixels, depths within 2^-20 but for a few pixels
//    in ten thousand on steep triangles;
//  - a query's fragment moved nearer by t in the vertex shader (z -= t * w), so it passes when
//    d - t > stored, the CPU's d > stored + t up to float rounding;
//  - the snap slack of cpu_reference_oracle.h's rules 6 and 7 as glPolygonOffset(factor, 0),
//    factor = 2^-GL_SUBPIXEL_BITS: the driver moves a fragment by factor times the largest depth
//    slope: for t > 0 draws move farther and queries nearer, so touching and coplanar faces never
//    count as behind each other; for t < 0 the other way. Enabled only inside the oracle's calls
//    (the renderer shares the context and draws without it).
//
// The passes (occlusion_oracle.h), with no CPU round trip per query:
//  - pass 1 (backToFrontPass): every query is issued (GL_ANY_SAMPLES_PASSED, one query object per
//    element) between the draws it depends on, and all answers are read once at the end; runs of
//    elements that are only drawn go out as one glMultiDrawArrays;
//  - pass 2 (frontToBackPass): an element in M is queried, then drawn under
//    glBeginConditionalRender(its query, GL_QUERY_WAIT): the GPU decides whether it is drawn,
//    the CPU never waits; answers are read at the end;
//  - the group test (queryAgainst): the occluders in one glMultiDrawArrays, then one query per
//    target, answers read at the end;
//  - single draw and anyBehind calls work too (anyBehind waits for its answer).
//
// Layer: vissort::gl (the package's `gl` component; docs/architecture.md).

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "vissort/geometry_oracle.h"
#include "vissort/gl_context.h"

namespace vissort {

/// What the oracle did since bind (or resetStats).
struct GlOracleStats {
    uint64_t draws = 0;      // primitives drawn (those skipped by conditional rendering count)
    uint64_t queries = 0;    // occlusion queries issued
    uint64_t draw_calls = 0; // glDrawArrays and glMultiDrawArrays calls
};

class GlOracle final : public GeometryOracle {
public:
    /// An oracle rendering through context, which it keeps alive. Every call makes the context
    /// current on the calling thread first.
    explicit GlOracle(std::shared_ptr<GlContext> context);
    ~GlOracle() override;
    GlOracle(const GlOracle&) = delete;
    GlOracle& operator=(const GlOracle&) = delete;

    /// See GeometryOracle::bind. Uploads the corners and sizes the framebuffer. Throws
    /// std::runtime_error naming the limit when the view exceeds the driver's largest
    /// framebuffer or the scene its largest draw (2^31 - 1 corners).
    void bind(PositionsView positions, const ViewProjection& view,
              std::span<const PrimitiveRange> primitives) override;

    uint32_t primitiveCount() const override;
    void clear() override;
    void draw(uint32_t primitive) override;
    bool anyBehind(uint32_t primitive) override;
    void backToFrontPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                         std::span<uint8_t> behind) override;
    void frontToBackPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                         std::span<uint8_t> behind) override;
    /// A group's query is one query object over all its members (any sample of any member
    /// passes it), its draws conditional on it in pass 2: batched as the plain passes are.
    void backToFrontGroupPass(std::span<const uint32_t> members, std::span<const uint32_t> first,
                              std::span<const uint8_t> query, std::span<uint8_t> behind) override;
    void frontToBackGroupPass(std::span<const uint32_t> members, std::span<const uint32_t> first,
                              std::span<const uint8_t> query, std::span<uint8_t> behind) override;
    void queryAgainst(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
                      std::span<uint8_t> behind) override;

    /// The depth buffer read back: width * height floats, row-major from the top row.
    std::vector<float> depthBuffer() const;

    const GlContext& context() const;
    const GlOracleStats& stats() const;
    void resetStats();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace vissort
