#pragma once
// The viewer's renderer on a thread of its own: ordering and rendering a frame can take from tens
// of milliseconds to seconds on a CPU renderer (llvmpipe), and the window must keep handling
// input meanwhile. The worker owns the headless OpenGL context (gl_context.h) and the
// TransparencyRenderer; the window's thread only hands it requests and takes finished images,
// the same pixels `vissort render` writes for the same camera and frame.

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "vissort/camera.h"
#include "vissort/collision.h"
#include "vissort/frame_driver.h"
#include "vissort/image.h"
#include "vissort/scene.h"
#include "vissort/transparency_renderer.h"

namespace vissort::viewer {

/// What the viewer shows beside the method's picture.
struct Overlays {
    /// The triangles that intersect another object's (the collision detector's pairs, vissort's
    /// method) in the renderer's highlight colour, as `render --highlight-collisions` draws them.
    bool highlight_collisions = false;
    /// Instead of the picture, where it differs from linked-list's (rendered with the same
    /// settings and highlights): errorMap (image.h), as `render --error-map` writes it. The
    /// picture is then rendered without colour_cycles, whose colours would all be errors.
    bool error_map = false;
};

/// What to render: the scene at a frame (time frame * kFrameInterval) through a camera.
struct RenderRequest {
    RenderSettings settings;
    Overlays overlays;
    CameraSpec camera;
    int frame = 0;
    uint32_t width = 0, height = 0;
};

/// A finished request: 8-bit RGBA rows from the top (the picture or its error map), or the
/// one-line error that stopped it.
struct RenderedFrame {
    RenderRequest request;
    std::vector<uint8_t> rgba;
    RenderStats stats;
    std::string error;
    // With highlight_collisions: the intersecting triangle pairs and the detector's time.
    uint64_t colliding_pairs = 0;
    uint64_t colliding_triangles = 0;
    double collision_ms = 0;
    std::optional<ImageError> difference; // with error_map: the picture against linked-list's
};

class RenderWorker {
public:
    /// Starts the thread; scene must outlive the worker.
    explicit RenderWorker(const Scene& scene);
    /// Finishes the frame in progress, then stops the thread.
    ~RenderWorker();
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    /// True from submit until the frame is taken.
    bool busy() const;
    /// Starts rendering request; the worker must not be busy.
    void submit(const RenderRequest& request);
    /// The finished frame, if there is one (the worker is then free).
    std::optional<RenderedFrame> take();
    /// Waits for the submitted frame and takes it.
    RenderedFrame wait();

private:
    void run();
    RenderedFrame render(const RenderRequest& request);
    // A renderer with these settings, remade when they change; its highlights follow the frame's.
    struct Slot {
        std::unique_ptr<TransparencyRenderer> renderer;
        RenderSettings settings;
        bool highlighting = false;
    };
    TransparencyRenderer& prepare(Slot& slot, const RenderSettings& settings);

    const Scene& scene_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<RenderRequest> pending_;
    std::optional<RenderedFrame> done_;
    bool busy_ = false, stopping_ = false;
    // The worker thread's own: made on the first request, remade when the settings change.
    Slot picture_, reference_; // the method's, and linked-list's for the error map
    std::unique_ptr<CollisionDetector> collisions_; // made when first asked for
    CollisionResult collided_;
    std::vector<uint32_t> highlighted_; // this frame's colliding triangles
    FrameDriver frames_;                // positions only: the camera comes with each request
    std::thread thread_;                // last: started once everything above exists
};

} // namespace vissort::viewer
