#include <algorithm>
#include <cerrno>
#include <chrono>
#include <iostream>
#include <numeric>

#include <nlohmann/json.hpp>

#include "cli/command_line_errors.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/environment.h"
#include "cli/json_output.h"
#include "cli/obj_output.h"
#include "cli/output_paths.h"
#include "cli/progress.h"
#include "cli/stats_output.h"
#include "cli/text_output.h"
#include "vissort/frame_driver.h"
#include "vissort/levels_of_detail.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort::cli {
namespace {

// --csv's columns: the frame, its primitives and cycles, Vis-sort's counts, its wall time.
std::vector<std::string> orderCsvColumns() {
    std::vector<std::string> columns =
        withStatColumns<VisSortStats>({"frame", "time_s", "primitives", "cycles"});
    columns.push_back("ms");
    return columns;
}

// A frame's statistics: Vis-sort's counts (forEachStat) and the frame's wall time.
nlohmann::json frameStatsJson(const FrameOrder& frame) {
    nlohmann::json stats = statsJson(frame.stats);
    stats["ms"] = frame.milliseconds;
    return stats;
}

// A frame's JSON record; its order is lists' placeholder `order_list` (writeJsonFile).
nlohmann::json frameRecord(const FrameOrder& frame, std::size_t order_list,
                           const CameraSpec& camera) {
    return {{"order", jsonIdListPlaceholder(order_list)},
            {"camera", cameraJson(camera)},
            {"level", orderLevelName(frame.level)},
            {"cycles", frame.cycles},
            {"stats", frameStatsJson(frame)}};
}

void printFrame(int index, const FrameOrder& frame) {
    std::cout << "frame " << index << ": " << counted(frame.order.size(), "primitive") << ", "
              << counted(frame.cycles.size(), "cycle") << ", "
              << counted(frame.stats.iterations, "iteration") << ", "
              << counted(frame.stats.queries, "query", "queries") << ", "
              << counted(frame.stats.draws, "draw") << ", " << milliseconds(frame.milliseconds)
              << '\n';
}

// "cycles: 2" then each cycle's ids (at object level with the objects' names), the first
// kShownCycles cycles and kShownIds ids of each; --json has them all.
void printCycles(const FrameOrder& frame, const std::vector<std::string>& object_names) {
    constexpr std::size_t kShownCycles = 5, kShownIds = 12;
    std::cout << "cycles: " << frame.cycles.size() << '\n';
    const bool named = frame.level == OrderLevel::object && !object_names.empty();
    for (std::size_t c = 0; c < std::min(frame.cycles.size(), kShownCycles); ++c) {
        const std::vector<uint32_t>& cycle = frame.cycles[c];
        std::cout << "  cycle " << c << " ("
                  << counted(cycle.size(), named ? "object" : "primitive") << "):";
        for (std::size_t i = 0; i < std::min(cycle.size(), kShownIds); ++i) {
            std::cout << ' ' << cycle[i];
            if (named && !object_names[cycle[i]].empty())
                std::cout << " '" << object_names[cycle[i]] << "'";
        }
        std::cout << (cycle.size() > kShownIds ? " ...\n" : "\n");
    }
    if (frame.cycles.size() > kShownCycles)
        std::cout << "  ... (--json lists every cycle)\n";
}

} // namespace

CLI::App* addOrderCommand(CLI::App& app, OrderOptions& options) {
    CLI::App* command = app.add_subcommand("order", "Compute a visibility order of a scene");
    command
        ->add_option("scene", options.scene, "Mesh file, JSON scene, or builtin:NAME?key=value&...")
        ->required();
    addObjectsOption(*command, options.objects);
    addThreadsOption(*command);
    addViewOptions(*command, options.view);
    command->add_option("--level", options.level, "object, triangle or multistage")
        ->capture_default_str();
    command
        ->add_option("--oracle", options.oracle,
                     "cpu, cpu-reference, exact or gl (OpenGL through headless EGL; "
                     "VISSORT_GL_PLATFORM=auto|device|surfaceless picks the EGL platform)")
        ->capture_default_str();
    command->add_flag("--back-to-front", options.back_to_front,
                      "Output back to front (default front to back)");
    addJsonOptions(*command, options.json, "Write the order and statistics as JSON");
    addCsvOption(*command, options.csv, columnList(orderCsvColumns()));
    command->add_option("--dump-primitives", options.dump_path,
                        "Write the last frame's primitives as OBJ, one group per id");
    command
        ->add_option("--lod-error", options.lod_error,
                     "Levels of detail: order each object at its coarsest level whose error "
                     "projects to at most PX pixels, objects out of view last without a query "
                     "(docs/lod.md); triangle ids are then the levels' scene's; 0: every triangle")
        ->option_text("PX")
        ->capture_default_str();
    return command;
}

int runOrder(const OrderOptions& options) {
    const Result<OrderLevel> parsed_level = parseOrderLevel(options.level);
    if (!parsed_level)
        return fail(kExitUsage, "--level: " + parsed_level.error);
    const OrderLevel level = *parsed_level.value;
    const Result<OracleKind> parsed_oracle = parseOracleKind(options.oracle);
    if (!parsed_oracle)
        return fail(kExitUsage, "--oracle: " + parsed_oracle.error);
    const OracleKind oracle_kind = *parsed_oracle.value;
    if (std::string error = checkLodError(options.lod_error); !error.empty())
        return fail(kExitUsage, error);
    std::optional<Scene> scene;
    ChosenView view;
    if (const int code =
            loadSceneAndView(options.scene, options.objects, options.view, scene, view);
        code != kExitOk)
        return code;

    Result<std::unique_ptr<GeometryOracle>> made =
        makeOracle(oracle_kind, environmentOracleOptions());
    if (!made)
        return fail(kExitFailure, made.error);
    std::unique_ptr<GeometryOracle> oracle = std::move(*made.value);
    SceneOrderer orderer(scene->objectPrimitives(), uint32_t(scene->triangleCount()), level,
                         *oracle);
    // With levels of detail each frame orders the levels chosen, gathered (DetailSelection).
    std::unique_ptr<DetailSelection> selection;
    if (const std::shared_ptr<const LevelsOfDetail> levels = buildLevels(*scene, options.lod_error))
        selection = std::make_unique<DetailSelection>(*scene, levels, float(options.lod_error));
    const std::size_t object_count = scene->objects.size();
    std::vector<std::string> object_names;
    for (const SceneObject& object : scene->objects)
        object_names.push_back(object.name);
    // The orderer keeps the objects' triangle ranges, and only --dump-primitives reads the
    // objects again: a scene of many small objects (builtin:soup, one a triangle) holds far more
    // in them (names, materials) than the ranges.
    if (options.dump_path.empty())
        std::vector<SceneObject>().swap(scene->objects);
    std::cout << options.scene << ": " << counted(object_count, "object") << ", "
              << counted(scene->triangleCount(), "triangle") << "; " << orderLevelName(level)
              << " level, " << oracleName(oracle_kind) << " oracle, " << view.width << 'x'
              << view.height
              << (selection ? ", levels of detail within " + formatNumber(options.lod_error) + " px"
                            : std::string())
              << ", " << counted(view.frames, "frame") << '\n'
              << cameraLine(view) << '\n';
    FrameDriver driver(*scene, view.camera, view.path, view.width, view.height);
    nlohmann::json frames = nlohmann::json::array();
    std::vector<std::vector<uint32_t>> frame_orders; // for --json, when there are several frames
    FrameOrder last;
    double total_ms = 0;
    CsvTable csv(orderCsvColumns());
    Progress progress("order", uint64_t(view.frames), "frame");
    int frame = 0;
    orderer.setProgress([&](double share) { progress.update(frame + share); });
    for (int f = 0; f < view.frames; ++f) {
        frame = f;
        driver.seek(f);
        PositionsView ordered = driver.positions();
        if (selection) {
            const auto start = std::chrono::steady_clock::now();
            selection->select(driver.positions(), driver.view());
            const DetailFrame& chosen = selection->gather();
            orderer.setObjects(chosen.objects, uint32_t(chosen.triangles));
            orderer.orderFrame(chosen.positions, driver.view(), last);
            // Triangle ids as the levels' scene's; the time includes choosing and gathering.
            if (level != OrderLevel::object) {
                for (uint32_t& t : last.order)
                    t = chosen.detailed_triangle[t];
                for (std::vector<uint32_t>& cycle : last.cycles)
                    for (uint32_t& t : cycle)
                        t = chosen.detailed_triangle[t];
            }
            last.milliseconds =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            ordered = chosen.positions;
        } else {
            orderer.orderFrame(driver.positions(), driver.view(), last);
        }
        progress.update(f + 1);
        total_ms += last.milliseconds;
        std::vector<double> row = withStatValues(
            {double(f), driver.time(), double(last.order.size()), double(last.cycles.size())},
            last.stats);
        row.push_back(last.milliseconds);
        csv.addRow(row);
        if (view.frames > 1) {
            progress.clear();
            printFrame(f, last);
            if (selection) {
                const DetailFrame& chosen = selection->frame(); // gathered above
                std::cout << "  "
                          << levelsLine(chosen.triangles, chosen.boxed_objects,
                                        chosen.culled_objects, scene->triangleCount(), "ordered")
                          << '\n';
            }
            if (!options.json.path.empty()) {
                frames.push_back(frameRecord(last, frame_orders.size(), driver.camera()));
                frame_orders.push_back(last.order);
            }
        }
    }

    progress.clear();
    const std::string unit = level == OrderLevel::object ? "object" : "triangle";
    std::cout << "order (" << (options.back_to_front ? "back to front" : "front to back") << ") of "
              << counted(last.order.size(), unit) << ':';
    const std::size_t n = last.order.size();
    for (std::size_t i = 0; i < std::min<std::size_t>(n, 20); ++i)
        std::cout << ' ' << last.order[options.back_to_front ? n - 1 - i : i];
    std::cout << (n > 20 ? " ...\n" : "\n");
    printCycles(last, object_names);
    std::cout << (view.frames > 1 ? "last frame: " : "")
              << counted(last.stats.iterations, "iteration") << ", "
              << counted(last.stats.queries, "query", "queries") << ", "
              << counted(last.stats.draws, "draw") << ", " << milliseconds(last.milliseconds);
    if (view.frames > 1)
        std::cout << "; mean " << milliseconds(total_ms / view.frames) << " a frame";
    std::cout << '\n';

    if (!options.json.path.empty()) {
        std::vector<JsonIdList> lists;
        for (const std::vector<uint32_t>& order : frame_orders)
            lists.push_back({order, options.back_to_front});
        nlohmann::json document = frameRecord(last, lists.size(), driver.camera());
        lists.push_back({last.order, options.back_to_front});
        document["scene"] = options.scene;
        document["oracle"] = oracleName(oracle_kind);
        document["back_to_front"] = options.back_to_front;
        document["size"] = {view.width, view.height};
        if (view.frames > 1)
            document["frames"] = std::move(frames);
        if (const int code = writeJsonFile(options.json, document, lists); code != kExitOk)
            return code;
    }
    if (!options.csv.empty())
        if (const int code = csv.write(options.csv); code != kExitOk)
            return code;
    if (!options.dump_path.empty()) {
        // With levels: an object is its chosen triangles at the last frame (gathered); a
        // triangle id is the levels' scene's, whose every triangle the dump holds.
        std::vector<PrimitiveRange> primitives = primitivesOf(*scene, level);
        PositionsView positions = driver.positions();
        if (selection && level == OrderLevel::object) {
            const DetailFrame& chosen = selection->frame();
            positions = chosen.positions;
            primitives = chosen.objects;
        } else if (selection) {
            positions = selection->levelsPositions();
            primitives = primitivesOf(selection->levels().scene(), level);
        }
        errno = 0;
        if (!writePrimitivesObj(options.dump_path,
                                "vissort primitives: one group per primitive id, world space",
                                positions, primitives))
            return fail(kExitFailure, cannotWrite(options.dump_path));
    }
    return kExitOk;
}

} // namespace vissort::cli
