#pragma once
// The OpenGL occlusion oracle: Vis-sort's comparisons (Govindaraju, Henson, Lin, Manocha, I3D 2005,
// section 4) as hardware occlusion queries, on any OpenGL 4.5 core driver through a headless EGL
// context (gl_context.h): Mesa's llvmpipe on a machine without a GPU, a GPU's driver where there
// is one.
//
// Conventions, the CPU rasterizer's (cpu_oracle.h) wherever OpenGL lets them be:
//  - one vertex buffer per scene holding the world-space corners (x, y and z each a float array,
//    as TrianglePositions stores them), uploaded by every bind, so a dynamic scene updates it
//    every frame; the vertex shader applies projection * view (computed in double, rounded to
//    float), and the driver interpolates depth in float. Measured on llvmpipe against the CPU
//    rasterizer (which works in double): the same covered pixels, depths within kDepthTolerance
//    but for a few pixels in ten thousand on steep triangles (up to 6 tolerances), where a
//    transform in double changed nothing: the difference is the driver's interpolation;
//  - glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE): window depth is the d of camera.h, clipping is
//    0 <= z <= w as the CPU's near and far planes, and row 0 is the top of the image; pixel
//    centres at (x + 0.5, y + 0.5); coverage and sub-pixel snapping are the driver's (Mesa and
//    the GPU vendors snap to 1/256 pixel, as the CPU rasterizer does);
//  - a depth-only framebuffer, GL_DEPTH_COMPONENT32F, colour writes off; cleared to 1.0, the
//    farthest depth a clipped fragment can have (the CPU clears to +infinity: the two differ only
//    for a fragment exactly on an orthographic far plane);
//  - draw: depth test LESS, writes on. Query: depth test GREATER, writes off, the fragment moved
//    nearer by the tolerance t (depthTolerance(), kDepthTolerance unless set) in the vertex
//    shader (z -= t * w), so it passes when d - t > stored, the CPU's d > stored + t up to float
//    rounding;
//  - the snap slack of cpu_oracle.h's rules 6 and 7 as glPolygonOffset(factor, 0), factor =
//    2^-GL_SUBPIXEL_BITS: the driver moves a fragment by factor times the largest depth slope,
//    the CPU's max(|ddx|, |ddy|) 2^-8 with 8 bits: for a tolerance >= 0 draws move farther and
//    queries nearer, so touching and coplanar faces never count as behind each other; for a
//    negative one the other way. Enabled only inside the oracle's calls (the renderer shares the
//    context and draws without it).
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
