#pragma once
// One rendered frame, as `vissort render`, the viewer and Python's Renderer make it: the frame's
// collisions (optional), its picture through a transparency method with the colliding triangles
// highlighted, and a reference method's picture with the error against it (optional). A struct
// says what to do (FramePipelineDef, box2d's def style); the pipeline keeps the renderers and
// the collision detector from frame to frame, so the order of one frame seeds the next.
//
// Layer: vissort::render (the package's `render` component; docs/architecture.md).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "vissort/camera.h"
#include "vissort/gl_context.h"
#include "vissort/image.h"
#include "vissort/scene.h"
#include "vissort/transparency_renderer.h"

namespace vissort {

/// What each frame holds beside the method's picture.
struct FramePipelineDef {
    RenderSettings settings;
    /// Also render each frame with this method (the same settings otherwise and the same
    /// highlights) and compare the picture with it.
    std::optional<BlendMethod> reference;
    /// Detect the frame's collisions (vissort's detector, on every core) and draw the triangles
    /// that intersect another object's in the highlight colour, in the picture and the
    /// reference.
    bool highlight_collisions = false;
};

/// A rendered frame.
struct PipelineFrame {
    std::vector<uint8_t> rgba; // the method's picture: 8-bit RGBA rows from the top
    RenderStats stats;
    /// With a reference: its picture and costs, and the picture's error against it.
    std::vector<uint8_t> reference_rgba;
    RenderStats reference_stats;
    std::optional<ImageError> error;
    /// With highlight_collisions: the intersecting triangle pairs, the triangles highlighted
    /// and the detector's time.
    uint64_t colliding_pairs = 0;
    uint64_t colliding_triangles = 0;
    double collision_ms = 0;
};

class FramePipeline {
public:
    /// A pipeline of scene through context; scene must outlive it. Throws as
    /// TransparencyRenderer's constructor does for settings it refuses. levels: the scene's
    /// levels of detail for settings with a lod_error, shared by every renderer of the
    /// pipeline; built when first needed when null.
    FramePipeline(std::shared_ptr<GlContext> context, const Scene& scene,
                  const FramePipelineDef& def,
                  std::shared_ptr<const LevelsOfDetail> levels = nullptr);
    ~FramePipeline();
    FramePipeline(const FramePipeline&) = delete;
    FramePipeline& operator=(const FramePipeline&) = delete;

    /// What the following frames do. A renderer whose settings did not change is kept, with its
    /// last order (coherence), and so is the collision detector: a viewer toggling an overlay
    /// rebuilds nothing it already had.
    void configure(const FramePipelineDef& def);
    const FramePipelineDef& def() const;

    /// Renders the scene at positions (its triangle count) through view into frame. Throws as
    /// TransparencyRenderer::render does.
    void render(PositionsView positions, const ViewProjection& view, PipelineFrame& frame);

    /// Reports the share of the method's order done while vissort orders
    /// (TransparencyRenderer::setOrderProgress).
    void setOrderProgress(std::function<void(double fraction)> report);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace vissort
