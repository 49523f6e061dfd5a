// `vissort render`: transparency through the headless OpenGL renderer, one method per run, with
// an optional reference method and its error.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/environment.h"
#include "cli/json_output.h"
#include "cli/output_paths.h"
#include "cli/progress.h"
#include "cli/stats_output.h"
#include "cli/text_output.h"
#include "vissort/frame_driver.h"
#include "vissort/frame_pipeline.h"
#include "vissort/output_files.h"
#include "vissort/transparency_renderer.h"

#if VISSORT_WITH_GL
#include "harnesses/method_comparison.h"
#endif

namespace vissort::cli {
namespace {

// --csv's columns: the frame, the method's statistics and the order's counts, the highlights,
// the reference's error.
std::vector<std::string> renderCsvColumns(bool highlight, bool reference) {
    std::vector<std::string> columns =
        withStatColumns<VisSortStats>(withStatColumns<RenderStats>({"frame", "time_s"}));
    if (highlight)
        columns.push_back("colliding_triangles");
    if (reference)
        columns.insert(columns.end(), {"max_abs", "rmse", "pixels_over_one"});
    return columns;
}

} // namespace

#if VISSORT_WITH_GL
namespace {

nlohmann::json errorJson(const ImageError& error, const std::string& reference) {
    return {
        {"rmse", error.rmse},
        {"psnr", std::isfinite(error.psnr) ? nlohmann::json(error.psnr) : nlohmann::json(nullptr)},
        {"max_abs", error.max_abs},
        {"pixels_over_one", error.pixels_over_one},
        {"reference", reference}};
}

// A method's statistics: its fields (forEachStat), times under "ms", the order's counts under
// "order".
nlohmann::json methodStatsJson(BlendMethod method, const RenderStats& stats) {
    nlohmann::json record = {{"method", blendMethodName(method)}};
    record.update(statsJson(stats));
    record["order"] = statsJson(stats.order);
    return record;
}

// --method all: every method on the same frame beside its error map against linked-list, as
// one PNG (the samples' compareEveryMethod), each method's line printed and its record in the
// JSON.
int renderEveryMethod(const RenderOptions& options, const RenderSettings& settings,
                      const Scene& scene, const ChosenView& view,
                      const std::shared_ptr<GlContext>& context) {
    const bench::MethodComparison comparison = bench::compareEveryMethod(
        context, scene, settings,
        frameCamera(view.camera, scene.positions.bounds(), view.width, view.height));
    nlohmann::json methods = nlohmann::json::array();
    for (const bench::MethodPicture& picture : comparison.methods) {
        const RenderStats& stats = picture.stats;
        const ImageError& error = picture.error;
        std::cout << std::left << std::setw(12) << blendMethodName(picture.method) << std::right
                  << std::fixed << std::setprecision(1) << std::setw(9) << stats.total_ms << " ms, "
                  << counted(stats.passes, "pass", "passes") << ", against linked-list: max "
                  << error.max_abs << "/255, RMSE " << std::setprecision(3) << error.rmse << ", "
                  << error.pixels_over_one << " pixels off by more than 1\n";
        nlohmann::json record = methodStatsJson(picture.method, stats);
        record["error"] = errorJson(error, "linked-list");
        methods.push_back(std::move(record));
    }
    const samples::Strip& strip = comparison.strip;
    if (Status error = writeImage(options.output, strip.width, strip.height, strip.rgba); !error)
        return fail(kExitFailure, error.error);
    std::cout << options.output << ": every method (top) and its error against linked-list "
              << "(below: grey within 1/255, yellow to red beyond)\n";
    if (options.json.path.empty())
        return kExitOk;
    const nlohmann::json document = {{"scene", options.scene},
                                     {"level", orderLevelName(settings.level)},
                                     {"oracle", oracleName(settings.oracle)},
                                     {"size", {view.width, view.height}},
                                     {"shading", shadingName(settings.shading)},
                                     {"samples", settings.samples},
                                     {"methods", methods}};
    return writeJsonFile(options.json, document);
}

} // namespace
#endif // VISSORT_WITH_GL

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options) {
#if VISSORT_WITH_GL
    constexpr bool kWithGl = true;
#else
    constexpr bool kWithGl = false;
#endif
    CLI::App* command =
        app.add_subcommand("render", "Render a scene's transparent objects, blended by a method");
    // Without OpenGL nothing is required: any `render ...` reaches runRender's one-line error.
    command
        ->add_option("scene", options.scene, "Mesh file, JSON scene, or builtin:NAME?key=value&...")
        ->required(kWithGl);
    addObjectsOption(*command, options.objects);
    addThreadsOption(*command);
    addViewOptions(*command, options.view);
    addRendererOptions(*command, options.renderer,
                       blendMethodNames() + "; all: every method side by side in one PNG, with "
                                            "error maps against linked-list");
    command
        ->add_option("-o,--output", options.output,
                     "Image to write (.png or .jpg); with --frames N, a pattern such as "
                     "frame_%04d.png (a pattern with one frame names frame 0)")
        ->required(kWithGl);
    addJsonOptions(*command, options.json, "Write the statistics (and error) as JSON");
    addCsvOption(*command, options.csv,
                 columnList(renderCsvColumns(false, false)) +
                     ", then colliding_triangles with --highlight-collisions, and max_abs, rmse, "
                     "pixels_over_one with --reference");
    command->add_option("--reference", options.reference,
                        "Also render this method and print RMSE, PSNR and the largest channel "
                        "error against it");
    command->add_flag("--highlight-collisions", options.highlight_collisions,
                      "Draw every triangle that intersects another object's in magenta "
                      "(vissort's collision detector, each frame)");
    command->add_option("--error-map", options.error_map,
                        "With --reference: write where the two differ as a PNG (a pattern with "
                        "--frames)");
    return command;
}

#if !VISSORT_WITH_GL
int runRender(const RenderOptions&) {
    return failWithoutGl("render");
}
#else
int runRender(const RenderOptions& options) {
    RenderSettings settings;
    const bool all_methods = options.renderer.method == "all";
    if (std::string error = resolveRendererOptions(options.renderer, true, settings);
        !error.empty())
        return fail(kExitUsage, error);
    if (options.renderer.colour_cycles && !options.reference.empty())
        return fail(kExitUsage, "--colour-cycles changes the picture: not with --reference");
    if (all_methods && options.highlight_collisions)
        return fail(kExitUsage, "--highlight-collisions renders one method: not with --method all");
    if (all_methods && (options.view.frames > 1 || !options.reference.empty()))
        return fail(kExitUsage, "--method all renders one frame against linked-list: no --frames "
                                "or --reference");
    BlendMethod reference_method{};
    if (!options.reference.empty()) {
        const Result<BlendMethod> reference = parseBlendMethod(options.reference);
        if (!reference)
            return fail(kExitUsage, "--reference: " + reference.error);
        reference_method = *reference.value;
    }
    if (!options.error_map.empty() && options.reference.empty())
        return fail(kExitUsage, "--error-map needs --reference METHOD");
    if (all_methods && !options.csv.empty())
        return fail(kExitUsage, "--csv writes one method's frames: --method all writes its "
                                "comparison with --json");
    for (const std::string* image : {&options.output, &options.error_map})
        if (!image->empty())
            if (const Result<ImageFormat> format = imageFormatOf(*image); !format)
                return fail(kExitUsage,
                            (image == &options.output ? "-o: " : "--error-map: ") + format.error);
    if (options.view.frames > 1 && !isFramePattern(options.output))
        return fail(kExitUsage, "with --frames, -o needs one %d (such as frame_%04d.png), got '" +
                                    options.output + "'");
    if (options.view.frames > 1 && !options.error_map.empty() && !isFramePattern(options.error_map))
        return fail(kExitUsage, "with --frames, --error-map needs one %d (such as "
                                "error_%04d.png), got '" +
                                    options.error_map + "'");
    std::optional<Scene> scene;
    ChosenView view;
    if (const int code =
            loadSceneAndView(options.scene, options.objects, options.view, scene, view);
        code != kExitOk)
        return code;
    Result<std::shared_ptr<GlContext>> context = GlContext::shared();
    if (!context)
        return fail(kExitFailure, context.error);
    if (all_methods)
        return renderEveryMethod(options, settings, *scene, view, *context.value);

    FramePipelineDef def;
    def.settings = settings;
    def.highlight_collisions = options.highlight_collisions;
    if (!options.reference.empty())
        def.reference = reference_method;
    printRenderHeader(options.scene, *scene, settings, view);
    FramePipeline pipeline(*context.value, *scene, def, buildLevels(*scene, settings.lod_error));
    FrameDriver driver(*scene, view.camera, view.path, view.width, view.height);
    nlohmann::json frames = nlohmann::json::array();
    std::vector<double> total_ms;
    CsvTable csv(renderCsvColumns(def.highlight_collisions, def.reference.has_value()));
    Progress progress("render", uint64_t(view.frames), "frame");
    int frame = 0;
    pipeline.setOrderProgress([&](double share) { progress.update(frame + share); });
    PipelineFrame rendered;
    for (int f = 0; f < view.frames; ++f) {
        frame = f;
        driver.seek(f);
        pipeline.render(driver.positions(), driver.view(), rendered);
        const RenderStats& stats = rendered.stats;
        // A pattern names every frame, the first too when it is the only one.
        const std::string path =
            isFramePattern(options.output) ? framePath(options.output, f) : options.output;
        if (Status error = writeImage(path, view.width, view.height, rendered.rgba); !error)
            return fail(kExitFailure, error.error);
        nlohmann::json record = methodStatsJson(settings.method, stats);
        progress.clear();
        std::cout << path << ": " << milliseconds(stats.total_ms) << " (order "
                  << milliseconds(stats.order_ms) << ", render " << milliseconds(stats.render_ms)
                  << "), " << counted(stats.passes, "pass", "passes");
        if (stats.fragments > 0)
            std::cout << ", " << counted(stats.fragments, "fragment") << " listed";
        if (settings.method == BlendMethod::vissort)
            std::cout << ", " << counted(stats.groups, "group") << " composited per pixel";
        if (stats.repaired_pixels > 0)
            std::cout << ", " << counted(stats.repaired_pixels, "pixel") << " repaired";
        if (settings.lod_error > 0)
            std::cout << "; "
                      << levelsLine(stats.triangles, stats.boxed_objects, stats.culled_objects,
                                    scene->triangleCount(), "drawn");
        total_ms.push_back(stats.total_ms);
        std::vector<double> row =
            withStatValues(withStatValues({double(f), driver.time()}, stats), stats.order);
        if (def.highlight_collisions) {
            std::cout << ", " << counted(rendered.colliding_triangles, "colliding triangle")
                      << " highlighted";
            record["colliding_triangles"] = rendered.colliding_triangles;
            row.push_back(double(rendered.colliding_triangles));
        }
        std::cout << '\n';
        if (rendered.error) {
            const ImageError& error = *rendered.error;
            if (!options.error_map.empty()) {
                const std::string map_path = isFramePattern(options.error_map)
                                                 ? framePath(options.error_map, f)
                                                 : options.error_map;
                if (Status e = writeImage(map_path, view.width, view.height,
                                          errorMap(rendered.rgba, rendered.reference_rgba));
                    !e)
                    return fail(kExitFailure, e.error);
            }
            std::cout << "  against " << options.reference << ": RMSE " << error.rmse << ", PSNR "
                      << error.psnr << " dB, max abs " << error.max_abs << "/255, "
                      << counted(error.pixels_over_one, "pixel") << " off by more than 1\n";
            record["error"] = errorJson(error, options.reference);
            row.insert(row.end(),
                       {double(error.max_abs), error.rmse, double(error.pixels_over_one)});
        }
        csv.addRow(row);
        progress.update(f + 1);
        record["camera"] = cameraJson(driver.camera());
        frames.push_back(std::move(record));
    }
    progress.clear();
    if (view.frames > 1) {
        std::nth_element(total_ms.begin(), total_ms.begin() + total_ms.size() / 2, total_ms.end());
        std::cout << counted(view.frames, "frame") << " written, " << framePath(options.output, 0)
                  << " to " << framePath(options.output, view.frames - 1) << ": median "
                  << milliseconds(total_ms[total_ms.size() / 2]) << " a frame\n";
    }
    if (!options.csv.empty())
        if (const int code = csv.write(options.csv); code != kExitOk)
            return code;
    if (!options.json.path.empty()) {
        nlohmann::json document = frames.back();
        document["scene"] = options.scene;
        document["level"] = orderLevelName(settings.level);
        document["oracle"] = oracleName(settings.oracle);
        document["size"] = {view.width, view.height};
        document["shading"] = shadingName(settings.shading);
        document["samples"] = settings.samples;
        if (view.frames > 1)
            document["frames"] = std::move(frames);
        if (const int code = writeJsonFile(options.json, document); code != kExitOk)
            return code;
    }
    return kExitOk;
}

#endif // VISSORT_WITH_GL

} // namespace vissort::cli
