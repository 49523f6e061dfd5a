#pragma once
// The frames of a multi-frame run, in one place for every command and benchmark: frame f of a
// dynamic scene is at time t = f * kFrameInterval, and its camera is the base camera moved along a
// path (turning about the first frame's bounds) and framed to the frame's own bounds.
//
// Layer: vissort::scene (the package's `scene` component; docs/architecture.md).

#include <cstdint>

#include "vissort/camera.h"
#include "vissort/camera_path.h"
#include "vissort/geometry.h"
#include "vissort/scene.h"

namespace vissort {

class FrameDriver {
public:
    /// Positions only, no camera (collision detection): view() must not be called.
    /// scene must outlive the driver.
    explicit FrameDriver(const Scene& scene);
    /// Positions and the view of a width x height image from base moved along path.
    /// scene must outlive the driver; width and height must be positive.
    FrameDriver(const Scene& scene, const CameraSpec& base, CameraPath path, uint32_t width,
                uint32_t height);

    /// Moves to frame `frame` (>= 0, in any order): its positions, camera and view.
    void seek(int frame);

    /// The current frame's index and time (seconds); -1 and 0 before the first seek.
    int frame() const { return frame_; }
    double time() const { return frame_ < 0 ? 0.0 : frame_ * kFrameInterval; }
    /// The current frame's world-space positions: a static scene's own, without a copy, or a
    /// buffer reused from frame to frame; valid until the next seek.
    PositionsView positions() const { return positions_; }
    /// The current frame's camera (the base one moved along the path) and its framed view.
    const CameraSpec& camera() const { return camera_; }
    const ViewProjection& view() const { return view_; }
    bool hasView() const { return has_view_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

private:
    const Scene* scene_;
    CameraSpec base_;
    CameraPath path_ = CameraPath::fixed;
    uint32_t width_ = 0, height_ = 0;
    bool has_view_ = false;
    Bounds first_bounds_; // the path turns about the scene at t = 0, the same every frame
    int frame_ = -1;
    TrianglePositions buffer_; // a dynamic scene's positions, reused
    PositionsView positions_;
    CameraSpec camera_;
    ViewProjection view_;
};

} // namespace vissort
