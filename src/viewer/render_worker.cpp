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
    // Their GL objects go with the context current on this thread.
    picture_ = {};
    reference_ = {};
}

TransparencyRenderer& RenderWorker::prepare(Slot& slot, const RenderSettings& settings) {
    if (!slot.renderer || slot.settings != settings) {
        slot.renderer.reset();
        Result<std::shared_ptr<GlContext>> context = GlContext::shared();
        if (!context)
            throw std::runtime_error(context.error);
        slot.renderer = std::make_unique<TransparencyRenderer>(*context.value, scene_, settings);
        slot.settings = settings;
        slot.highlighting = false;
    }
    if (!highlighted_.empty() || slot.highlighting) {
        slot.renderer->setHighlightedTriangles(highlighted_);
        slot.highlighting = !highlighted_.empty();
    }
    return *slot.renderer;
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
        highlighted_.clear();
        if (request.overlays.highlight_collisions) {
            if (!collisions_) {
                CollisionSettings settings;
                settings.threads = 0; // every core
                collisions_ =
                    std::make_unique<CollisionDetector>(scene_.objectPrimitives(), settings);
            }
            collisions_->collide(positions, collided_);
            highlighted_ = collidingTriangles(collided_.pairs);
            frame.colliding_pairs = collided_.pairs.size();
            frame.colliding_triangles = highlighted_.size();
            frame.collision_ms = collided_.stats.total_ms;
        }
        RenderSettings settings = request.settings;
        if (request.overlays.error_map)
            settings.colour_cycles = false;
        frame.rgba = prepare(picture_, settings).render(positions, view, frame.stats).toRgba8();
        if (request.overlays.error_map) {
            settings.method = BlendMethod::linked_list;
            RenderStats reference_stats;
            const std::vector<uint8_t> reference =
                prepare(reference_, settings).render(positions, view, reference_stats).toRgba8();
            frame.difference = compareImages(frame.rgba, reference);
            frame.rgba = errorMap(frame.rgba, reference);
        }
    } catch (const std::exception& error) {
        picture_ = {};
        reference_ = {};
        frame.error = error.what();
    }
    return frame;
}

} // namespace vissort::viewer
