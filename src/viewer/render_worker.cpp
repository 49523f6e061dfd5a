// The viewer's render thread (render_worker.h).

#include "viewer/render_worker.h"

#include <cassert>
#include <exception>
#include <stdexcept>

#include "vissort/gl_context.h"

namespace vissort::viewer {
RenderWorker::RenderWorker(const Scene& scene, const TetGrid* grid)
    : scene_(scene), grid_(grid), frames_(scene), thread_([this] { run(); }) {}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

bool RenderWorker::busy() const {
    std::lock_guard lock(mutex_);
    return busy_;
}

void RenderWorker::submit(const RenderRequest& request) {
    {
        std::lock_guard lock(mutex_);
        assert(!busy_);
        busy_ = true;
        pending_ = request;
    }
    changed_.notify_all();
}

std::optional<RenderedFrame> RenderWorker::take() {
    std::lock_guard lock(mutex_);
    if (!done_)
        return std::nullopt;
    std::optional<RenderedFrame> frame = std::move(done_);
    done_.reset();
    busy_ = false;
    return frame;
}

RenderedFrame RenderWorker::wait() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return done_.has_value() || !busy_; });
    assert(done_);
    RenderedFrame frame = std::move(*done_);
    done_.reset();
    busy_ = false;
    return frame;
}

void RenderWorker::run() {
    for (;;) {
        RenderRequest request;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] { return stopping_ || pending_.has_value(); });
            if (stopping_)
                break;
            request = std::move(*pending_);
            pending_.reset();
        }
        RenderedFrame frame = render(request);
        {
            std::lock_guard lock(mutex_);
            done_ = std::move(frame);
        }
        changed_.notify_all();
    }
    // Its GL objects go with the context current on this thread (the gl oracle's too).
    pipeline_.reset();
    volume_.reset();
    volume_reference_.reset();
}

RenderedFrame RenderWorker::render(const RenderRequest& request) {
    RenderedFrame frame;
    frame.request = request;
    if (request.volume) {
        try {
            renderVolume(request, frame);
        } catch (const std::exception& error) {
            volume_.reset();
            frame.error = error.what();
        }
        return frame;
    }
    try {
        // The frame's positions as `vissort render` takes them; the view framed to its bounds.
        frames_.seek(request.frame);
        const PositionsView positions = frames_.positions();
        const ViewProjection view =
            frameCamera(request.camera, positions.bounds(), request.width, request.height);
        FramePipelineDef def;
        def.settings = request.settings;
        def.highlight_collisions = request.overlays.highlight_collisions;
        if (request.overlays.error_map) {
            def.settings.colour_cycles = false; // its colours would all be errors
            def.reference = BlendMethod::linked_list;
        }
        if (!pipeline_) {
            Result<std::shared_ptr<GlContext>> context = GlContext::shared();
            if (!context)
                throw std::runtime_error(context.error);
            pipeline_ = std::make_unique<FramePipeline>(*context.value, scene_, def);
        }
        pipeline_->configure(def);
        pipeline_->render(positions, view, frame.frame);
        if (request.overlays.error_map)
            frame.frame.rgba = errorMap(frame.frame.rgba, frame.frame.reference_rgba);
    } catch (const std::exception& error) {
        pipeline_.reset();
        frame.error = error.what();
    }
    return frame;
}

void RenderWorker::renderVolume(const RenderRequest& request, RenderedFrame& frame) {
    if (grid_ == nullptr)
        throw std::logic_error("a volume was asked of a window without a grid");
    const VolumeView& volume = *request.volume;
    // Framed to the boundary's bounds, as `vissort volume` frames it.
    const ViewProjection view =
        frameCamera(request.camera, scene_.positions.bounds(), request.width, request.height);
    if (!volume_ || volume_method_ != volume.method || volume_oracle_ != volume.oracle) {
        volume_.reset(); // one gl oracle at a time on this thread's context
        volume_ = std::make_unique<VolumeRenderer>(*grid_, volume.method, volume.oracle);
        volume_method_ = volume.method;
        volume_oracle_ = volume.oracle;
    }
    Result<Image> image = volume_->render(volume.settings, view);
    if (!image)
        throw std::runtime_error(image.error);
    frame.volume_stats = volume_->stats();
    RenderStats& stats = frame.frame.stats;
    stats.order_ms = frame.volume_stats.order_ms;
    stats.render_ms = frame.volume_stats.composite_ms;
    stats.total_ms = stats.order_ms + stats.render_ms;
    stats.order.queries = frame.volume_stats.queries;
    frame.frame.rgba = image.value->toRgba8();
    if (!request.overlays.error_map)
        return;
    if (!volume_reference_)
        volume_reference_ = std::make_unique<VolumeRenderer>(*grid_, VolumeMethod::raycast);
    Result<Image> truth = volume_reference_->render(volume.settings, view);
    if (!truth)
        throw std::runtime_error(truth.error);
    const std::vector<uint8_t> truth_rgba = truth.value->toRgba8();
    frame.frame.error = compareImages(frame.frame.rgba, truth_rgba);
    frame.frame.rgba = errorMap(frame.frame.rgba, truth_rgba);
}

} // namespace vissort::viewer
