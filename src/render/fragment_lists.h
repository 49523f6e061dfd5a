#pragma once
// Per-pixel fragment lists (Yang, Hensley, Grün, Thibieroz, "Real-time concurrent linked list
// construction on the GPU", EGSR 2010): every fragment of a draw is stored in its pixel's list,
// then each list is sorted by depth and blended back to front. The exact reference method
// (`linked-list`), and how `vissort` composites the few primitives its order cannot separate.
//
// Never drops a fragment: when a draw stores more fragments than the buffers hold, they grow to
// the count and the draw runs again; past the memory limit or the driver's largest buffer, the
// rectangle is split into bands of rows drawn one at a time (scissored), each within the buffers.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>

#include "gl/gl_objects.h"
#include "render/render_target.h"

namespace vissort::detail {

class FragmentLists {
public:
    /// Lists that hold at most max_bytes of fragments at once (0: kDefaultMaxBytes), and never
    /// more than the driver's largest shader storage buffer.
    explicit FragmentLists(uint64_t max_bytes = 0);

    struct Result {
        uint64_t fragments = 0; // fragments stored and blended
        uint32_t passes = 0;    // times draw ran (1, more after growing or splitting)
    };

    /// Blends every fragment that `draw` produces inside rect onto the target's colour, each
    /// pixel's fragments back to front by depth (ties: the lower triangle id in front), over what
    /// the pixel holds. `draw` issues the draws with buildProgram() bound (its view uniforms set
    /// by the caller); it runs with the caller's framebuffer (of the target's size), depth and
    /// stencil tests (evaluated before a fragment is stored), no depth or colour writes, and may
    /// run more than once. With opaque_depth (a depth texture, not the framebuffer's), fragments
    /// at or behind it are dropped; with 0 the caller's depth test hides the opaque surfaces.
    /// Throws std::runtime_error when a single pixel has more fragments than the buffers hold.
    /// With tile_origins (x, y pairs of 8x8 tiles' top-left pixels, as MarkedPixels lists
    /// them), only those tiles' pixels are resolved: the draw's fragments must all lie in them
    /// (a stencil test), as the few a repair composites do.
    Result composite(const RenderTarget& target, PixelRect rect, GLuint opaque_depth,
                     const std::function<void()>& draw,
                     std::optional<std::span<const uint32_t>> tile_origins = std::nullopt);

    /// The program `draw` binds: the shading vertex shader, fragments into the lists.
    GLuint buildProgram() const { return build_program_.get(); }

    static constexpr uint64_t kBytesPerFragment = 28; // colour vec4, depth, link, triangle id
    static constexpr uint64_t kDefaultMaxBytes = uint64_t(3) << 30;

private:
    /// Draws rect's fragments into the lists; returns how many there were (kHuge when the
    /// counter passed 2^31, where it could wrap).
    uint64_t build(PixelRect rect, GLuint opaque_depth, const std::function<void()>& draw);
    void allocate(uint64_t nodes);

    GlProgram build_program_, resolve_program_;
    GlTexture heads_;
    GlBuffer counter_, colours_, links_, triangles_, tiles_;
    uint32_t width_ = 0, height_ = 0;
    uint64_t capacity_ = 0;  // nodes the buffers hold
    uint64_t max_nodes_ = 0; // the most nodes the buffers may hold
};

} // namespace vissort::detail
