#pragma once
// Blending in a visibility order, checked on every pixel against the GPU's own depths, so that
// the image is exact whatever the order's source got wrong. While the order's runs blend, a depth
// buffer of their own keeps each pixel's nearest blended depth (test LESS, writes on); a fragment
// that is not nearer than it came after something in front of it, and the stencil marks its
// pixel. Groups (the primitives the order cannot separate) are blended in the sequence like the
// rest, and the check marks the pixels where their fragments came out of depth order (unchecked,
// they are composited per pixel from fragment lists at their place). Marked pixels are
// composited again at the end, in one list pass: the colour the opaque pass left there (copied
// before blending), and every transparent fragment that covers them.
//
// With Vis-sort's order marked pixels are few: where a cycle's triangles overlap, a pixel centre
// within a rounding error of an edge, which the oracle's rasterizer and the GPU's put on
// different sides, or depths that tie exactly (docs/transparency.md).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "gl/gl_objects.h"
#include "render/draw_sequence.h"
#include "render/fragment_lists.h"
#include "render/marked_pixels.h"
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
    /// opaque surfaces, their depth in the target's depth), marking every pixel where a fragment
    /// came after one in front of it or tied with it. `draw(program, first, count)` draws
    /// sequence triangles [first, first + count) with program bound and its view set; programs
    /// are the shading vertex shader's. lists serve the sequence's per-pixel groups; without a
    /// repair, marked pixels keep the order's blend (an unchecked order, its groups per pixel).
    Result
    blend(const RenderTarget& target, FragmentLists& lists, const DrawSequence& sequence,
          bool has_opaque,
          const std::function<void(GLuint program, std::size_t first, std::size_t count)>& draw);

    /// The pixels the last blend marked (none when it had nothing to blend).
    MarkedPixels marked();

    /// Composites the marked pixels again: the colour the opaque pass left (the target's colour
    /// when blend began), then every transparent fragment from lists. `draw_transparent(program)`
    /// draws, the same way as blend's draw, at least every transparent triangle that may cover a
    /// marked pixel (trianglesCovering); it may run more than once.
    Result repair(const RenderTarget& target, FragmentLists& lists, const MarkedPixels& marked,
                  bool has_opaque, const std::function<void(GLuint program)>& draw_transparent);

private:
    void resize(const RenderTarget& target);

    GlProgram blend_program_, opaque_blend_program_; // without and with the opaque test
    GlProgram opaque_colour_program_;                // the repair's first pass

    GlVertexArray empty_vertex_array_;
    GlTexture nearest_;         // depth and stencil of the check
    GlTexture opaque_colour_;   // the target's colour as blend found it
    GlFramebuffer framebuffer_; // the target's colour with nearest_
    uint32_t width_ = 0, height_ = 0;
    GLuint target_colour_ = 0;
    bool blended_ = false;         // the last blend drew something: its marks are in nearest_
    std::vector<uint8_t> stencil_; // the marks as read back, reused from frame to frame
};

} // namespace vissort::detail
