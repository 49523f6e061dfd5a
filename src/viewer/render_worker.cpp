// The viewer's render thread (render_worker.h).

#include "viewer/render_worker.h"

#include <cassert>
#include <exception>
#include <stdexcept>

#include "vissort/gl_context.h"

namespace vissort::viewer {
RenderWorker::RenderWorker(const Scene& scene)
    : scene_(scene), frames_(scene), thread_([this] { run(); }) {}

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
    // Its GL objects go with the context current on this thread.
    pipeline_.reset();
}

RenderedFrame RenderWorker::render(const RenderRequest& request) {
    RenderedFrame frame;
    frame.request = request;
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

} // namespace vissort::viewer
