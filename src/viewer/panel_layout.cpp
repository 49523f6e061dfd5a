// The viewer's panel layout (panel_layout.h).

#include "viewer/panel_layout.h"

#include <algorithm>

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

} // namespace vissort::viewer
