// vissort volume: a tetrahedral grid's picture by emission and absorption (docs/volume.md).
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/colour_options.h"
#include "cli/command_line_errors.h"
#include "cli/commands.h"
#include "cli/json_output.h"
#include "cli/output_paths.h"
#include "cli/progress.h"
#include "cli/text_output.h"
#include "cli/volume_options.h"
#include "harnesses/volume_comparison.h"
#include "vissort/output_files.h"
#include "vissort/volume.h"

namespace vissort::cli {

CLI::App* addVolumeCommand(CLI::App& app, VolumeOptions& options) {
    CLI::App* command = app.add_subcommand(
        "volume",
        "Render a tetrahedral grid's scalar field by emission and absorption (docs/volume.md)");
    command
        ->add_option("grid", options.grid,
                     "Grid file (.vtk, .vtu, tetgen .node/.ele, Medit .mesh) or builtin:cube, "
                     "builtin:torus, builtin:knot (?n=CELLS per side)")
        ->required();
    command
        ->add_option("-o,--output", options.output,
                     "The picture: .png or .jpg; with --frames a pattern such as frame_%04d.png")
        ->required();
    command
        ->add_option("--tf", options.tf,
                     "Transfer function: a preset (cool-warm, fire, grey, bands) or a JSON file "
                     "(docs/volume.md)")
        ->capture_default_str();
    command->add_option("--density", options.density, "Scales every extinction (>= 0)")
        ->capture_default_str();
    command
        ->add_option("--method", options.method,
                     "vissort (exact: Vis-sort's order of cells, cycles per pixel), centroid (cell "
                     "centres, as VTK), mpvo (Williams' face adjacency), lists (per-pixel lists: "
                     "exact), raycast (cell-walking rays: exact, the reference), or all (one "
                     "picture of every method and its error against raycast)")
        ->capture_default_str();
    command
        ->add_option("--oracle", options.oracle,
                     "vissort's oracle: cpu, cpu-reference, exact or gl")
        ->capture_default_str();
    command->add_option("--background", options.background,
                        "The background: R,G,B or R,G,B,A (each in [0, 1]) or #RRGGBB (default " +
                            backgroundText(kDefaultBackground) + ")");
    command->add_option("--reference", options.reference,
                        "Compare every frame with this method's picture and report the error "
                        "(raycast is exact)");
    command->add_option("--error-map", options.error_map,
                        "With --reference: where each frame's error map goes (a pattern with "
                        "--frames)");
    addViewOptions(*command, options.view);
    addJsonOptions(*command, options.json,
                   "Write the run as JSON: grid, method, camera and per frame its file, times, "
                   "counts and error (docs/cli.md)");
    return command;
}

namespace {

nlohmann::json statsJson(const VolumeFrameStats& s) {
    return {{"order_ms", s.order_ms}, {"composite_ms", s.composite_ms},
            {"cells", s.cells},       {"queries", s.queries},
            {"cycles", s.cycles},     {"cells_in_cycles", s.cells_in_cycles},
            {"segments", s.segments}, {"list_segments", s.list_segments}};
}

nlohmann::json errorJson(const ImageError& error, const std::string& reference) {
    return {{"max_abs", error.max_abs},
            {"pixels_over_one", error.pixels_over_one},
            {"rmse", error.rmse},
            {"reference", reference}};
}

int writeComparison(const VolumeOptions& options, const TetGrid& grid,
                    const VolumeSettings& settings, const ViewProjection& view, OracleKind oracle) {
    Result<bench::VolumeComparison> comparison =
        bench::compareVolumeMethods(grid, settings, view, oracle);
    if (!comparison)
        return fail(kExitInput, comparison.error);
    const samples::Strip& strip = comparison.value->strip;
    if (Status written = writeImage(options.output, strip.width, strip.height, strip.rgba);
        !written)
        return fail(kExitFailure, written.error);
    nlohmann::json methods = nlohmann::json::array();
    for (const bench::VolumePicture& p : comparison.value->methods) {
        std::cout << "  " << volumeMethodName(p.method) << ": "
                  << formatNumber(p.stats.order_ms + p.stats.composite_ms) << " ms, max error "
                  << p.error.max_abs << "/255, " << p.error.pixels_over_one
                  << " pixels over 1/255\n";
        nlohmann::json record = statsJson(p.stats);
        record["method"] = volumeMethodName(p.method);
        record["error"] = errorJson(p.error, "raycast");
        methods.push_back(std::move(record));
    }
    std::cout << options.output
              << ": every method (top) and its error against raycast (below: grey "
              << "within 1/255, yellow to red beyond)\n";
    if (options.json.path.empty())
        return kExitOk;
    return writeJsonFile(options.json,
                         {{"grid", grid.name}, {"method", "all"}, {"methods", methods}});
}

} // namespace

int runVolume(const VolumeOptions& options) {
    const bool all = options.method == "all";
    Result<VolumeMethod> method =
        all ? Result<VolumeMethod>{VolumeMethod::vissort, {}} : parseVolumeMethod(options.method);
    if (!method)
        return fail(kExitUsage, "--method " + method.error + " or all");
    Result<VolumeMethod> reference =
        parseVolumeMethod(options.reference.empty() ? "raycast" : options.reference);
    if (!reference)
        return fail(kExitUsage, "--reference " + reference.error);
    if (!options.error_map.empty() && options.reference.empty())
        return fail(kExitUsage,
                    "--error-map needs --reference (the method the error is measured against)");
    Result<OracleKind> oracle = parseOracleKind(options.oracle);
    if (!oracle)
        return fail(kExitUsage, "--oracle " + oracle.error);
    VolumeSettings settings;
    if (const std::string error =
            resolveVolumeSettings(options.tf, options.density, options.background, settings);
        !error.empty())
        return fail(kExitUsage, error);
    if (all && options.view.frames > 1)
        return fail(kExitUsage, "--method all draws one frame: leave out --frames");
    for (const auto& [option, path] :
         {std::pair{"-o", &options.output}, {"--error-map", &options.error_map}}) {
        if (path->empty())
            continue;
        if (options.view.frames > 1 && !isFramePattern(*path))
            return fail(kExitUsage, std::string("with --frames, ") + option +
                                        " needs one %d (such as frame_%04d.png), got '" + *path +
                                        "'");
        if (Result<ImageFormat> format = imageFormatOf(*path); !format)
            return fail(kExitUsage, format.error);
    }

    Result<TetGrid> grid = loadGrid(options.grid);
    if (!grid)
        return fail(kExitInput, grid.error);
    if (Status valid = validateVolumeSettings(*grid.value, settings); !valid)
        return fail(kExitInput, valid.error);
    const Scene boundary = boundaryScene(*grid.value);
    ChosenView view;
    if (const std::string error = resolveView(options.view, boundary, view); !error.empty())
        return fail(kExitUsage, error);
    const Bounds bounds = boundary.positions.bounds();
    std::cout << "grid: " << grid.value->name << ", "
              << counted(grid.value->tets.size(), "tetrahedron", "tetrahedra") << '\n'
              << cameraLine(view) << '\n';
    if (all)
        return writeComparison(options, *grid.value, settings,
                               frameCamera(view.camera, bounds, view.width, view.height),
                               *oracle.value);

    VolumeRenderer renderer(*grid.value, *method.value, *oracle.value);
    std::optional<VolumeRenderer> reference_renderer;
    if (!options.reference.empty())
        reference_renderer.emplace(*grid.value, *reference.value, *oracle.value);
    nlohmann::json frames = nlohmann::json::array();
    Progress progress("volume", uint64_t(view.frames), "frame");
    int worst_error = 0;
    for (int f = 0; f < view.frames; ++f) {
        const CameraSpec camera = cameraOnPath(view.camera, view.path, f, bounds);
        const ViewProjection projection = frameCamera(camera, bounds, view.width, view.height);
        Result<Image> image = renderer.render(settings, projection);
        if (!image)
            return fail(kExitFailure, image.error);
        const std::vector<uint8_t> rgba = image.value->toRgba8();
        const std::string path =
            isFramePattern(options.output) ? framePath(options.output, f) : options.output;
        if (Status written = writeImage(path, image.value->width, image.value->height, rgba);
            !written)
            return fail(kExitFailure, written.error);
        const VolumeFrameStats& stats = renderer.stats();
        nlohmann::json record = statsJson(stats);
        record["frame"] = f;
        record["file"] = path;
        std::string error_text;
        if (reference_renderer) {
            Result<Image> truth = reference_renderer->render(settings, projection);
            if (!truth)
                return fail(kExitFailure, truth.error);
            const std::vector<uint8_t> truth_rgba = truth.value->toRgba8();
            const ImageError error = compareImages(rgba, truth_rgba);
            worst_error = std::max(worst_error, error.max_abs);
            record["error"] = errorJson(error, options.reference);
            error_text = ", max error " + std::to_string(error.max_abs) + "/255 against " +
                         options.reference;
            if (!options.error_map.empty()) {
                const std::string map = isFramePattern(options.error_map)
                                            ? framePath(options.error_map, f)
                                            : options.error_map;
                if (Status written =
                        writeImage(map, view.width, view.height, errorMap(rgba, truth_rgba));
                    !written)
                    return fail(kExitFailure, written.error);
            }
        }
        frames.push_back(std::move(record));
        progress.update(f + 1);
        if (view.frames == 1)
            std::cout << "wrote " << path << " (" << options.method << ": order "
                      << formatNumber(stats.order_ms) << " ms, composite "
                      << formatNumber(stats.composite_ms) << " ms"
                      << (stats.cycles ? ", " + counted(stats.cycles, "cycle") : "") << error_text
                      << ")\n";
    }
    if (view.frames > 1)
        std::cout << counted(view.frames, "frame") << " written, " << framePath(options.output, 0)
                  << " to " << framePath(options.output, view.frames - 1)
                  << (reference_renderer ? ", max error " + std::to_string(worst_error) +
                                               "/255 against " + options.reference
                                         : "")
                  << '\n';
    if (options.json.path.empty())
        return kExitOk;
    const nlohmann::json document = {{"grid", grid.value->name},
                                     {"tetrahedra", grid.value->tets.size()},
                                     {"method", options.method},
                                     {"oracle", options.oracle},
                                     {"tf", options.tf},
                                     {"density", options.density},
                                     {"camera", cameraJson(view.camera)},
                                     {"path", cameraPathName(view.path)},
                                     {"size", {view.width, view.height}},
                                     {"frames", frames}};
    return writeJsonFile(options.json, document);
}

} // namespace vissort::cli
