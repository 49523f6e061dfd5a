#pragma once
// Weighted blended order-independent transparency (McGuire and Bavoil, "Weighted blended
// order-independent transparency", JCGT 2013): one geometry pass accumulates depth-weighted
// premultiplied colours and the product of (1 - alpha); a full-screen step divides and
// composites. Fast, approximate: it is wrong wherever layers of different colours overlap, by an
// amount that depends on the weights. The fast peer, not an exact method.

#include <cstdint>
#include <functional>

#include "gl/gl_objects.h"
#include "render/render_target.h"

namespace vissort::detail {

class WeightedBlended {
public:
    WeightedBlended();

    /// Composites the transparent fragments of `draw` onto the target's colour, in front of what
    /// it holds and hidden by its depth (the opaque surfaces). `draw` issues the draws with
    /// program() bound (view uniforms set by the caller) and runs once.
    void composite(const RenderTarget& target, const std::function<void()>& draw);

    GLuint program() const { return accumulate_program_.get(); }

private:
    GlProgram accumulate_program_, finish_program_;
    GlTexture accumulated_, revealage_;
    GlFramebuffer framebuffer_;
    uint32_t width_ = 0, height_ = 0;
    GLuint target_depth_ = 0;
};

} // namespace vissort::detail
