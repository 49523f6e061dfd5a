#pragma once
// The viewer's panel and help overlay (Dear ImGui): scene facts, the renderer's settings, live
// statistics with a frame-time plot, and the controls. Drawn between ImGui::NewFrame and
// ImGui::Render; reads the viewer's state and returns what the user asked for.

#include <optional>
#include <span>

#include "viewer/panel_layout.h"
#include "viewer/render_worker.h"
#include "vissort/depth_complexity.h"
#include "vissort/scene.h"
#include "vissort/tet_grid.h"
#include "vissort/transparency_renderer.h"

namespace vissort::viewer {

struct PanelState {
    PanelLayout layout; // where it sits (panel_layout.h)
    const Scene* scene = nullptr;
    const RenderedFrame* last = nullptr; // the frame on screen, if any
    std::span<const float> frame_ms;     // recent frames' total ms, oldest first
    double fps = 0;                      // frames rendered per second, recently
    int frame = 0;                       // the animation frame
    bool playing = false;
    const std::optional<DepthComplexity>* complexity = nullptr; // measured on demand
    const GridFacts* grid_facts = nullptr;                      // a grid's window: its facts
};

struct PanelActions {
    bool settings_changed = false;
    bool toggle_play = false;
    bool reset_camera = false;
    bool frame_scene = false;
    bool measure_complexity = false;
    bool screenshot = false;
    bool hide_panel = false;
};

/// The panel as a sidebar at the window's left (state.layout); settings and overlays are edited
/// in place.
PanelActions drawPanel(const PanelState& state, RenderSettings& settings, Overlays& overlays);

/// The sections every window's panel has, for volume_panel.cpp: the sidebar's window begun
/// (with its hide button), the camera and time buttons, the frame-time plot, and the end of the
/// sidebar with the help hint.
void beginSidebar(const PanelState& state, PanelActions& actions);
void drawCameraSection(const PanelState& state, PanelActions& actions);
void drawFrameTimePlot(const PanelState& state);
void endSidebar();

/// While the panel is hidden: a small button at the top-left that shows it again; true when
/// pressed.
bool drawShowPanelButton();

/// The controls, centred.
void drawHelpOverlay();

} // namespace vissort::viewer
