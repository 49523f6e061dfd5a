#pragma once
// The renderer's framebuffer: a 32-bit float RGBA colour texture (every method blends in float)
// and a 32-bit float depth texture (the opaque objects' depth), and the per-pixel compute passes
// that composite onto it.

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <span>
#include <vector>

#include "gl/gl_objects.h"
#include "render/pixel_rect.h"

namespace vissort::detail {

class RenderTarget {
public:
    /// Resizes when the size changed; throws std::runtime_error beyond the driver's limits.
    void resize(uint32_t width, uint32_t height);
    /// Binds the framebuffer as the draw target and sets the viewport.
    void bind() const;
    /// Clears colour to background and depth to 1.0 (the far plane).
    void clear(const float background[4]) const;
    /// Reads the colour back: width * height * 4 floats, row 0 at the top.
    std::vector<float> readColour() const;

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    PixelRect whole() const { return {0, 0, width_, height_}; }
    GLuint colourTexture() const { return colour_.get(); }
    GLuint depthTexture() const { return depth_.get(); }

private:
    uint32_t width_ = 0, height_ = 0;
    GlTexture colour_, depth_;
    GlFramebuffer framebuffer_;
};

/// Links a per-pixel compute program: kPixelComputeHeader (shading.h), then body. Throws like
/// linkProgram.
GlProgram linkPixelProgram(const char* body);

/// Runs a compute program written with kPixelComputeHeader (shading.h) once per pixel of rect:
/// sets its origin and extent uniforms, dispatches, and makes its image writes visible to the
/// draws, texture fetches and image loads that follow.
void runPixelProgram(GLuint program, PixelRect rect);

/// The same over the pixels of rect within the 8x8 tiles (kPixelGroupSide) whose top-left
/// pixels are origins (x, y pairs; shading.h's header reads them from shader storage binding 7,
/// uploaded to tiles_buffer here).
void runPixelProgramOnTiles(GLuint program, PixelRect rect, std::span<const uint32_t> origins,
                            const GlBuffer& tiles_buffer);

/// Runs draw under an occlusion query and waits for the answer: did any sample pass? (A peeling
/// pass that finds nothing ends the loop.) query is a GL_ANY_SAMPLES_PASSED query object.
bool anySamplePasses(const GlQuery& query, const std::function<void()>& draw);

/// A new GL_ANY_SAMPLES_PASSED query object.
GlQuery makeQuery();

/// A new 2D texture of one level; throws std::runtime_error when the driver refuses it.
GlTexture makeTexture(GLenum format, uint32_t width, uint32_t height);

/// A framebuffer over the given colour textures (attachments 0, 1, ... in order, at most 8) and
/// depth texture (0 for none; a depth and stencil texture with GL_DEPTH_STENCIL_ATTACHMENT),
/// drawing to all of them; throws std::runtime_error when incomplete.
GlFramebuffer makeFramebuffer(std::initializer_list<GLuint> colours, GLuint depth,
                              GLenum depth_attachment = GL_DEPTH_ATTACHMENT);

} // namespace vissort::detail
