#include "render/sample_resolve.h"

#include <cassert>

#include "render/shading.h"

namespace vissort::detail {
namespace {

// One invocation a pixel: the mean of its grid of samples, row by row.
constexpr const char* kResolveBody = R"(
layout(binding = 0, rgba32f) readonly uniform image2D samples;
layout(binding = 1, rgba32f) writeonly uniform image2D resolved;
uniform ivec2 grid;  // columns, rows
void main() {
    ivec2 pixel;
    if (!rectanglePixel(pixel)) return;
    vec4 sum = vec4(0.0);
    for (int row = 0; row < grid.y; ++row)
        for (int column = 0; column < grid.x; ++column)
            sum += imageLoad(samples, pixel * grid + ivec2(column, row));
    imageStore(resolved, pixel, sum / float(grid.x * grid.y));
}
)";

} // namespace

SampleResolve::SampleResolve() : program_(linkPixelProgram(kResolveBody)) {}

std::vector<float> SampleResolve::resolve(const RenderTarget& target, const SampleGrid& grid) {
    assert(target.width() % grid.columns == 0 && target.height() % grid.rows == 0);
    const uint32_t width = target.width() / grid.columns, height = target.height() / grid.rows;
    if (width != width_ || height != height_) {
        resolved_ = makeTexture(GL_RGBA32F, width, height);
        width_ = width;
        height_ = height;
    }
    glBindImageTexture(0, target.colourTexture(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, resolved_.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glProgramUniform2i(program_.get(), glGetUniformLocation(program_.get(), "grid"),
                       GLint(grid.columns), GLint(grid.rows));
    runPixelProgram(program_.get(), {0, 0, width, height});
    std::vector<float> rgba(std::size_t(width) * height * 4);
    glGetTextureImage(resolved_.get(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)),
                      rgba.data());
    return rgba;
}

} // namespace vissort::detail
