// `vissort view`: the interactive viewer (src/viewer), parsed here and run there.

#include <iomanip>
#include <iostream>

#include "cli/commands.h"
#include "cli/environment.h"

#if VISSORT_WITH_VIEWER
#include "cli/command_line_errors.h"
#include "cli/text_output.h"
#include "cli/volume_options.h"
#include "viewer/input_script.h"
#include "viewer/panel_layout.h"
#include "viewer/viewer.h"
#include "vissort/image.h"
#include "vissort/tet_grid.h"
#include "vissort/transparency_renderer.h"
#include "vissort/volume.h"
#endif

namespace vissort::cli {

CLI::App* addViewCommand(CLI::App& app, ViewerOptions& options) {
    CLI::App* command = app.add_subcommand(
        "view", "Open a window on a scene or a tetrahedral grid: move around it, switch methods, "
                "edit a grid's transfer function, watch the statistics");
#if VISSORT_WITH_VIEWER
    constexpr bool kWithViewer = true;
#else
    constexpr bool kWithViewer = false;
#endif
    // Without a viewer nothing is required: any `view ...` reaches runView's one-line error.
    command
        ->add_option("scene", options.scene,
                     "Mesh file, JSON scene, or builtin:NAME?key=value&...; or a grid (as "
                     "vissort volume takes it), rendered by the volume renderer")
        ->required(kWithViewer);
    addObjectsOption(*command, options.objects);
    addThreadsOption(*command);
    options.view.size = "1024x768";
    addViewOptions(*command, options.view);
    addRendererOptions(*command, options.renderer,
                       "The method shown first (1-7 switch); a grid's: vissort, centroid, mpvo, "
                       "lists or raycast (1-5 switch)");
    command
        ->add_option("--tf", options.tf,
                     "A grid's transfer function shown first: a preset (cool-warm, fire, grey, "
                     "bands) or a JSON file; edited in the panel (T: next preset)")
        ->capture_default_str();
    command
        ->add_option("--density", options.density,
                     "A grid's density, scaling every extinction (>= 0; [ and ] change it)")
        ->capture_default_str();
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
        "A grid's window: 1-5 vissort, centroid, mpvo, lists, raycast; T next transfer\n"
        "function preset; [ and ] density down and up; X error map against raycast; the\n"
        "panel edits the transfer function point by point and saves it as JSON.\n"
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

void printCamera(const CameraSpec& camera) {
    std::cout << std::setprecision(9) << std::defaultfloat << "camera:";
    printVec("eye", camera.eye);
    printVec("target", camera.target);
    printVec("up", camera.up);
    std::cout << " fov " << camera.fov_degrees << '\n';
}

// The first of names given on the command line, or empty.
std::string firstGiven(const ViewerOptions& options, std::initializer_list<const char*> names) {
    for (const char* name : names)
        if (options.given(name))
            return name;
    return {};
}

// The window's size and the camera's options framed for the part right of the panel; a window
// without --frames runs on: a dynamic scene is framed over its first 10 s.
std::string windowFraming(const ViewerOptions& options, uint32_t& width, uint32_t& height,
                          ViewOptions& framing) {
    if (std::string error = parseSize(options.view.size, width, height); !error.empty())
        return error;
    framing = options.view;
    framing.size = std::to_string(viewer::sceneWidth(width, height, !options.hide_ui)) + "x" +
                   std::to_string(height);
    if (!options.frames_given)
        framing.frames = kOpenEndedFrames;
    return {};
}

// What every window takes from the command line: the script, the screenshot, the frames.
std::string windowSettings(const ViewerOptions& options, viewer::ViewerSettings& settings) {
    if (!options.screenshot.empty())
        if (const Result<ImageFormat> format = imageFormatOf(options.screenshot); !format)
            return "--screenshot: " + format.error;
    if (!options.script.empty()) {
        Result<std::vector<viewer::ScriptEvent>> script = viewer::loadInputScript(options.script);
        if (!script)
            return "--script: " + script.error;
        settings.script = std::move(*script.value);
    }
    settings.screenshot = options.screenshot;
    settings.hide_ui = options.hide_ui;
    settings.overlays.error_map = options.show_errors;
    return {};
}

// windowSettings, a display, then windowFraming: kExitOk, else the code after the error.
int prepareWindow(const ViewerOptions& options, viewer::ViewerSettings& settings, uint32_t& width,
                  uint32_t& height, ViewOptions& framing) {
    if (const std::string error = windowSettings(options, settings); !error.empty())
        return fail(kExitUsage, error);
    if (Status display = viewer::checkDisplay(); !display)
        return fail(kExitFailure, display.error);
    if (const std::string error = windowFraming(options, width, height, framing); !error.empty())
        return fail(kExitUsage, error);
    return kExitOk;
}

void placeWindow(const ViewerOptions& options, const ChosenView& view, uint32_t width,
                 uint32_t height, viewer::ViewerSettings& settings) {
    settings.title = "vissort view " + options.scene;
    settings.camera = view.camera;
    settings.path = view.path;
    settings.width = width;
    settings.height = height;
    // A screenshot is taken after the last frame: without --frames, the first.
    settings.frames = options.frames_given ? view.frames : options.screenshot.empty() ? 0 : 1;
}

// `view GRID`: the volume renderer in the window, the transfer function in the panel.
int runGridView(const ViewerOptions& options) {
    if (const std::string scene_option =
            firstGiven(options, {"--objects", "--level", "--all-transparent", "--alpha",
                                 "--shading", "--samples", "--check", "--list-memory",
                                 "--colour-cycles", "--highlight-collisions"});
        !scene_option.empty())
        return fail(kExitUsage, scene_option + " is a scene's option; " + options.scene +
                                    " is a grid (its options: --method, --oracle, --tf, "
                                    "--density, --background, --show-errors)");
    viewer::ViewerSettings settings;
    viewer::VolumeView volume;
    const Result<VolumeMethod> method = parseVolumeMethod(options.renderer.method);
    if (!method)
        return fail(kExitUsage, "--method " + method.error);
    const Result<OracleKind> oracle = parseOracleKind(options.renderer.oracle);
    if (!oracle)
        return fail(kExitUsage, "--oracle " + oracle.error);
    volume.method = *method.value;
    volume.oracle = *oracle.value;
    volume.tf_name = options.tf;
    if (const std::string error = resolveVolumeSettings(
            options.tf, options.density, options.renderer.background, volume.settings);
        !error.empty())
        return fail(kExitUsage, error);
    uint32_t width = 0, height = 0;
    ViewOptions framing;
    if (const int code = prepareWindow(options, settings, width, height, framing); code != kExitOk)
        return code;
    Result<TetGrid> grid = loadGrid(options.scene);
    if (!grid)
        return fail(kExitInput, grid.error);
    if (Status valid = validateVolumeSettings(*grid.value, volume.settings); !valid)
        return fail(kExitInput, valid.error);
    const Scene boundary = boundaryScene(*grid.value);
    ChosenView view;
    if (const std::string error = resolveView(framing, boundary, view); !error.empty())
        return fail(kExitUsage, error);
    std::cout << "grid: " << grid.value->name << ", "
              << counted(grid.value->tets.size(), "tetrahedron", "tetrahedra") << '\n'
              << cameraLine(view) << '\n';
    placeWindow(options, view, width, height, settings);
    settings.volume = volume;
    Result<viewer::ViewerSummary> summary =
        viewer::runVolumeViewer(*grid.value, boundary, settings);
    if (!summary)
        return fail(kExitFailure, summary.error);
    const viewer::ViewerSummary& s = *summary.value;
    const viewer::VolumeView& last = s.volume ? *s.volume : volume;
    std::cout << s.frames << (s.frames == 1 ? " frame" : " frames") << " at " << s.width << 'x'
              << s.height << ", " << volumeMethodName(last.method) << ", tf " << last.tf_name
              << ", density " << formatNumber(last.settings.density) << ": median " << std::fixed
              << std::setprecision(1) << s.median_ms << " ms a frame, " << s.fps << " frames/s\n";
    printCamera(s.camera);
    if (s.difference)
        std::cout << "against raycast: max abs " << s.difference->max_abs << "/255, "
                  << s.difference->pixels_over_one << " pixels off by more than 1\n";
    for (const std::string& path : s.screenshots)
        std::cout << path << ": screenshot\n";
    return kExitOk;
}

} // namespace

int runView(const ViewerOptions& options) {
    if (options.scene.empty())
        return fail(kExitUsage, "view needs a scene (a mesh file, JSON scene or builtin:NAME)");
    if (isGridSpec(options.scene))
        return runGridView(options);
    if (const std::string grid_option = firstGiven(options, {"--tf", "--density"});
        !grid_option.empty())
        return fail(kExitUsage, grid_option + " is a grid's option; " + options.scene +
                                    " is a scene (vissort view GRID takes it)");
    viewer::ViewerSettings settings;
    if (std::string error = resolveRendererOptions(options.renderer, false, settings.render);
        !error.empty())
        return fail(kExitUsage, error);
    uint32_t window_width = 0, window_height = 0;
    ViewOptions framing;
    if (const int code = prepareWindow(options, settings, window_width, window_height, framing);
        code != kExitOk)
        return code;
    std::optional<Scene> scene;
    ChosenView view;
    if (const int code = loadSceneAndView(options.scene, options.objects, framing, scene, view);
        code != kExitOk)
        return code;
    printRenderHeader(options.scene, *scene, settings.render, view);
    placeWindow(options, view, window_width, window_height, settings);
    settings.overlays.highlight_collisions = options.highlight_collisions;
    Result<viewer::ViewerSummary> summary = viewer::runViewer(*scene, settings);
    if (!summary)
        return fail(kExitFailure, summary.error);
    const viewer::ViewerSummary& s = *summary.value;
    std::cout << s.frames << (s.frames == 1 ? " frame" : " frames") << " at " << s.width << 'x'
              << s.height << ", " << blendMethodName(s.render.method) << ", "
              << orderLevelName(s.render.level) << " level: median " << std::fixed
              << std::setprecision(1) << s.median_ms << " ms a frame, " << s.fps << " frames/s\n";
    printCamera(s.camera);
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
