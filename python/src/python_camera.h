#pragma once
// The Python Camera: a CameraSpec and, for an orthographic camera made with a scene, the bounds
// it frames (otherwise each call frames the positions it is given, as the command line frames
// each frame's own bounds).

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

#include <pybind11/pybind11.h>

#include "vissort/camera.h"
#include "vissort/scene.h"

namespace vissort::python {

struct PythonCamera {
    CameraSpec spec;
    std::optional<Bounds> framed_bounds;
};

/// The camera the command line uses when none is asked for (chooseView with nothing asked):
/// the scene's own (a mesh file's first usable camera), else its geometry framed for a width x
/// height image over `frames` frames. ValueError for frames out of range.
PythonCamera defaultCameraOf(const Scene& scene, uint32_t width, uint32_t height, int frames = 1);

/// The camera a call uses: `camera` (a vissort.Camera; ValueError for anything else but None),
/// else the scene's default camera over its first 300 frames (kept for the next call of the same
/// scene and size: a dynamic scene's is framed over sampled frames of its motion, not free), else
/// the positions framed (framingCamera). Needs the GIL.
class CameraChoice {
public:
    PythonCamera choose(const pybind11::handle& camera, const std::shared_ptr<Scene>& scene,
                        PositionsView positions, uint32_t width, uint32_t height);

private:
    std::shared_ptr<Scene> scene_;
    std::pair<uint32_t, uint32_t> size_;
    PythonCamera camera_;
};

/// The view through camera of a width x height image, framing positions' bounds (or the
/// camera's own).
ViewProjection viewOf(const PythonCamera& camera, PositionsView positions, uint32_t width,
                      uint32_t height);

} // namespace vissort::python
