// `vissort view`: the interactive viewer (src/viewer), parsed here and run there.

#include <iomanip>
#include <iostream>

#include "cli/commands.h"

#if VISSORT_WITH_VIEWER
#include "viewer/input_script.h"
#include "viewer/panel_layout.h"
#include "viewer/viewer.h"
#include "vissort/image.h"
#include "vissort/transparency_renderer.h"
#endif

namespace vissort::cli {

CLI::App* addViewCommand(CLI::App& app, ViewerOptions& options) {
    CLI::App* command = app.add_subcommand(
        "view", "Open a window on a scene: move around it, switch methods, watch the statistics");
#if VISSORT_WITH_VIEWER
    constexpr bool kWithViewer = true;
#else
    constexpr bool kWithViewer = false;
#endif
    // Without a viewer nothing is required: any `view ...` reaches runView's one-line error.
    command
        ->add_option("scene", options.scene, "Mesh file, JSON scene, or builtin:NAME?key=value&...")
        ->required(kWithViewer);
    addObjectsOption(*command, options.objects);
    options.view.size = "1024x768";
    addViewOptions(*command, options.view);
    addRendererOptions(*command, options.renderer, "The method shown first (1-7 switch)");
    command->add_option("--screenshot", options.screenshot,
                        "Save the window after the last frame (PNG) and exit: after --frames N, "
                        "or after the first frame without --frames");
    command->add_flag("--hide-ui", options.hide_ui, "No panel or overlay (nor in screenshots)");
    command->add_flag("--highlight-collisions", options.highlight_collisions,
                      "Draw the triangles that intersect another object's in magenta (K)");
    command->add_flag("--show-errors", options.show_errors,
                      "Show where the picture differs from linked-list's, yellow to red, "
                      "instead of the picture (X; the map of render --error-map)");
    command->add_option("--script", options.script,
                        "Replay input from a file: key presses, drags, wheel steps and resizes "
                        "at given frames (docs/viewer.md)");
    command->footer(
        "Without --frames (or --screenshot) the window stays until closed; with --frames N it\n"
        "renders N frames (each before the next is asked for, the script's events between\n"
        "them) and exits.\n"
        "Controls:\n"
        "  left drag        orbit about the target     right/middle drag  pan\n"
        "  wheel            zoom                       W/S  fly forward/back\n"
        "  A/D              fly left/right             Q/E  fly down/up\n"
        "  F                frame the scene            R    reset the camera\n"
        "  Space            play/pause                 P    screenshot (vissort-view-N.png)\n"
        "  1-7              vissort, unsorted, centroid, peel, dual-peel, linked-list, weighted\n"
        "  C                colour cycles              K    highlight collisions\n"
        "  X                error map against linked-list   Tab  hide/show the panel\n"
        "  H                help overlay               Escape  quit\n"
        "Needs a display: on a machine without one, run it under xvfb-run.");
    return command;
}

#if !VISSORT_WITH_VIEWER
int runView(const ViewerOptions&) {
    return failWithoutGl("view");
}
#else
namespace {

constexpr int kOpenEndedFrames = 300; // a window left open: the first 10 s of a dynamic scene

void printVec(const char* name, const Vec3& v) {
    std::cout << ' ' << name << ' ' << v.x << ',' << v.y << ',' << v.z;
}

} // namespace

int runView(const ViewerOptions& options) {
    if (options.scene.empty())
        return fail(kExitUsage, "view needs a scene (a mesh file, JSON scene or builtin:NAME)");
    viewer::ViewerSettings settings;
    if (std::string error = resolveRendererOptions(options.renderer, false, settings.render);
        !error.empty())
        return fail(kExitUsage, error);
    if (!options.screenshot.empty())
        if (const Result<ImageFormat> format = imageFormatOf(options.screenshot); !format)
            return fail(kExitUsage, "--screenshot: " + format.error);
    if (!options.script.empty()) {
        Result<std::vector<viewer::ScriptEvent>> script = viewer::loadInputScript(options.script);
        if (!script)
            return fail(kExitUsage, "--script: " + script.error);
        settings.script = std::move(*script.value);
    }
    if (Status display = viewer::checkDisplay(); !display)
        return fail(kExitFailure, display.error);
    std::optional<Scene> scene;
    ChosenView view;
    uint32_t window_width = 0, window_height = 0;
    if (auto error = parseSize(options.view.size, window_width, window_height); !error.empty())
        return fail(kExitUsage, error);
    // The camera frames the scene in the part of the window right of the panel; a window
    // without --frames runs on: a dynamic scene is framed over its first 10 s.
    ViewOptions framing = options.view;
    framing.size =
        std::to_string(viewer::sceneWidth(window_width, window_height, !options.hide_ui)) + "x" +
        std::to_string(window_height);
    if (!options.frames_given)
        framing.frames = kOpenEndedFrames;
    if (const int code = loadSceneAndView(options.scene, options.objects, framing, scene, view);
        code != kExitOk)
        return code;
    printRenderHeader(options.scene, *scene, settings.render, view);
    settings.title = "vissort view " + options.scene;
    settings.camera = view.camera;
    settings.path = view.path;
    settings.width = window_width;
    settings.height = window_height;
    // A screenshot is taken after the last frame: without --frames, the first.
    settings.frames = options.frames_given ? view.frames : options.screenshot.empty() ? 0 : 1;
    settings.screenshot = options.screenshot;
    settings.hide_ui = options.hide_ui;
    settings.overlays.highlight_collisions = options.highlight_collisions;
    settings.overlays.error_map = options.show_errors;
    Result<viewer::ViewerSummary> summary = viewer::runViewer(*scene, settings);
    if (!summary)
        return fail(kExitFailure, summary.error);
    const viewer::ViewerSummary& s = *summary.value;
    std::cout << s.frames << (s.frames == 1 ? " frame" : " frames") << " at " << s.width << 'x'
              << s.height << ", " << blendMethodName(s.render.method) << ", "
              << orderLevelName(s.render.level) << " level: median " << std::fixed
              << std::setprecision(1) << s.median_ms << " ms a frame, " << s.fps << " frames/s\n";
    std::cout << std::setprecision(9) << std::defaultfloat << "camera:";
    printVec("eye", s.camera.eye);
    printVec("target", s.camera.target);
    printVec("up", s.camera.up);
    std::cout << " fov " << s.camera.fov_degrees << '\n';
    if (s.overlays.highlight_collisions)
        std::cout << "collisions: " << s.colliding_pairs << " intersecting triangle pairs\n";
    if (s.difference)
        std::cout << "against linked-list: max abs " << s.difference->max_abs << "/255, "
                  << s.difference->pixels_over_one << " pixels off by more than 1\n";
    for (const std::string& path : s.screenshots)
        std::cout << path << ": screenshot\n";
    return kExitOk;
}
#endif

} // namespace vissort::cli
