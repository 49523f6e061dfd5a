// The viewer's panel (viewer_panel.h).

#include "viewer/viewer_panel.h"

#include <imgui.h>

#include <algorithm>
#include <iterator>
#include <numeric>
#include <string>

namespace vissort::viewer {
namespace {

// A combo over an enum's names; true when the choice changed.
template <class Enum, std::size_t N>
bool enumCombo(const char* label, const EnumName<Enum> (&names)[N], Enum& value) {
    bool changed = false;
    if (ImGui::BeginCombo(label, enumName<Enum>(names, value))) {
        for (const EnumName<Enum>& entry : names) {
            const bool selected = entry.value == value;
            if (ImGui::Selectable(entry.name, selected) && !selected) {
                value = entry.value;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

// Samples a pixel, from kSampleGrids.
bool samplesCombo(uint32_t& samples) {
    bool changed = false;
    if (ImGui::BeginCombo("samples", std::to_string(samples).c_str())) {
        for (const SampleGrid& grid : kSampleGrids) {
            const bool selected = grid.samples() == samples;
            if (ImGui::Selectable(std::to_string(grid.samples()).c_str(), selected) && !selected) {
                samples = grid.samples();
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

} // namespace

PanelActions drawPanel(const PanelState& state, RenderSettings& settings, Overlays& overlays) {
    PanelActions actions;
    beginSidebar(state, actions);
    const Scene& scene = *state.scene;
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) {
        // As drawn: "all transparent" counts every object.
        std::size_t transparent = 0, transparent_triangles = 0;
        for (const SceneObject& object : scene.objects)
            if (drawnTransparent(object, settings)) {
                ++transparent;
                transparent_triangles += object.triangle_count;
            }
        ImGui::TextWrapped("%s", scene.name.c_str());
        ImGui::Text("%zu objects, %zu transparent", scene.objects.size(), transparent);
        ImGui::Text("%zu triangles, %zu transparent", scene.triangleCount(), transparent_triangles);
        if (*state.complexity)
            ImGui::Text("depth complexity: max %llu, mean %.2f",
                        static_cast<unsigned long long>((*state.complexity)->max),
                        (*state.complexity)->mean);
        if (ImGui::Button("Measure depth complexity (this view)"))
            actions.measure_complexity = true;
    }
    if (ImGui::CollapsingHeader("Rendering", ImGuiTreeNodeFlags_DefaultOpen)) {
        actions.settings_changed |= enumCombo("method", kBlendMethodNames, settings.method);
        actions.settings_changed |= enumCombo("level", kOrderLevelNames, settings.level);
        actions.settings_changed |= enumCombo("oracle", kOracleKindNames, settings.oracle);
        actions.settings_changed |= ImGui::Checkbox("all transparent", &settings.all_transparent);
        if (settings.all_transparent) {
            float alpha = settings.alpha;
            if (ImGui::SliderFloat("alpha", &alpha, 0.01f, 1.0f, "%.2f")) {
                settings.alpha = std::clamp(alpha, 0.01f, 1.0f);
                actions.settings_changed = true;
            }
        }
        actions.settings_changed |= enumCombo("shading", kShadingNames, settings.shading);
        float background[3] = {settings.background.r, settings.background.g, settings.background.b};
        if (ImGui::ColorEdit3("background", background)) {
            settings.background = {background[0], background[1], background[2], 1.0f};
            actions.settings_changed = true;
        }
        actions.settings_changed |= samplesCombo(settings.samples);
        actions.settings_changed |= enumCombo("check", kOrderCheckNames, settings.check);
    }
    if (ImGui::CollapsingHeader("Show", ImGuiTreeNodeFlags_DefaultOpen)) {
        actions.settings_changed |= ImGui::Checkbox("colour cycles (C)", &settings.colour_cycles);
        if (settings.colour_cycles && settings.method != BlendMethod::vissort) {
            ImGui::SameLine();
            ImGui::TextDisabled("(vissort only)");
        }
        // Levels of detail (docs/lod.md): 0 draws every triangle. The levels are built once, when
        // first asked for, and kept for the window's life.
        actions.settings_changed |=
            ImGui::SliderFloat("level of detail (px)", &settings.lod_error, 0.0f, 16.0f, "%.2f");
        settings.lod_error = std::clamp(settings.lod_error, 0.0f, 16.0f);
        actions.settings_changed |=
            ImGui::Checkbox("colliding triangles (K)", &overlays.highlight_collisions);
        actions.settings_changed |=
            ImGui::Checkbox("error map vs linked-list (X)", &overlays.error_map);
        if (overlays.error_map)
            ImGui::TextDisabled("grey: within 1/255; yellow 2/255 to red 64/255");
    }
    drawCameraSection(state, actions);
    if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("%.1f frames/s", state.fps);
        if (state.last != nullptr && state.last->error.empty()) {
            const RenderStats& stats = state.last->frame.stats;
            ImGui::Text("frame %.1f ms: order %.1f, render %.1f", stats.total_ms, stats.order_ms,
                        stats.render_ms);
            ImGui::Text("%llu queries, %u iterations",
                        static_cast<unsigned long long>(stats.order.queries),
                        stats.order.iterations);
            ImGui::Text("%u %s, %u %s per pixel (cycles)", stats.passes,
                        stats.passes == 1 ? "pass" : "passes", stats.groups,
                        stats.groups == 1 ? "group" : "groups");
            ImGui::Text("%llu pixels repaired",
                        static_cast<unsigned long long>(stats.repaired_pixels));
            if (settings.lod_error > 0)
                ImGui::Text("%llu triangles drawn, %u boxes, %u out of view",
                            static_cast<unsigned long long>(stats.triangles), stats.boxed_objects,
                            stats.culled_objects);
            const RenderedFrame& last = *state.last;
            if (last.request.overlays.highlight_collisions)
                ImGui::Text("collisions: %llu pairs, %llu triangles, %.1f ms",
                            static_cast<unsigned long long>(last.frame.colliding_pairs),
                            static_cast<unsigned long long>(last.frame.colliding_triangles),
                            last.frame.collision_ms);
            if (last.frame.error)
                ImGui::Text("vs linked-list: max %d/255, %llu pixels over 1/255",
                            last.frame.error->max_abs,
                            static_cast<unsigned long long>(last.frame.error->pixels_over_one));
        }
        drawFrameTimePlot(state);
    }
    endSidebar();
    return actions;
}

void beginSidebar(const PanelState& state, PanelActions& actions) {
    // A sidebar: the scene is drawn right of it (panel_layout.h), so it never covers the scene.
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(float(state.layout.width), ImGui::GetIO().DisplaySize.y),
                             ImGuiCond_Always);
    ImGui::Begin("vissort", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    if (ImGui::Button("Hide panel (Tab)"))
        actions.hide_panel = true;
}

void drawCameraSection(const PanelState& state, PanelActions& actions) {
    if (!ImGui::CollapsingHeader("Camera and time", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    if (ImGui::Button(state.playing ? "Pause (Space)" : "Play (Space)"))
        actions.toggle_play = true;
    ImGui::SameLine();
    ImGui::Text("frame %d", state.frame);
    if (ImGui::Button("Frame scene (F)"))
        actions.frame_scene = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)"))
        actions.reset_camera = true;
    ImGui::SameLine();
    if (ImGui::Button("Screenshot (P)"))
        actions.screenshot = true;
}

void drawFrameTimePlot(const PanelState& state) {
    if (state.frame_ms.empty())
        return;
    // The plot's scale on it: the axis runs from 0 at the bottom to `top` at the top.
    const PlotScale scale = frameTimePlotScale(state.frame_ms);
    ImGui::PlotLines("ms", state.frame_ms.data(), int(state.frame_ms.size()), 0,
                     scale.caption.c_str(), 0.0f, scale.top, ImVec2(0, 60));
}

void endSidebar() {
    ImGui::TextDisabled("H: help");
    ImGui::End();
}

bool drawShowPanelButton() {
    ImGui::SetNextWindowPos(ImVec2(4, 4), ImGuiCond_Always);
    ImGui::Begin("show panel", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoMove);
    const bool pressed = ImGui::Button("Panel (Tab)");
    ImGui::End();
    return pressed;
}

void drawHelpOverlay() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Controls", nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    static constexpr const char* kLines[][2] = {
        {"left drag", "orbit about the target"},
        {"right or middle drag", "pan"},
        {"wheel", "zoom"},
        {"W / S", "fly forward / back"},
        {"A / D", "fly left / right"},
        {"Q / E", "fly down / up"},
        {"F", "frame the scene"},
        {"R", "reset the camera"},
        {"Space", "play / pause"},
        {"1 to 7", "vissort, unsorted, centroid, peel, dual-peel, linked-list, weighted"},
        {"1 to 5 (a grid)", "vissort, centroid, mpvo, lists, raycast"},
        {"T (a grid)", "next transfer function preset"},
        {"[ / ] (a grid)", "density down / up"},
        {"C", "colour the cycles of vissort's order"},
        {"K", "highlight colliding triangles"},
        {"X", "error map against linked-list (a grid: raycast)"},
        {"P", "screenshot (vissort-view-N.png)"},
        {"H", "this help"},
        {"Tab", "hide / show the panel"},
        {"Escape", "quit"},
    };
    for (const auto& line : kLines) {
        ImGui::Text("%-22s", line[0]);
        ImGui::SameLine();
        ImGui::TextUnformatted(line[1]);
    }
    ImGui::End();
}

} // namespace vissort::viewer
