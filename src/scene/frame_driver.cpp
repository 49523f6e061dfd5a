// The frames of a multi-frame run: positions at f * kFrameInterval, a camera on a path, its view.

#include "vissort/frame_driver.h"

#include <cassert>

namespace vissort {

FrameDriver::FrameDriver(const Scene& scene) : scene_(&scene) {}

FrameDriver::FrameDriver(const Scene& scene, const CameraSpec& base, CameraPath path,
                         uint32_t width, uint32_t height)
    : scene_(&scene), base_(base), path_(path), width_(width), height_(height), has_view_(true),
      first_bounds_(scene.positions.bounds()), camera_(base) {
    assert(width > 0 && height > 0);
}

void FrameDriver::seek(int frame) {
    assert(frame >= 0);
    frame_ = frame;
    if (scene_->isDynamic()) {
        scene_->frame(frame * kFrameInterval, buffer_);
        positions_ = buffer_.view();
    } else {
        positions_ = scene_->positions.view(); // static: every frame is t = 0
    }
    if (!has_view_)
        return;
    camera_ = cameraOnPath(base_, path_, frame, first_bounds_, scene_->camera_path);
    // A static scene's bounds are its first frame's: not walked again (9 ms a frame, the
    // power plant's 2.4M corners).
    view_ = frameCamera(camera_, scene_->isDynamic() ? positions_.bounds() : first_bounds_, width_,
                        height_);
}

} // namespace vissort
