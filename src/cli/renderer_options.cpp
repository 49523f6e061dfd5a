// The transparency renderer's options, shared by `render` and `view` (commands.h).

#include <algorithm>
#include <charconv>
#include <iostream>

#include "cli/colour_options.h"
#include "cli/command_line_errors.h"
#include "cli/commands.h"
#include "cli/environment.h"
#include "cli/progress.h"
#include "cli/text_output.h"
#include "vissort/levels_of_detail.h"
#include "vissort/transparency_renderer.h" // names and settings only: header-only without GL

namespace vissort::cli {
void addRendererOptions(CLI::App& command, RendererOptions& options,
                        const std::string& method_help) {
    command.add_option("--method", options.method, method_help)->capture_default_str();
    command
        .add_option("--level", options.level,
                    "object, triangle or multistage: vissort's ordering level, centroid's unit")
        ->capture_default_str();
    command
        .add_option("--oracle", options.oracle, "vissort's oracle: cpu, cpu-reference, exact or gl")
        ->capture_default_str();
    command.add_flag("--all-transparent", options.all_transparent,
                     "Treat every object as transparent with alpha --alpha");
    command.add_option("--background", options.background,
                       "The background: R,G,B or R,G,B,A (each in [0, 1]) or #RRGGBB (default " +
                           backgroundText(kDefaultBackground) +
                           ", a dark slate grey under which transparent surfaces show; 1,1,1 is "
                           "white)");
    command.add_option("--alpha", options.alpha, "Alpha of --all-transparent, in (0, 1]")
        ->capture_default_str();
    command
        .add_option("--shading", options.shading,
                    "lit (a headlight, per vertex), flat (each object's colour, unlit) or "
                    "membrane (lit, transparent surfaces more opaque where seen edge-on)")
        ->capture_default_str();
    command
        .add_option("--samples", options.samples,
                    "Samples a pixel, 1, 2, 4 or 8: every method blends each sample, averaged "
                    "at the end (anti-aliasing; costs about that many times the pixel work)")
        ->capture_default_str();
    command
        .add_option("--check", options.check,
                    "auto, on or off: check every pixel of an ordered blend against the GPU's "
                    "depths and repair it from fragment lists (auto: on for vissort only)")
        ->capture_default_str();
    command
        .add_option("--list-memory", options.list_memory_mib,
                    "MiB for per-pixel fragment lists (linked-list, vissort's cycles); more "
                    "fragments are drawn in bands")
        ->capture_default_str();
    command.add_flag("--colour-cycles", options.colour_cycles,
                     "vissort: draw the primitives of each cycle of the order in a colour of "
                     "their own (at their alpha)");
    command
        .add_option("--lod-error", options.lod_error,
                    "Levels of detail: draw and order each object at its coarsest level whose "
                    "error projects to at most PX pixels, objects out of view left out "
                    "(docs/lod.md); 0: every triangle")
        ->option_text("PX")
        ->capture_default_str();
}

std::shared_ptr<const LevelsOfDetail> buildLevels(const Scene& scene, double lod_error) {
    if (!(lod_error > 0))
        return nullptr;
    auto levels = [&] {
        Progress progress("levels of detail", scene.triangleCount(), "triangle");
        return std::make_shared<const LevelsOfDetail>(
            LevelsOfDetail::build(scene, {}, [&](double share) {
                progress.update(share * double(scene.triangleCount()));
            }));
    }();
    // What the levels hold (docs/lod.md, "Memory").
    const double chained = double(levels->levelCount());
    const double objects = double(std::max<std::size_t>(1, levels->objectCount()));
    std::cout << "levels of detail: " << levels->scene().triangleCount() << " triangles ("
              << formatNumber(double(levels->scene().triangleCount()) /
                              double(std::max<std::size_t>(1, scene.triangleCount())))
              << "x the scene's), " << formatNumber(chained / objects) << " levels an object\n";
    return levels;
}

std::string levelsLine(uint64_t triangles, uint32_t boxed_objects, uint32_t culled_objects,
                       std::size_t scene_triangles, const std::string& verb) {
    return std::to_string(triangles) + " of " + std::to_string(scene_triangles) + " triangles " +
           verb + " (" + counted(boxed_objects, "object") + " as boxes, " +
           std::to_string(culled_objects) + " out of view)";
}

std::string checkLodError(double lod_error) {
    if (lod_error >= 0 && lod_error <= 1e6)
        return "";
    return "--lod-error must be 0 (every triangle) or a number of pixels up to 1e6, got " +
           formatNumber(lod_error);
}

#if VISSORT_WITH_GL

void printRenderHeader(const std::string& specification, const Scene& scene,
                       const RenderSettings& settings, const ChosenView& view) {
    std::size_t transparent = 0, invisible = 0;
    for (const SceneObject& object : scene.objects) {
        if (!drawnTransparent(object, settings))
            continue;
        ++transparent;
        // Below half a level of 8 bits: nothing of it reaches the image.
        const float alpha = settings.all_transparent ? settings.alpha : object.colour.a;
        invisible += alpha < 0.5f / 255 ? 1 : 0;
    }
    std::cout << specification << ": " << counted(scene.objects.size(), "object") << " ("
              << transparent << " transparent), " << counted(scene.triangleCount(), "triangle")
              << "; " << blendMethodName(settings.method) << ", " << orderLevelName(settings.level)
              << " level, " << view.width << 'x' << view.height
              << (settings.samples > 1 ? " at " + std::to_string(settings.samples) + " samples"
                                       : std::string())
              << (settings.lod_error > 0
                      ? ", levels of detail within " + formatNumber(settings.lod_error) + " px"
                      : std::string())
              << ", " << counted(view.frames, "frame") << '\n'
              << cameraLine(view) << '\n';
    if (transparent == 0) // a hint, not a problem: the picture is right
        std::cout << "note: no transparent objects, so every method draws the same opaque "
                     "picture; --all-transparent [--alpha A] makes every object transparent\n";
    else if (invisible > 0)
        warn("transparent objects with alpha 0 do not show: " + std::to_string(invisible) + " of " +
             std::to_string(transparent) +
             " (the file's opacity, or a transparency read as opacity); --all-transparent "
             "--alpha A draws every object at alpha A");
}

std::string resolveRendererOptions(const RendererOptions& options, bool allow_all,
                                   RenderSettings& settings) {
    if (!(allow_all && options.method == "all")) {
        const Result<BlendMethod> method = parseBlendMethod(options.method);
        if (!method && allow_all) {
            // "all" is the command's word, not a method's: suggested among the methods' names.
            std::vector<std::string> names = {"all"};
            for (const auto& entry : kBlendMethodNames)
                names.emplace_back(entry.name);
            return "--method: unknown method '" + options.method + "' (" +
                   didYouMeanFirst(options.method, names) + "expected " + blendMethodNames() +
                   "; or all)";
        }
        if (!method)
            return "--method: " + method.error;
        settings.method = *method.value;
    }
    const Result<OrderLevel> level = parseOrderLevel(options.level);
    if (!level)
        return "--level: " + level.error;
    settings.level = *level.value;
    const Result<OracleKind> oracle = parseOracleKind(options.oracle);
    if (!oracle)
        return "--oracle: " + oracle.error;
    settings.oracle = *oracle.value;
    settings.oracle_options = environmentOracleOptions();
    if (!(options.alpha > 0.0 && options.alpha <= 1.0))
        return "--alpha must be in (0, 1], got " + formatNumber(options.alpha);
    const Result<Shading> shading = parseShading(options.shading);
    if (!shading)
        return "--shading: " + shading.error;
    settings.shading = *shading.value;
    if (const Result<SampleGrid> grid = sampleGridOf(options.samples); !grid)
        return "--" + grid.error;
    settings.samples = uint32_t(options.samples);
    const Result<RenderSettings::OrderCheck> check = parseOrderCheck(options.check);
    if (!check)
        return "--check: " + check.error;
    settings.check = *check.value;
    // At least one fragment (28 bytes); at most a petabyte, far beyond any driver.
    if (!(options.list_memory_mib >= 1.0 / 1024 && options.list_memory_mib <= 1e9))
        return "--list-memory must be between 0.001 and 1e9 MiB, got " +
               formatNumber(options.list_memory_mib);
    settings.list_bytes = uint64_t(options.list_memory_mib * 1024 * 1024);
    if (options.colour_cycles && options.method != "vissort")
        return "--colour-cycles colours vissort's cycles: not with --method " + options.method;
    settings.colour_cycles = options.colour_cycles;
    if (std::string error = checkLodError(options.lod_error); !error.empty())
        return error;
    settings.lod_error = float(options.lod_error);
    settings.all_transparent = options.all_transparent;
    settings.alpha = float(options.alpha);
    const Result<Rgba> background = parseBackground(options.background);
    if (!background)
        return "--background " + background.error;
    settings.background = *background.value;
    return "";
}
#endif

} // namespace vissort::cli
