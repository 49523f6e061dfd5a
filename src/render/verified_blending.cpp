#include "render/verified_blending.h"

#include "gl/gl_program.h"
#include "render/shading.h"

static_assert(vissort::detail::MarkedPixels::kTileSide == vissort::detail::kPixelGroupSide,
              "the repair resolves the marked tiles one work group each");

namespace vissort::detail {
namespace {

// The opaque surfaces hide fragments here, not through the framebuffer's depth, which keeps
// the check's nearest blended depth. A discarded fragment leaves depth and stencil alone.
// Without opaque surfaces a program without the test blends: a discard anywhere in a shader
// makes llvmpipe test depth after shading, which cost a third of the pass.
constexpr const char* kCheckedBlendFragmentShader = R"(#version 450 core
in vec4 shaded;
layout(binding = 1) uniform sampler2D opaque_depth;
layout(location = 0) out vec4 colour;
void main() {
    if (gl_FragCoord.z >= texelFetch(opaque_depth, ivec2(gl_FragCoord.xy), 0).r) discard;
    colour = shaded;
}
)";

// A triangle over the whole viewport, for the repair's pass that only tests the stencil.
constexpr const char* kCoverVertexShader = R"(#version 450 core
void main() {
    gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
}
)";

// The colour the opaque pass left: the background, or the opaque surface in front.
constexpr const char* kOpaqueColourFragmentShader = R"(#version 450 core
layout(binding = 2) uniform sampler2D opaque_colour;
layout(location = 0) out vec4 colour;
void main() { colour = texelFetch(opaque_colour, ivec2(gl_FragCoord.xy), 0); }
)";

constexpr GLint kMark = 1;

// Depth test LESS against the check's depth; a fragment that fails marks its pixel.
void checkAndMark() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, kMark, 0xFF);
    glStencilOp(GL_KEEP, GL_REPLACE, GL_KEEP);
}

} // namespace

VerifiedBlending::VerifiedBlending()
    : blend_program_(linkProgram(kShadeVertexShader, kShadeFragmentShader)),
      opaque_blend_program_(linkProgram(kShadeVertexShader, kCheckedBlendFragmentShader)),
      opaque_colour_program_(linkProgram(kCoverVertexShader, kOpaqueColourFragmentShader)) {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    empty_vertex_array_ = GlVertexArray(name);
}

void VerifiedBlending::resize(const RenderTarget& target) {
    if (target.width() == width_ && target.height() == height_ &&
        target.colourTexture() == target_colour_)
        return;
    width_ = target.width();
    height_ = target.height();
    target_colour_ = target.colourTexture();
    nearest_ = makeTexture(GL_DEPTH32F_STENCIL8, width_, height_);
    opaque_colour_ = makeTexture(GL_RGBA32F, width_, height_);
    framebuffer_ = makeFramebuffer({target_colour_}, nearest_.get(), GL_DEPTH_STENCIL_ATTACHMENT);
}

VerifiedBlending::Result VerifiedBlending::blend(
    const RenderTarget& target, FragmentLists& lists, const DrawSequence& sequence, bool has_opaque,
    const std::function<void(GLuint program, std::size_t first, std::size_t count)>& draw) {
    Result result;
    blended_ = !sequence.triangles.empty();
    if (!blended_)
        return result;
    resize(target);
    // What the repair restores marked pixels to: one copy of the colour, where drawing the
    // opaque surfaces again over the marked tiles drew a good part of the power plant's opaque
    // triangles every frame of its walkthrough (docs/benchmarks.md, issue 33 step 2).
    glCopyImageSubData(target_colour_, GL_TEXTURE_2D, 0, 0, 0, 0, opaque_colour_.get(),
                       GL_TEXTURE_2D, 0, 0, 0, 0, GLsizei(width_), GLsizei(height_), 1);
    const float far = 1.0f;
    glDepthMask(GL_TRUE); // clears obey the write masks
    glStencilMask(0xFF);
    glClearNamedFramebufferfi(framebuffer_.get(), GL_DEPTH_STENCIL, 0, far, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, GLsizei(width_), GLsizei(height_));
    glBindTextureUnit(1, target.depthTexture());
    const GLuint blend = has_opaque ? opaque_blend_program_.get() : blend_program_.get();
    const GLuint opaque_depth = has_opaque ? target.depthTexture() : 0;

    for (const DrawSegment& segment : sequence.segments) {
        if (!segment.per_pixel) {
            checkAndMark();
            glDepthMask(GL_TRUE);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            // Colour: source over destination; the buffer's alpha stays 1 (opaque background).
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
            draw(blend, segment.first_triangle, segment.triangle_count);
            continue;
        }
        // A group: its fragments in front of everything blended so far are composited per pixel;
        // one behind marks its pixel. Then its nearest depth joins the check, its own order
        // free (no marks).
        checkAndMark();
        const FragmentLists::Result listed =
            lists.composite(target, segment.rect, opaque_depth, [&] {
                draw(lists.buildProgram(), segment.first_triangle, segment.triangle_count);
            });
        result.fragments += listed.fragments;
        result.extra_passes += listed.passes; // the group is also drawn for the check below
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
        glBindTextureUnit(1, target.depthTexture());
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        draw(blend, segment.first_triangle, segment.triangle_count);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    glDisable(GL_BLEND);
    glDepthMask(GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    return result;
}

MarkedPixels VerifiedBlending::marked() {
    if (!blended_)
        return {};
    // One byte a pixel (2 MB at 1600x1200), scanned on the CPU: cheaper than counting and
    // bounding the marks in a pass over every pixel (14 ms at 1024x1024 on llvmpipe).
    stencil_.resize(std::size_t(width_) * height_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(nearest_.get(), 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE,
                      GLsizei(stencil_.size()), stencil_.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return MarkedPixels(stencil_, width_, height_);
}

VerifiedBlending::Result
VerifiedBlending::repair(const RenderTarget& target, FragmentLists& lists,
                         const MarkedPixels& marked, bool has_opaque,
                         const std::function<void(GLuint program)>& draw_transparent) {
    Result result;
    if (marked.count() == 0)
        return result;
    result.repaired_pixels = marked.count();
    const PixelRect rect = marked.bounds();

    // On marked pixels only (stencil test): the colour the opaque pass left, then every
    // transparent fragment from lists.
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, GLsizei(width_), GLsizei(height_));
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, kMark, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_SCISSOR_TEST);
    glScissor(GLint(rect.x), GLint(rect.y), GLsizei(rect.width), GLsizei(rect.height));
    glUseProgram(opaque_colour_program_.get());
    glBindTextureUnit(2, opaque_colour_.get());
    glBindVertexArray(empty_vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_SCISSOR_TEST);
    glBindTextureUnit(1, target.depthTexture());
    const GLuint opaque_depth = has_opaque ? target.depthTexture() : 0;
    const FragmentLists::Result listed = lists.composite(
        target, rect, opaque_depth, [&] { draw_transparent(lists.buildProgram()); },
        marked.tileOrigins());
    glDisable(GL_STENCIL_TEST);
    result.fragments = listed.fragments;
    result.extra_passes = listed.passes;
    return result;
}

} // namespace vissort::detail
