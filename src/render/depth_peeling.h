#pragma once
// Depth peeling (Everitt, "Interactive order-independent transparency", NVIDIA 2001), front to
// back: each geometry pass keeps, per pixel, the nearest transparent fragment behind the layer
// the previous pass kept, and blends it under the layers peeled so far. As many passes as the
// depth complexity needs: an occlusion query stops the loop at the first pass that finds nothing.

#include <cstdint>
#include <functional>

#include "gl/gl_objects.h"
#include "render/render_target.h"

namespace vissort::detail {

class DepthPeeling {
public:
    DepthPeeling();

    /// Composites the transparent fragments of `draw` onto the target's colour, in front of what
    /// it holds and hidden by its depth (the opaque surfaces). `draw` issues the draws with
    /// program() bound (view uniforms set by the caller) and runs once per pass. Returns the
    /// geometry passes, the last one empty.
    uint32_t composite(const RenderTarget& target, const std::function<void()>& draw);

    GLuint program() const { return peel_program_.get(); }

private:
    void resize(uint32_t width, uint32_t height);

    GlProgram peel_program_, under_program_, finish_program_;
    GlQuery query_; // does a pass peel anything?
    GlTexture layer_, accumulated_, depth_[2];
    GlFramebuffer framebuffer_[2]; // layer_ with depth_[i]
    uint32_t width_ = 0, height_ = 0;
};

} // namespace vissort::detail
