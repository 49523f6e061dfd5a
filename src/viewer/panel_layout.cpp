// The viewer's panel layout (panel_layout.h).

#include "viewer/panel_layout.h"

#include <algorithm>
#include <cstdio>

namespace vissort::viewer {

PanelLayout panelLayout(uint32_t window_width, uint32_t window_height, bool shown) {
    constexpr float kWidthAtScaleOne = 340, kMostOfTheWidth = 0.3f;
    PanelLayout layout;
    layout.scale =
        std::clamp(std::min(float(window_width) / 1280, float(window_height) / 800), 0.75f, 1.5f);
    if (shown)
        layout.width = uint32_t(
            std::min(kWidthAtScaleOne * layout.scale, kMostOfTheWidth * float(window_width)));
    return layout;
}

uint32_t sceneWidth(uint32_t window_width, uint32_t window_height, bool panel_shown) {
    const uint32_t panel = panelLayout(window_width, window_height, panel_shown).width;
    return window_width > panel ? window_width - panel : 1;
}

PlotScale frameTimePlotScale(std::span<const float> frame_ms) {
    PlotScale scale;
    if (frame_ms.empty())
        return scale;
    scale.top = std::max(1.0f, *std::max_element(frame_ms.begin(), frame_ms.end()) * 1.1f);
    char caption[64];
    std::snprintf(caption, sizeof caption, "0 to %.0f ms; last %.1f ms", scale.top,
                  frame_ms.back());
    scale.caption = caption;
    return scale;
}

} // namespace vissort::viewer
