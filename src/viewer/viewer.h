#pragma once
// `vissort view`: a window showing a scene rendered by the transparency renderer (the same pixels
// `vissort render` writes for the same camera and size), or a tetrahedral grid by the volume
// renderer (the pixels of `vissort volume`), moved with the mouse and keys, with a panel of
// settings and live statistics (Dear ImGui); a grid's panel edits its transfer function. GLFW makes
// the window and its OpenGL context on the calling thread; a RenderWorker renders on its own thread
// through the headless context, so input is handled while a slow frame renders.
//
// Controls (also in `vissort view --help` and the help overlay, H):
//   left drag: orbit about the target      right or middle drag: pan       wheel: zoom
//   W/S: fly forward/back   A/D: left/right   Q/E: down/up   F: frame the scene   R: reset camera
//   Space: play/pause       1-7: method (vissort, unsorted, centroid, peel, dual-peel,
//   linked-list, weighted)  C: colour cycles  K: highlight collisions  X: error map against
//   linked-list             P: screenshot     H: help overlay      Tab: hide/show the panel
//   Escape: quit
// A grid's window: 1-5 method (vissort, centroid, mpvo, lists, raycast), T: next transfer
// function preset, [ and ]: density down and up (by 1.5x), X: error map against raycast; C and K
// do nothing.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "viewer/input_script.h"
#include "viewer/render_worker.h"
#include "vissort/camera.h"
#include "vissort/camera_path.h"
#include "vissort/result.h"
#include "vissort/scene.h"
#include "vissort/transparency_renderer.h"

namespace vissort::viewer {

struct ViewerSettings {
    std::string title = "vissort";
    RenderSettings render;
    Overlays overlays; // collisions and the error map at the start (K and X toggle them)
    CameraSpec camera; // the start camera, as `render` resolves it; R comes back to it
    CameraPath path = CameraPath::fixed;
    uint32_t width = 1024, height = 768; // the window's size
    int frames = 0;         // 0: until the window closes; N: render N frames, then close
    std::string screenshot; // with frames: where the last frame is saved (PNG)
    bool hide_ui = false;   // no panel (and no help overlay) in the window or the screenshot
    std::vector<ScriptEvent> script;  // input replayed (input_script.h)
    std::optional<VolumeView> volume; // runVolumeViewer's start settings
};

/// What a run of the viewer did.
struct ViewerSummary {
    int frames = 0;                 // frames rendered
    double median_ms = 0;           // per frame, ordering and rendering (the renderer's total)
    double fps = 0;                 // frames rendered per second of the window's life
    CameraSpec camera;              // the camera of the last frame
    RenderSettings render;          // the settings of the last frame
    uint32_t width = 0, height = 0; // the last frame's size
    Overlays overlays;              // those of the last frame
    uint64_t colliding_pairs = 0;   // the last frame's, with highlight_collisions
    std::optional<ImageError> difference; // the last frame's, with error_map
    std::vector<std::string> screenshots; // files written (the final one and P presses)
    std::optional<VolumeView> volume;     // a grid's: the last frame's settings
    VolumeFrameStats volume_stats;        // ... and counts
};

/// Whether a display is named to open windows on (X11 or Wayland), without connecting to it: a
/// caller can say that `view` needs one (pointing to `xvfb-run` and `vissort render`) before
/// loading a scene.
Status checkDisplay();

/// Opens the window and runs until it is closed (or settings.frames are rendered). Errors: no
/// display to connect to (the same advice as checkDisplay's), no OpenGL context for the window,
/// a frame the renderer could not render, a screenshot that could not be written; each one line.
Result<ViewerSummary> runViewer(const Scene& scene, const ViewerSettings& settings);

/// The same for a grid rendered by the volume renderer from settings.volume (required), the
/// camera framed on its boundary (boundaryScene(grid)); both must outlive the call. The panel
/// edits the method, the transfer function and the density.
Result<ViewerSummary> runVolumeViewer(const TetGrid& grid, const Scene& boundary,
                                      const ViewerSettings& settings);

} // namespace vissort::viewer
