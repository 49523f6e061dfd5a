// The panel of a grid's window (volume_panel.h).

#include "viewer/volume_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "viewer/transfer_editing.h"
#include "vissort/atomic_file.h"

namespace vissort::viewer {
namespace {

constexpr const char* kEdited = "edited";

void drawGridFacts(const GridFacts& facts) {
    if (!ImGui::CollapsingHeader("Grid", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    ImGui::Text("%llu tetrahedra, %llu points", static_cast<unsigned long long>(facts.tets),
                static_cast<unsigned long long>(facts.points));
    ImGui::Text("scalar %.4g to %.4g", facts.scalar_min, facts.scalar_max);
    ImGui::Text("%llu boundary faces, %s", static_cast<unsigned long long>(facts.boundary_faces),
                facts.convex ? "convex" : "not convex");
}

// The transfer function over [first, last] scalar: its colour, and below it its colour weighted
// by its opacity over one unit of length at this density (what a cell a diagonal long shows).
void drawTransferStrip(const TransferFunction& tf, double density) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = std::max(ImGui::GetContentRegionAvail().x, 16.0f);
    const float height = 14 * ImGui::GetIO().FontGlobalScale;
    const double low = tf.normalized ? 0.0 : tf.points.front().scalar;
    const double high = tf.normalized ? 1.0 : tf.points.back().scalar;
    constexpr int kSteps = 64;
    for (int i = 0; i < kSteps; ++i) {
        const TransferPoint p = tf.at(low + (high - low) * (i + 0.5) / kSteps);
        const double alpha = 1 - std::exp(-density * p.extinction);
        const float x0 = origin.x + width * float(i) / kSteps;
        const float x1 = origin.x + width * float(i + 1) / kSteps;
        draw->AddRectFilled(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height),
                            ImColor(float(p.r), float(p.g), float(p.b)));
        draw->AddRectFilled(ImVec2(x0, origin.y + height), ImVec2(x1, origin.y + 2 * height),
                            ImColor(float(p.r * alpha), float(p.g * alpha), float(p.b * alpha)));
    }
    ImGui::Dummy(ImVec2(width, 2 * height));
}

// Writes tf beside the working directory's other outputs: vissort-tf-N.json, N the first free.
std::string saveTransferFunction(const TransferFunction& tf) {
    for (int n = 1;; ++n) {
        const std::string path = "vissort-tf-" + std::to_string(n) + ".json";
        if (std::filesystem::exists(path))
            continue;
        // Whole or not at all (atomic_file.h): never a half-written file another run then reads.
        const Status saved = writeFileAtomically(path, [&](const std::string& write_path) {
            std::ofstream out(write_path);
            out << transferFunctionJson(tf) << '\n';
            out.close();
            return out ? Status::ok() : Status::failure("cannot write " + path);
        });
        return saved ? path : std::string();
    }
}

bool drawTransferEditor(VolumeView& volume) {
    bool changed = false;
    TransferFunction& tf = volume.settings.transfer;
    if (ImGui::BeginCombo("preset", volume.tf_name.c_str())) {
        for (const TransferPreset& preset : transferPresets()) {
            const bool selected = volume.tf_name == preset.name;
            if (ImGui::Selectable(preset.name, selected) && !selected) {
                tf = *loadTransferFunction(preset.name).value;
                volume.tf_name = preset.name;
                changed = true;
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("%s", preset.description);
        }
        ImGui::EndCombo();
    }
    float density = float(volume.settings.density);
    if (ImGui::SliderFloat("density", &density, 0.01f, 100.0f, "%.3g",
                           ImGuiSliderFlags_Logarithmic)) {
        volume.settings.density = std::clamp(double(density), 0.0, 1e6);
        changed = true;
    }
    drawTransferStrip(tf, volume.settings.density);
    // Each point: its colour, scalar and extinction; + adds one after it, del removes it.
    bool edited = false;
    const float field_width = ImGui::GetContentRegionAvail().x * 0.3f;
    for (std::size_t i = 0; i < tf.points.size(); ++i) {
        ImGui::PushID(int(i));
        TransferPoint& point = tf.points[i];
        float colour[3] = {float(point.r), float(point.g), float(point.b)};
        if (ImGui::ColorEdit3("##colour", colour, ImGuiColorEditFlags_NoInputs)) {
            point.r = colour[0];
            point.g = colour[1];
            point.b = colour[2];
            edited = true;
        }
        ImGui::SameLine();
        ImGui::SetNextItemWidth(field_width);
        float scalar = float(point.scalar);
        if (ImGui::DragFloat("##scalar", &scalar, 0.002f, 0, 0, "s %.3f")) {
            moveTransferPoint(tf, i, double(scalar));
            edited = true;
        }
        ImGui::SameLine();
        ImGui::SetNextItemWidth(field_width);
        float extinction = float(point.extinction);
        if (ImGui::DragFloat("##extinction", &extinction, 0.01f, 0.0f, 1e4f, "e %.2f")) {
            point.extinction = extinction;
            edited = true;
        }
        clampTransferPoint(point);
        ImGui::SameLine();
        if (ImGui::SmallButton("+")) {
            insertTransferPoint(tf, i);
            edited = true;
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("del") && removeTransferPoint(tf, i))
            edited = true;
        ImGui::PopID();
    }
    if (edited)
        volume.tf_name = kEdited;
    if (ImGui::Button("Save as JSON")) {
        const std::string path = saveTransferFunction(tf);
        ImGui::OpenPopup(path.empty() ? "not saved" : "saved");
        volume.tf_name = path.empty() ? volume.tf_name : path;
    }
    if (ImGui::BeginPopup("saved")) {
        ImGui::Text("saved as %s (vissort volume --tf)", volume.tf_name.c_str());
        ImGui::EndPopup();
    }
    if (ImGui::BeginPopup("not saved")) {
        ImGui::Text("could not write the file here");
        ImGui::EndPopup();
    }
    return changed || edited;
}

void drawVolumeStatistics(const PanelState& state) {
    ImGui::Text("%.1f frames/s", state.fps);
    if (state.last == nullptr || !state.last->error.empty())
        return;
    const RenderStats& times = state.last->frame.stats;
    const VolumeFrameStats& s = state.last->volume_stats;
    ImGui::Text("frame %.1f ms: order %.1f, composite %.1f", times.total_ms, times.order_ms,
                times.render_ms);
    if (s.queries > 0 && s.cells > 0)
        ImGui::Text("%.2f queries a cell", double(s.queries) / double(s.cells));
    ImGui::Text("%llu cycles, %llu cells in them", static_cast<unsigned long long>(s.cycles),
                static_cast<unsigned long long>(s.cells_in_cycles));
    ImGui::Text("%.2fM segments, %.2fM in lists", double(s.segments) * 1e-6,
                double(s.list_segments) * 1e-6);
    if (state.last->frame.error)
        ImGui::Text("vs raycast: max %d/255, %llu pixels over 1/255",
                    state.last->frame.error->max_abs,
                    static_cast<unsigned long long>(state.last->frame.error->pixels_over_one));
}

} // namespace

PanelActions drawVolumePanel(const PanelState& state, VolumeView& volume, Overlays& overlays) {
    PanelActions actions;
    beginSidebar(state, actions);
    if (state.grid_facts != nullptr)
        drawGridFacts(*state.grid_facts);
    if (ImGui::CollapsingHeader("Rendering", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (ImGui::BeginCombo("method", volumeMethodName(volume.method))) {
            for (const EnumName<VolumeMethod>& entry : kVolumeMethodNames) {
                const bool selected = entry.value == volume.method;
                if (ImGui::Selectable(entry.name, selected) && !selected) {
                    volume.method = entry.value;
                    actions.settings_changed = true;
                }
            }
            ImGui::EndCombo();
        }
        float background[3] = {volume.settings.background.r, volume.settings.background.g,
                               volume.settings.background.b};
        if (ImGui::ColorEdit3("background", background)) {
            volume.settings.background = {background[0], background[1], background[2], 1.0f};
            actions.settings_changed = true;
        }
        actions.settings_changed |=
            ImGui::Checkbox("error map vs raycast (X)", &overlays.error_map);
    }
    if (ImGui::CollapsingHeader("Transfer function", ImGuiTreeNodeFlags_DefaultOpen))
        actions.settings_changed |= drawTransferEditor(volume);
    drawCameraSection(state, actions);
    if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) {
        drawVolumeStatistics(state);
        drawFrameTimePlot(state);
    }
    endSidebar();
    return actions;
}

} // namespace vissort::viewer
