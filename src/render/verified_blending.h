#pragma once
// Blending in a visibility order, checked on every pixel against the GPU's own depths, so that
// the image is exact whatever the order's source got wrong. While the order's runs blend, a depth
// buffer of their own keeps each pixel's nearest blended depth (test LESS, writes on); a fragment
// that is not nearer than it came after something in front of it, and the stencil marks its
// pixel. Groups (the primitives the order cannot separate) are composited per pixel from fragment
// lists at their place, checked the same way. Marked pixels are composited again at the end:
// the background, the opaque surfaces drawn again, and every transparent fragment from lists.
//
// With Vis-sort's order marked pixels are rare: a pixel centre within a rounding error of an
// edge, which the oracle's rasterizer and the GPU's put on different sides, or depths that tie
// exactly (docs/transparency.md).

#include <cstddef>
#include <cstdint>
#include <functional>

#include "gl/gl_objects.h"
#include "render/draw_sequence.h"
#include "render/fragment_lists.h"
#include "render/render_target.h"
#include "vissort/geometry.h"

namespace vissort::detail {

class VerifiedBlending {
public:
    VerifiedBlending();

    struct Result {
        uint64_t fragments = 0;       // fragments blended from lists (groups and repairs)
        uint32_t extra_passes = 0;    // geometry passes beyond the one over the sequence
        uint64_t repaired_pixels = 0; // pixels composited again
    };

    /// Composites the sequence's transparent triangles onto the target's colour (which holds the
    /// opaque surfaces, their depth in the target's depth). `draw(program, first, count)` draws
    /// sequence triangles [first, first + count) with program bound and its view set; programs
    /// are the shading vertex shader's. lists serves the groups and the repair. Without repair,
    /// marked pixels keep the order's blend (an unchecked order, its groups still per pixel).
    /// `draw_opaque(program)` draws the opaque triangles (none unless has_opaque) the same way:
    /// the repair draws the background over marked pixels, then the opaque surfaces again.
    Result composite(
        const RenderTarget& target, FragmentLists& lists, const DrawSequence& sequence, bool repair,
        const Rgba& background, bool has_opaque,
        const std::function<void(GLuint program)>& draw_opaque,
        const std::function<void(GLuint program, std::size_t first, std::size_t count)>& draw);

private:
    void resize(const RenderTarget& target);

    GlProgram blend_program_, opaque_blend_program_; // without and with the opaque test
    GlProgram opaque_program_, background_program_, scan_program_;
    GlQuery query_;
    GlVertexArray empty_vertex_array_;
    GlTexture nearest_;         // depth and stencil of the check
    GlFramebuffer framebuffer_; // the target's colour with nearest_
    GlBuffer marked_;           // count and bounds of the marked pixels
    uint32_t width_ = 0, height_ = 0;
    GLuint target_colour_ = 0;
};

} // namespace vissort::detail
