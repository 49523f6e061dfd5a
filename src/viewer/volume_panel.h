#pragma once
// The panel of a grid's window (`vissort view GRID`): the grid's facts, the volume method, the
// transfer function (a preset, or edited point by point: scalar, colour, extinction, with a
// strip showing it) and the density, the error map against raycast, and the frame's costs.
// Drawn between ImGui::NewFrame and ImGui::Render, like viewer_panel.h's.

#include "viewer/render_worker.h"
#include "viewer/viewer_panel.h"

namespace vissort::viewer {

/// The sidebar for a grid (state.grid_facts set); volume and overlays are edited in place.
/// "Save" writes the transfer function as JSON (vissort-tf-N.json, for `vissort volume --tf`).
PanelActions drawVolumePanel(const PanelState& state, VolumeView& volume, Overlays& overlays);

} // namespace vissort::viewer
