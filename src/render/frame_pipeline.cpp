// FramePipeline (frame_pipeline.h): collisions, the method's picture and a reference's, per frame.

#include "vissort/frame_pipeline.h"

#include <utility>

#include "vissort/collision.h"

namespace vissort {

// A renderer with these settings, remade only when they change; its highlights follow the
// frame's.
struct RendererSlot {
    std::unique_ptr<TransparencyRenderer> renderer;
    RenderSettings settings;
    bool highlighting = false; // the renderer holds highlights that the next frame may clear
    std::function<void(double)> progress;

    TransparencyRenderer& prepare(const std::shared_ptr<GlContext>& context, const Scene& scene,
                                  const RenderSettings& wanted,
                                  const std::vector<uint32_t>& highlighted,
                                  std::shared_ptr<const LevelsOfDetail>& levels) {
        if (!renderer || settings != wanted) {
            renderer.reset();
            // The scene's levels of detail are built once, when first needed, and shared by
            // every renderer of the pipeline.
            if (wanted.lod_error > 0.0f && !levels)
                levels = std::make_shared<const LevelsOfDetail>(LevelsOfDetail::build(scene));
            renderer = std::make_unique<TransparencyRenderer>(context, scene, wanted, levels);
            settings = wanted;
            highlighting = false;
            if (progress)
                renderer->setOrderProgress(progress);
        }
        if (!highlighted.empty() || highlighting) {
            renderer->setHighlightedTriangles(highlighted);
            highlighting = !highlighted.empty();
        }
        return *renderer;
    }
};

struct FramePipeline::Impl {
    std::shared_ptr<GlContext> context;
    const Scene& scene;
    FramePipelineDef def;
    RendererSlot picture, reference;
    std::unique_ptr<CollisionDetector> collisions; // made when first asked for
    CollisionResult collided;
    std::vector<uint32_t> highlighted;            // this frame's colliding triangles
    std::shared_ptr<const LevelsOfDetail> levels; // made when a renderer first needs them
};

FramePipeline::FramePipeline(std::shared_ptr<GlContext> context, const Scene& scene,
                             const FramePipelineDef& def,
                             std::shared_ptr<const LevelsOfDetail> levels)
    : impl_(std::make_unique<Impl>(
          Impl{std::move(context), scene, def, {}, {}, {}, {}, {}, std::move(levels)})) {
    // The method's renderer now, so that settings it refuses are refused before a frame.
    impl_->picture.prepare(impl_->context, scene, def.settings, {}, impl_->levels);
}

FramePipeline::~FramePipeline() = default;

void FramePipeline::configure(const FramePipelineDef& def) {
    impl_->def = def;
}

const FramePipelineDef& FramePipeline::def() const {
    return impl_->def;
}

void FramePipeline::setOrderProgress(std::function<void(double)> report) {
    impl_->picture.progress = report;
    if (impl_->picture.renderer)
        impl_->picture.renderer->setOrderProgress(std::move(report));
}

void FramePipeline::render(PositionsView positions, const ViewProjection& view,
                           PipelineFrame& frame) {
    Impl& p = *impl_;
    frame = {};
    p.highlighted.clear();
    if (p.def.highlight_collisions) {
        if (!p.collisions) {
            CollisionSettings settings;
            settings.threads = 0; // every core
            p.collisions =
                std::make_unique<CollisionDetector>(p.scene.objectPrimitives(), settings);
        }
        p.collisions->collide(positions, p.collided);
        p.highlighted = collidingTriangles(p.collided.pairs);
        frame.colliding_pairs = p.collided.pairs.size();
        frame.colliding_triangles = p.highlighted.size();
        frame.collision_ms = p.collided.stats.total_ms;
    }
    frame.rgba = p.picture.prepare(p.context, p.scene, p.def.settings, p.highlighted, p.levels)
                     .render(positions, view, frame.stats)
                     .toRgba8();
    if (p.def.reference) {
        RenderSettings settings = p.def.settings;
        settings.method = *p.def.reference;
        frame.reference_rgba =
            p.reference.prepare(p.context, p.scene, settings, p.highlighted, p.levels)
                .render(positions, view, frame.reference_stats)
                .toRgba8();
        frame.error = compareImages(frame.rgba, frame.reference_rgba);
    }
}

} // namespace vissort
