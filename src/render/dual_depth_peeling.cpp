#include "render/dual_depth_peeling.h"

#include "gl/gl_program.h"
#include "render/shading.h"

namespace vissort::detail {
namespace {

// The depth range of the transparent fragments at each pixel, as (-nearest, farthest) under MAX
// blending. Cleared to (-1, -1): an empty range (nearest 1 > farthest -1).
constexpr const char* kInitFragmentShader = R"(#version 450 core
layout(location = 0) out vec2 range;
void main() { range = vec2(-gl_FragCoord.z, gl_FragCoord.z); }
)";

// A fragment outside the previous pass's range was peeled before; strictly inside, it widens the
// next range; at either end it is peeled now: the nearest blended under the front layers, the
// farthest over the back layers. Outputs that must not change a buffer are neutral for its blend
// (-1 for MAX; transparent black for the front and back blends).
constexpr const char* kPeelFragmentShader = R"(#version 450 core
in vec4 shaded;
layout(binding = 0) uniform sampler2D previous_range;
layout(location = 0) out vec2 range;
layout(location = 1) out vec4 front;
layout(location = 2) out vec4 back;
void main() {
    float depth = gl_FragCoord.z;
    vec2 previous = texelFetch(previous_range, ivec2(gl_FragCoord.xy), 0).rg;
    float nearest = -previous.x, farthest = previous.y;
    if (depth < nearest || depth > farthest) discard;
    range = vec2(-1.0);
    front = vec4(0.0);
    back = vec4(0.0);
    if (depth > nearest && depth < farthest) {
        range = vec2(-depth, depth);
    } else {
        vec4 premultiplied = vec4(shaded.rgb * shaded.a, shaded.a);
        if (depth == nearest) front = premultiplied;
        else back = premultiplied;
    }
}
)";

// front = (C_f, T_f), back = (C_b, T_b), each premultiplied colour and transmittance:
// colour = C_f + T_f (C_b + T_b colour).
constexpr const char* kFinishBody = R"(
layout(binding = 0, rgba32f) uniform readonly image2D front;
layout(binding = 1, rgba32f) uniform readonly image2D back;
layout(binding = 2, rgba32f) uniform image2D target;
void main() {
    ivec2 pixel;
    if (!rectanglePixel(pixel)) return;
    vec4 f = imageLoad(front, pixel), b = imageLoad(back, pixel);
    vec4 destination = imageLoad(target, pixel);
    imageStore(target, pixel, vec4(f.rgb + f.a * (b.rgb + b.a * destination.rgb), destination.a));
}
)";

} // namespace

DualDepthPeeling::DualDepthPeeling()
    : init_program_(linkProgram(kShadeVertexShader, kInitFragmentShader)),
      peel_program_(linkProgram(kShadeVertexShader, kPeelFragmentShader)),
      finish_program_(linkPixelProgram(kFinishBody)), query_(makeQuery()) {}

void DualDepthPeeling::resize(const RenderTarget& target) {
    if (target.width() == width_ && target.height() == height_ &&
        target.depthTexture() == target_depth_)
        return;
    width_ = target.width();
    height_ = target.height();
    target_depth_ = target.depthTexture();
    for (int i = 0; i < 2; ++i)
        range_[i] = makeTexture(GL_RG32F, width_, height_);
    front_ = makeTexture(GL_RGBA32F, width_, height_);
    back_ = makeTexture(GL_RGBA32F, width_, height_);
    // Every pass tests against the opaque depth (LESS, no writes): hidden fragments never count.
    init_framebuffer_ = makeFramebuffer({range_[0].get()}, target_depth_);
    for (int i = 0; i < 2; ++i)
        peel_framebuffer_[i] =
            makeFramebuffer({range_[i].get(), front_.get(), back_.get()}, target_depth_);
}

uint32_t DualDepthPeeling::composite(const RenderTarget& target,
                                     const std::function<void(GLuint program)>& draw) {
    resize(target);
    const float empty_range[2] = {-1, -1};
    const float nothing[4] = {0, 0, 0, 1}; // no colour, full transmittance
    glClearTexImage(range_[0].get(), 0, GL_RG, GL_FLOAT, empty_range);
    glClearTexImage(front_.get(), 0, GL_RGBA, GL_FLOAT, nothing);
    glClearTexImage(back_.get(), 0, GL_RGBA, GL_FLOAT, nothing);
    glViewport(0, 0, GLsizei(width_), GLsizei(height_));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);

    glBindFramebuffer(GL_FRAMEBUFFER, init_framebuffer_.get());
    glBlendEquation(GL_MAX);
    glBlendFunc(GL_ONE, GL_ONE);
    draw(init_program_.get());
    uint32_t passes = 1;

    // Per draw buffer: MAX for the range; "under" for the front, (C, T) += T_dst (a c, 0) and
    // T *= 1 - a; "over" for the back, C = a c + (1 - a) C and T *= 1 - a.
    glBlendEquationi(0, GL_MAX);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendEquationi(1, GL_FUNC_ADD);
    glBlendFuncSeparatei(1, GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
    glBlendEquationi(2, GL_FUNC_ADD);
    glBlendFuncSeparatei(2, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
    for (int previous = 0;; previous = 1 - previous) {
        const int next = 1 - previous;
        glClearTexImage(range_[next].get(), 0, GL_RG, GL_FLOAT, empty_range);
        glBindFramebuffer(GL_FRAMEBUFFER, peel_framebuffer_[next].get());
        glBindTextureUnit(0, range_[previous].get());
        const bool peeled = anySamplePasses(query_, [&] { draw(peel_program_.get()); });
        ++passes;
        if (!peeled)
            break; // every fragment is peeled
    }
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glBindImageTexture(0, front_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, back_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(2, target.colourTexture(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    runPixelProgram(finish_program_.get(), target.whole());
    return passes;
}

} // namespace vissort::detail
