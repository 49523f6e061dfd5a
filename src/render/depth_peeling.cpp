#include "render/depth_peeling.h"

#include "gl/gl_program.h"
#include "render/shading.h"

namespace vissort::detail {
namespace {

// A pass keeps the nearest fragment strictly behind the previous pass's layer (the depth test
// LESS does the keeping, on a depth buffer that starts as the opaque depth). A fragment at the
// exact depth of the layer before is that layer's own: it was peeled already.
constexpr const char* kPeelFragmentShader = R"(#version 450 core
in vec4 shaded;
layout(binding = 0) uniform sampler2D previous_layer_depth;
uniform bool first_pass;
layout(location = 0) out vec4 colour;
void main() {
    if (!first_pass && gl_FragCoord.z <= texelFetch(previous_layer_depth, ivec2(gl_FragCoord.xy), 0).r)
        discard;
    colour = shaded;
}
)";

// Blends the pass's layer under those peeled before (front-to-back "under" operator):
// accumulated = (premultiplied colour C, transmittance T); C += T a c, T *= 1 - a.
constexpr const char* kUnderBody = R"(
layout(binding = 0) uniform sampler2D layer;
layout(binding = 1, rgba32f) uniform image2D accumulated;
void main() {
    ivec2 pixel;
    if (!rectanglePixel(pixel)) return;
    vec4 fragment = texelFetch(layer, pixel, 0);
    if (fragment.a == 0.0) return;  // nothing peeled here
    vec4 sum = imageLoad(accumulated, pixel);
    imageStore(accumulated, pixel, vec4(sum.rgb + sum.a * fragment.a * fragment.rgb,
                                        sum.a * (1.0 - fragment.a)));
}
)";

// The peeled layers over what the target holds: colour = C + T * colour.
constexpr const char* kFinishBody = R"(
layout(binding = 0, rgba32f) uniform readonly image2D accumulated;
layout(binding = 1, rgba32f) uniform image2D target;
void main() {
    ivec2 pixel;
    if (!rectanglePixel(pixel)) return;
    vec4 sum = imageLoad(accumulated, pixel);
    vec4 destination = imageLoad(target, pixel);
    imageStore(target, pixel, vec4(sum.rgb + sum.a * destination.rgb, destination.a));
}
)";

} // namespace

DepthPeeling::DepthPeeling()
    : peel_program_(linkProgram(kShadeVertexShader, kPeelFragmentShader)),
      under_program_(linkPixelProgram(kUnderBody)), finish_program_(linkPixelProgram(kFinishBody)),
      query_(makeQuery()) {}

void DepthPeeling::resize(uint32_t width, uint32_t height) {
    if (width == width_ && height == height_)
        return;
    layer_ = makeTexture(GL_RGBA32F, width, height);
    accumulated_ = makeTexture(GL_RGBA32F, width, height);
    for (int i = 0; i < 2; ++i) {
        depth_[i] = makeTexture(GL_DEPTH_COMPONENT32F, width, height);
        framebuffer_[i] = makeFramebuffer({layer_.get()}, depth_[i].get());
    }
    width_ = width;
    height_ = height;
}

uint32_t DepthPeeling::composite(const RenderTarget& target, const std::function<void()>& draw) {
    resize(target.width(), target.height());
    const float cleared[4] = {0, 0, 0, 1}; // nothing yet: no colour, full transmittance
    glClearTexImage(accumulated_.get(), 0, GL_RGBA, GL_FLOAT, cleared);
    uint32_t passes = 0;
    for (int current = 0;; current = 1 - current) {
        // The pass's depth buffer starts as the opaque depth: fragments behind opaque surfaces
        // fail the test like those of nearer layers.
        glCopyImageSubData(target.depthTexture(), GL_TEXTURE_2D, 0, 0, 0, 0, depth_[current].get(),
                           GL_TEXTURE_2D, 0, 0, 0, 0, GLsizei(width_), GLsizei(height_), 1);
        const float transparent[4] = {0, 0, 0, 0};
        glClearTexImage(layer_.get(), 0, GL_RGBA, GL_FLOAT, transparent);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_[current].get());
        glViewport(0, 0, GLsizei(width_), GLsizei(height_));
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        glBindTextureUnit(0, depth_[1 - current].get());
        glProgramUniform1i(peel_program_.get(),
                           glGetUniformLocation(peel_program_.get(), "first_pass"), passes == 0);
        const bool peeled = anySamplePasses(query_, draw);
        ++passes;
        if (!peeled)
            break; // every fragment is peeled
        glBindTextureUnit(0, layer_.get());
        glBindImageTexture(1, accumulated_.get(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
        runPixelProgram(under_program_.get(), target.whole());
    }
    glDepthMask(GL_FALSE);
    glBindImageTexture(0, accumulated_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, target.colourTexture(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    runPixelProgram(finish_program_.get(), target.whole());
    return passes;
}

} // namespace vissort::detail
