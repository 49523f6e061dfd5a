#include "render/verified_blending.h"

#include "gl/gl_program.h"
#include "render/shading.h"

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

// How many pixels are marked, and the rectangle around them: (count, x0, y0, x1, y1) with the
// bounds inclusive, set by atomics from (0, ~0, ~0, 0, 0).
constexpr const char* kScanBody = R"(
layout(binding = 0) uniform usampler2D marks;
layout(std430, binding = 4) buffer Marked { uint count; uint x0; uint y0; uint x1; uint y1; };
void main() {
    ivec2 pixel;
    if (!rectanglePixel(pixel) || texelFetch(marks, pixel, 0).r == 0u) return;
    atomicAdd(count, 1u);
    atomicMin(x0, uint(pixel.x));
    atomicMin(y0, uint(pixel.y));
    atomicMax(x1, uint(pixel.x));
    atomicMax(y1, uint(pixel.y));
}
)";

// A triangle over the whole viewport, for the passes that only test the stencil.
constexpr const char* kCoverVertexShader = R"(#version 450 core
void main() {
    gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
}
)";
constexpr const char* kBackgroundFragmentShader = R"(#version 450 core
uniform vec4 background;
layout(location = 0) out vec4 colour;
void main() { colour = background; }
)";

// An opaque surface's colour where it is the one the opaque pass kept: its depth there is the
// stored one, bit for bit (the same vertex shader, invariant gl_Position).
constexpr const char* kOpaqueAgainFragmentShader = R"(#version 450 core
in vec4 shaded;
layout(binding = 1) uniform sampler2D opaque_depth;
layout(location = 0) out vec4 colour;
void main() {
    if (gl_FragCoord.z != texelFetch(opaque_depth, ivec2(gl_FragCoord.xy), 0).r) discard;
    colour = shaded;
}
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
      opaque_program_(linkProgram(kShadeVertexShader, kOpaqueAgainFragmentShader)),
      background_program_(linkProgram(kCoverVertexShader, kBackgroundFragmentShader)),
      scan_program_(linkPixelProgram(kScanBody)), query_(makeQuery()) {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    empty_vertex_array_ = GlVertexArray(name);
    glCreateBuffers(1, &name);
    marked_ = GlBuffer(name);
    glNamedBufferStorage(marked_.get(), 5 * sizeof(GLuint), nullptr,
                         GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
}

void VerifiedBlending::resize(const RenderTarget& target) {
    if (target.width() == width_ && target.height() == height_ &&
        target.colourTexture() == target_colour_)
        return;
    width_ = target.width();
    height_ = target.height();
    target_colour_ = target.colourTexture();
    nearest_ = makeTexture(GL_DEPTH32F_STENCIL8, width_, height_);
    // Compute passes read the marks: the stencil, as an unsigned integer texture, which is only
    // complete (readable) with nearest filtering.
    glTextureParameteri(nearest_.get(), GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
    glTextureParameteri(nearest_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(nearest_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    framebuffer_ = makeFramebuffer({target_colour_}, nearest_.get(), GL_DEPTH_STENCIL_ATTACHMENT);
}

VerifiedBlending::Result VerifiedBlending::composite(
    const RenderTarget& target, FragmentLists& lists, const DrawSequence& sequence, bool repair,
    const Rgba& background, bool has_opaque, const std::function<void(GLuint program)>& draw_opaque,
    const std::function<void(GLuint program, std::size_t first, std::size_t count)>& draw) {
    Result result;
    if (sequence.triangles.empty())
        return result;
    resize(target);
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
    if (!repair)
        return result;

    // Any mark? One stencil-tested triangle over the screen answers; only then are the marks
    // counted and bounded, and repaired.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, kMark, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(background_program_.get());
    glBindVertexArray(empty_vertex_array_.get());
    const bool any_marked = anySamplePasses(query_, [] { glDrawArrays(GL_TRIANGLES, 0, 3); });
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    if (!any_marked)
        return result;
    const GLuint initial[5] = {0, ~0u, ~0u, 0, 0};
    glNamedBufferSubData(marked_.get(), 0, sizeof(initial), initial);
    glBindTextureUnit(0, nearest_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, marked_.get());
    runPixelProgram(scan_program_.get(), target.whole());
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint marked[5];
    glGetNamedBufferSubData(marked_.get(), 0, sizeof(marked), marked);
    result.repaired_pixels = marked[0];
    const PixelRect rect{marked[1], marked[2], marked[3] - marked[1] + 1,
                         marked[4] - marked[2] + 1};

    // The repair, on marked pixels only (stencil test): the background, the opaque surfaces
    // again, then every transparent fragment from lists.
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_SCISSOR_TEST);
    glScissor(GLint(rect.x), GLint(rect.y), GLsizei(rect.width), GLsizei(rect.height));
    glProgramUniform4f(background_program_.get(),
                       glGetUniformLocation(background_program_.get(), "background"), background.r,
                       background.g, background.b, 1.0f);
    glUseProgram(background_program_.get());
    glBindVertexArray(empty_vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(1, target.depthTexture());
    draw_opaque(opaque_program_.get());
    glDisable(GL_SCISSOR_TEST);
    const FragmentLists::Result listed = lists.composite(target, rect, opaque_depth, [&] {
        draw(lists.buildProgram(), 0, sequence.triangles.size());
    });
    glDisable(GL_STENCIL_TEST);
    result.fragments += listed.fragments;
    result.extra_passes += listed.passes;
    return result;
}

} // namespace vissort::detail
