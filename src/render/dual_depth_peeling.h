#pragma once
// Dual depth peeling (Bavoil and Myers, "Order independent transparency with dual depth
// peeling", NVIDIA 2008): each geometry pass peels two layers per pixel, the nearest and the
// farthest not peeled yet, found with MAX blending of (-depth, depth) in the pass before; the
// front layers are blended under those peeled so far, the back layers over theirs. About half
// the passes of depth peeling; an occlusion query stops the loop at the first empty pass.

#include <cstdint>
#include <functional>

#include "gl/gl_objects.h"
#include "render/render_target.h"

namespace vissort::detail {

class DualDepthPeeling {
public:
    DualDepthPeeling();

    /// Composites the transparent fragments of `draw` onto the target's colour, in front of what
    /// it holds and hidden by its depth (the opaque surfaces). `draw` binds the program it is
    /// given (the depth range's, then the peel's), sets its view uniforms and issues the draws;
    /// it runs once per pass. Returns the geometry passes (the first finds the depth range, the
    /// last is empty).
    uint32_t composite(const RenderTarget& target, const std::function<void(GLuint program)>& draw);

private:
    void resize(const RenderTarget& target);

    GlProgram init_program_, peel_program_, finish_program_;
    GlQuery query_; // does a pass peel anything?
    GlTexture range_[2], front_, back_;
    GlFramebuffer init_framebuffer_, peel_framebuffer_[2]; // writing range_[i]
    uint32_t width_ = 0, height_ = 0;
    GLuint target_depth_ = 0;
};

} // namespace vissort::detail
