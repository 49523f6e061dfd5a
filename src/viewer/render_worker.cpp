// The viewer's render thread (render_worker.h).

#include "viewer/render_worker.h"

#include <cassert>
#include <exception>

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
    renderer_.reset(); // its GL objects go with the context current on this thread
}

RenderedFrame RenderWorker::render(const RenderRequest& request) {
    RenderedFrame frame;
    frame.request = request;
    try {
        if (!renderer_ || renderer_settings_ != request.settings) {
            renderer_.reset();
            Result<std::shared_ptr<GlContext>> context = GlContext::shared();
            if (!context) {
                frame.error = context.error;
                return frame;
            }
            renderer_ =
                std::make_unique<TransparencyRenderer>(*context.value, scene_, request.settings);
            renderer_settings_ = request.settings;
        }
        // The frame's positions as `vissort render` takes them; the view framed to its bounds.
        frames_.seek(request.frame);
        const PositionsView positions = frames_.positions();
        const ViewProjection view =
            frameCamera(request.camera, positions.bounds(), request.width, request.height);
        frame.rgba = renderer_->render(positions, view, frame.stats).toRgba8();
    } catch (const std::exception& error) {
        renderer_.reset();
        frame.error = error.what();
    }
    return frame;
}

} // namespace vissort::viewer
