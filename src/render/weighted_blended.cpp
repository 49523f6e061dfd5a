#include "render/weighted_blended.h"

#include "gl/gl_program.h"
#include "render/shading.h"

namespace vissort::detail {
namespace {

// The paper's weight of equation (9), w = alpha * max(1e-2, 3e3 (1 - z)^3), with z the window
// depth (here d in [0, 1), camera.h): nearer fragments weigh more. Accumulated in 32-bit floats,
// so large weights do not overflow as they could in the paper's 16-bit targets.
constexpr const char* kAccumulateFragmentShader = R"(#version 450 core
in vec4 shaded;
layout(location = 0) out vec4 accumulated;  // sum of w (a c, a), blended ONE, ONE
layout(location = 1) out float revealage;   // product of (1 - a), blended ZERO, 1 - source
void main() {
    float a = shaded.a;
    float w = a * max(1e-2, 3e3 * pow(1.0 - gl_FragCoord.z, 3.0));
    accumulated = vec4(shaded.rgb * a, a) * w;
    revealage = a;
}
)";

// colour = (sum w a c / sum w a) (1 - revealage) + revealage colour.
constexpr const char* kFinishBody = R"(
layout(binding = 0, rgba32f) uniform readonly image2D accumulated;
layout(binding = 1, r32f) uniform readonly image2D revealage;
layout(binding = 2, rgba32f) uniform image2D target;
void main() {
    ivec2 pixel;
    if (!rectanglePixel(pixel)) return;
    float r = imageLoad(revealage, pixel).r;
    if (r == 1.0) return;  // no transparent fragment here
    vec4 sum = imageLoad(accumulated, pixel);
    vec3 average = sum.rgb / max(sum.a, 1e-5);
    vec4 destination = imageLoad(target, pixel);
    imageStore(target, pixel, vec4(average * (1.0 - r) + r * destination.rgb, destination.a));
}
)";

} // namespace

WeightedBlended::WeightedBlended()
    : accumulate_program_(linkProgram(kShadeVertexShader, kAccumulateFragmentShader)),
      finish_program_(linkPixelProgram(kFinishBody)) {}

void WeightedBlended::composite(const RenderTarget& target, const std::function<void()>& draw) {
    if (target.width() != width_ || target.height() != height_ ||
        target.depthTexture() != target_depth_) {
        width_ = target.width();
        height_ = target.height();
        target_depth_ = target.depthTexture();
        accumulated_ = makeTexture(GL_RGBA32F, width_, height_);
        revealage_ = makeTexture(GL_R32F, width_, height_);
        framebuffer_ = makeFramebuffer({accumulated_.get(), revealage_.get()}, target_depth_);
    }
    const float zero[4] = {0, 0, 0, 0}, one = 1;
    glClearTexImage(accumulated_.get(), 0, GL_RGBA, GL_FLOAT, zero);
    glClearTexImage(revealage_.get(), 0, GL_RED, GL_FLOAT, &one);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, GLsizei(width_), GLsizei(height_));
    glEnable(GL_DEPTH_TEST); // against the opaque depth, no writes
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
    draw();
    glDisable(GL_BLEND);
    glBindImageTexture(0, accumulated_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, revealage_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(2, target.colourTexture(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    runPixelProgram(finish_program_.get(), target.whole());
}

} // namespace vissort::detail
