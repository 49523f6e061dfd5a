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
#include "vissort/frame_driver.h"
#include "vissort/frame_pipeline.h"
#include "vissort/image.h"
#include "vissort/scene.h"
#include "vissort/transparency_renderer.h"
#include "vissort/volume.h"

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

/// What a grid's window renders (`vissort view GRID`): the volume renderer's settings and
/// method, and the name the panel shows for the transfer function (a preset's, a file's, or
/// "edited").
struct VolumeView {
    VolumeSettings settings;
    VolumeMethod method = VolumeMethod::vissort;
    OracleKind oracle = OracleKind::cpu; // vissort's
    std::string tf_name;
};

/// What to render: the scene at a frame (time frame * kFrameInterval) through a camera; for a
/// grid, its volume (the scene is then the grid's boundary, which frames the camera).
struct RenderRequest {
    RenderSettings settings;
    std::optional<VolumeView> volume; // a grid's window: these settings instead of `settings`
    Overlays overlays; // a grid's: error_map against raycast, highlight_collisions unused
    CameraSpec camera;
    int frame = 0;
    uint32_t width = 0, height = 0;
};

/// A finished request: the pipeline's frame (its picture replaced by the error map with
/// overlays.error_map), or the one-line error that stopped it. A grid's frame has its picture,
/// its times (order_ms, render_ms: compositing, total_ms) and error in `frame`, its counts in
/// volume_stats.
struct RenderedFrame {
    RenderRequest request;
    PipelineFrame frame;
    VolumeFrameStats volume_stats;
    std::string error;
};

class RenderWorker {
public:
    /// Starts the thread; scene must outlive the worker. With a grid (which must outlive it
    /// too), requests with a volume render the grid, scene being its boundary (boundaryScene).
    explicit RenderWorker(const Scene& scene, const TetGrid* grid = nullptr);
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
    void renderVolume(const RenderRequest& request, RenderedFrame& frame);

    const Scene& scene_;
    const TetGrid* grid_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<RenderRequest> pending_;
    std::optional<RenderedFrame> done_;
    bool busy_ = false, stopping_ = false;
    // The worker thread's own: made on the first request, reconfigured by each.
    std::unique_ptr<FramePipeline> pipeline_;
    // A grid's: the method's renderer (kept while method and oracle stay, for vissort's
    // coherence) and raycast's for the error map.
    std::unique_ptr<VolumeRenderer> volume_, volume_reference_;
    VolumeMethod volume_method_ = VolumeMethod::vissort;
    OracleKind volume_oracle_ = OracleKind::cpu;
    FrameDriver frames_; // positions only: the camera comes with each request
    std::thread thread_; // last: started once everything above exists
};

} // namespace vissort::viewer
