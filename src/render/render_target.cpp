#include "render/render_target.h"

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>

#include "gl/gl_program.h"
#include "render/shading.h"

namespace vissort::detail {

GlTexture makeTexture(GLenum format, uint32_t width, uint32_t height) {
    while (glGetError() != GL_NO_ERROR) {
    } // only this call's errors count below
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &name);
    GlTexture texture(name);
    glTextureStorage2D(name, 1, format, GLsizei(width), GLsizei(height));
    if (glGetError() != GL_NO_ERROR)
        throw std::runtime_error("the OpenGL driver cannot make a " + std::to_string(width) + "x" +
                                 std::to_string(height) + " texture");
    return texture;
}

GlFramebuffer makeFramebuffer(std::initializer_list<GLuint> colours, GLuint depth,
                              GLenum depth_attachment) {
    assert(colours.size() <= 8);
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    GlFramebuffer framebuffer(name);
    GLenum buffers[8];
    GLsizei count = 0;
    for (GLuint colour : colours) {
        buffers[count] = GL_COLOR_ATTACHMENT0 + GLenum(count);
        glNamedFramebufferTexture(name, buffers[count], colour, 0);
        ++count;
    }
    if (depth != 0)
        glNamedFramebufferTexture(name, depth_attachment, depth, 0);
    glNamedFramebufferDrawBuffers(name, count, buffers);
    if (glCheckNamedFramebufferStatus(name, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the OpenGL driver cannot render to 32-bit float colour, depth "
                                 "and stencil buffers");
    return framebuffer;
}

void RenderTarget::resize(uint32_t width, uint32_t height) {
    if (width == width_ && height == height_ && framebuffer_.get() != 0)
        return;
    GLint largest = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
    if (width > uint32_t(largest) || height > uint32_t(largest))
        throw std::runtime_error("the OpenGL driver's textures reach " + std::to_string(largest) +
                                 " pixels on a side, not " + std::to_string(width) + "x" +
                                 std::to_string(height));
    colour_ = makeTexture(GL_RGBA32F, width, height);
    depth_ = makeTexture(GL_DEPTH_COMPONENT32F, width, height);
    framebuffer_ = makeFramebuffer({colour_.get()}, depth_.get());
    width_ = width;
    height_ = height;
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, GLsizei(width_), GLsizei(height_));
}

void RenderTarget::clear(const float background[4]) const {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    glClearNamedFramebufferfv(framebuffer_.get(), GL_COLOR, 0, background);
    const float far = 1.0f;
    glClearNamedFramebufferfv(framebuffer_.get(), GL_DEPTH, 0, &far);
}

std::vector<float> RenderTarget::readColour() const {
    std::vector<float> rgba(std::size_t(width_) * height_ * 4);
    // With glClipControl(GL_UPPER_LEFT), window row 0 is the top row: texel order is image order.
    glGetTextureImage(colour_.get(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)),
                      rgba.data());
    return rgba;
}

GlQuery makeQuery() {
    GLuint name = 0;
    glCreateQueries(GL_ANY_SAMPLES_PASSED, 1, &name);
    return GlQuery(name);
}

bool anySamplePasses(const GlQuery& query, const std::function<void()>& draw) {
    glBeginQuery(GL_ANY_SAMPLES_PASSED, query.get());
    draw();
    glEndQuery(GL_ANY_SAMPLES_PASSED);
    GLuint any = 0;
    glGetQueryObjectuiv(query.get(), GL_QUERY_RESULT, &any);
    return any != 0;
}

GlProgram linkPixelProgram(const char* body) {
    return linkComputeProgram((std::string(kPixelComputeHeader) + body).c_str());
}

namespace {

void setRectangle(GLuint program, PixelRect rect, bool tiled, uint32_t tile_count) {
    glUseProgram(program);
    glUniform2i(glGetUniformLocation(program, "origin"), GLint(rect.x), GLint(rect.y));
    glUniform2i(glGetUniformLocation(program, "extent"), GLint(rect.width), GLint(rect.height));
    glUniform1i(glGetUniformLocation(program, "tiled"), tiled ? 1 : 0);
    glUniform1ui(glGetUniformLocation(program, "tile_count"), tile_count);
}

void afterPixelProgram() {
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

} // namespace

void runPixelProgram(GLuint program, PixelRect rect) {
    if (rect.empty())
        return;
    setRectangle(program, rect, false, 0);
    glDispatchCompute((rect.width + kPixelGroupSide - 1) / kPixelGroupSide,
                      (rect.height + kPixelGroupSide - 1) / kPixelGroupSide, 1);
    afterPixelProgram();
}

void runPixelProgramOnTiles(GLuint program, PixelRect rect, std::span<const uint32_t> origins,
                            const GlBuffer& tiles_buffer) {
    const uint32_t tiles = uint32_t(origins.size() / 2);
    if (rect.empty() || tiles == 0)
        return;
    glNamedBufferData(tiles_buffer.get(), GLsizeiptr(origins.size_bytes()), origins.data(),
                      GL_STREAM_DRAW);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, tiles_buffer.get());
    setRectangle(program, rect, true, tiles);
    // Work groups in rows of at most 65,535, the least count every driver dispatches along x.
    constexpr uint32_t kRow = 65535;
    glDispatchCompute(std::min(tiles, kRow), (tiles + kRow - 1) / kRow, 1);
    afterPixelProgram();
}

} // namespace vissort::detail
