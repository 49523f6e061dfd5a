#pragma once
// Where the viewer's panel sits and how large its text is, for a window of a given size: a
// sidebar at the left, the full height, scaled with the window, and the scene drawn in the rest,
// so that the panel never covers the scene (at 800x600 a fixed 345-pixel panel hid 44% of it);
// and the scale of its frame-time plot, written on the plot.

#include <cstdint>
#include <span>
#include <string>

namespace vissort::viewer {

struct PanelLayout {
    float scale = 1;    // of Dear ImGui's default font and spacing
    uint32_t width = 0; // pixels from the window's left edge, the full height; 0: hidden
};

/// The panel for a window of this size: scaled as min(width / 1280, height / 800), held to 0.75
/// to 1.5, and 340 * scale pixels wide but at most 30% of the window's width. Hidden: width 0.
PanelLayout panelLayout(uint32_t window_width, uint32_t window_height, bool shown = true);

/// The width of the part of the window the scene is drawn in (at least 1 pixel): the window's
/// less the panel's.
uint32_t sceneWidth(uint32_t window_width, uint32_t window_height, bool panel_shown);

/// The frame-time plot's vertical axis: from 0 at the bottom to `top` ms (the largest of the
/// frames plotted and a tenth more, at least 1 ms), and the caption that says so with the last
/// frame's time: "0 to 146 ms; last 77.4 ms". frame_ms: oldest first, not empty.
struct PlotScale {
    float top = 1;
    std::string caption;
};
PlotScale frameTimePlotScale(std::span<const float> frame_ms);

} // namespace vissort::viewer
