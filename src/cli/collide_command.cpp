// vissort collide: every intersecting pair of triangles of different objects, frame by frame.

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/json_output.h"
#include "cli/obj_output.h"
#include "cli/output_paths.h"
#include "cli/progress.h"
#include "cli/stats_output.h"
#include "cli/text_output.h"
#include "harnesses/measurement.h"
#include "vissort/atomic_file.h"
#include "vissort/collision.h"
#include "vissort/frame_driver.h"

namespace vissort::cli {
namespace {

// A frame's JSON record: its statistics and the object pairs that collide, by index into the
// document's "objects".
nlohmann::json frameRecord(int frame, const CollisionResult& result) {
    nlohmann::json record = statsJson(result.stats);
    record["frame"] = frame;
    nlohmann::json pairs = nlohmann::json::array();
    for (const ObjectPair& p : result.object_pairs)
        pairs.push_back({p.first, p.second});
    record["object_pairs_colliding"] = std::move(pairs);
    return record;
}

// "3 'bunny_3'": an object as people read it.
std::string objectLabel(const Scene& scene, uint32_t object) {
    return std::to_string(object) + " '" + scene.objects[object].name + "'";
}

// The colliding objects of a frame, the first kListed pairs by id and name.
void printObjectPairs(const Scene& scene, const std::vector<ObjectPair>& pairs) {
    constexpr std::size_t kListed = 20;
    std::cout << "colliding objects: " << counted(pairs.size(), "pair");
    for (std::size_t i = 0; i < pairs.size() && i < kListed; ++i)
        std::cout << (i == 0 ? ": " : "; ") << objectLabel(scene, pairs[i].first) << " and "
                  << objectLabel(scene, pairs[i].second);
    if (pairs.size() > kListed)
        std::cout << "; and " << pairs.size() - kListed << " more (--json lists them all)";
    std::cout << '\n';
}

} // namespace

CLI::App* addCollideCommand(CLI::App& app, CollideOptions& options) {
    CLI::App* command = app.add_subcommand(
        "collide", "Find every pair of intersecting triangles of different objects");
    command
        ->add_option("scene", options.scene, "Mesh file, JSON scene, or builtin:NAME?key=value&...")
        ->required();
    addObjectsOption(*command, options.objects);
    command
        ->add_option("--frames", options.frames,
                     "Frames to run; dynamic scenes advance 1/30 s a frame")
        ->capture_default_str();
    command
        ->add_option("--method", options.method,
                     "vissort (visibility culling), brute (ground truth), bullet or fcl")
        ->capture_default_str();
    command->add_option("--size", options.size, "vissort: pixels of each object-stage view, WxH")
        ->capture_default_str();
    command
        ->add_option("--directions", options.directions,
                     "vissort: how many of the object stage's directions to allow (the axes, "
                     "then the cube diagonals)")
        ->check(CLI::Range(1, 7))
        ->capture_default_str();
    command
        ->add_option("--min-cull", options.min_cull,
                     "vissort: try the next direction only while the last culled at least "
                     "this fraction of its object pairs (0: until none is culled, the paper's "
                     "rule)")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    command
        ->add_option("--object-stage", options.object_stage,
                     "vissort: when the object stage runs: adaptive (while it saves more "
                     "descent time than it takes), always (the paper's method) or never")
        ->capture_default_str();
    command
        ->add_option("--threads", options.threads,
                     "vissort and bullet: threads, 0 = one per core (the pairs never depend on it)")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    addJsonOptions(*command, options.json, "Write per-frame statistics as JSON");
    addCsvOption(*command, options.csv,
                 columnList(withStatColumns<CollisionStats>({"frame", "time_s"})));
    command->add_option("--pairs-out", options.pairs_path,
                        "Write 'FRAME A B' per intersecting pair (triangle ids, A < B, sorted)");
    command->add_option("--dump-primitives", options.dump_path,
                        "Write the last frame's objects as OBJ, one group per object");
    return command;
}

int runCollide(const CollideOptions& options) {
    // The limit and the words of every command's --frames (view_choice.h).
    if (options.frames < 1 || options.frames > kMaxFrames)
        return fail(kExitUsage, "--frames must be between 1 and " + std::to_string(kMaxFrames));
    CollisionSettings settings;
    const Result<CollisionMethod> method = parseCollisionMethod(options.method);
    if (!method)
        return fail(kExitUsage, "--method: " + method.error);
    settings.method = *method.value;
    if (auto error = parseSize(options.size, settings.width, settings.height); !error.empty())
        return fail(kExitUsage, error);
    settings.threads = uint32_t(options.threads);
    settings.min_cull_fraction = float(options.min_cull);
    const Result<ObjectStage> object_stage = parseObjectStage(options.object_stage);
    if (!object_stage)
        return fail(kExitUsage, "--object-stage: " + object_stage.error);
    settings.object_stage = *object_stage.value;
    const std::vector<Vec3> all_directions = defaultCollisionDirections();
    settings.directions.assign(all_directions.begin(), all_directions.begin() + options.directions);
    if (Status valid = validateCollisionSettings(settings); !valid)
        return fail(kExitUsage, "--size " + options.size + ": " + valid.error);
    std::optional<Scene> scene;
    if (const int code = loadSceneOrReport(options.scene, options.objects, scene); code != kExitOk)
        return code;

    // Written frame by frame into a temporary file, renamed into place at the end
    // (atomic_file.h): a failed or killed run leaves the old pairs file whole.
    std::optional<AtomicFile> pairs_file;
    std::ofstream pairs_out;
    if (!options.pairs_path.empty()) {
        Result<AtomicFile> begun = AtomicFile::begin(options.pairs_path);
        if (!begun)
            return fail(kExitFailure, begun.error);
        pairs_file = std::move(*begun.value);
        errno = 0;
        pairs_out.open(pairs_file->writePath());
        if (!pairs_out)
            return fail(kExitFailure, cannotWrite(options.pairs_path));
    }
    const std::vector<PrimitiveRange> objects = scene->objectPrimitives();
    CollisionDetector detector(objects, settings);
    FrameDriver driver(*scene);
    CollisionResult result;
    nlohmann::json frames = nlohmann::json::array();
    std::vector<double> total_ms;
    uint64_t pair_sum = 0;
    CsvTable csv(withStatColumns<CollisionStats>({"frame", "time_s"}));
    std::cout << options.scene << ": " << counted(scene->objects.size(), "object") << ", "
              << counted(scene->triangleCount(), "triangle") << "; method " << options.method
              << ", " << counted(options.frames, "frame") << '\n';
    Progress progress("collide", uint64_t(options.frames), "frame");
    for (int f = 0; f < options.frames; ++f) {
        driver.seek(f);
        detector.collide(driver.positions(), result);
        progress.clear();
        const CollisionStats& s = result.stats;
        csv.addRow(withStatValues({double(f), driver.time()}, s));
        total_ms.push_back(result.stats.total_ms);
        pair_sum += result.pairs.size();
        if (!options.json.path.empty())
            frames.push_back(frameRecord(f, result));
        if (pairs_out.is_open())
            for (const TrianglePair& p : result.pairs)
                pairs_out << f << ' ' << p.first << ' ' << p.second << '\n';
        if (options.frames > 1)
            std::cout << "frame " << f << ": " << counted(result.pairs.size(), "intersecting pair")
                      << " between " << counted(result.object_pairs.size(), "object pair") << ", "
                      << counted(result.stats.triangle_pairs, "candidate triangle pair") << ", "
                      << milliseconds(result.stats.total_ms) << '\n';
        progress.update(f + 1);
    }
    progress.clear();
    errno = 0;
    if (pairs_out.is_open()) {
        pairs_out.close();
        if (!pairs_out)
            return fail(kExitFailure, cannotWrite(options.pairs_path));
        if (Status committed = pairs_file->commit(); !committed)
            return fail(kExitFailure, committed.error);
    }

    double mean = 0;
    for (double ms : total_ms)
        mean += ms / double(total_ms.size());
    std::cout << counted(options.frames, "frame") << ": mean " << milliseconds(mean) << ", median "
              << milliseconds(bench::median(total_ms)) << " a frame, "
              << double(pair_sum) / options.frames << " intersecting pairs a frame\n"
              << (options.frames > 1 ? "last frame: " : "")
              << counted(result.stats.object_pairs, "candidate object pair") << ", "
              << counted(result.stats.triangle_pairs, "candidate triangle pair") << ", "
              << result.pairs.size() << " intersecting\n";
    printObjectPairs(*scene, result.object_pairs);

    if (!options.csv.empty())
        if (const int code = csv.write(options.csv); code != kExitOk)
            return code;
    if (!options.json.path.empty()) {
        nlohmann::json names = nlohmann::json::array();
        for (const SceneObject& object : scene->objects)
            names.push_back(object.name);
        nlohmann::json document = {{"method", options.method},
                                   {"scene", options.scene},
                                   {"size", {settings.width, settings.height}},
                                   {"objects", std::move(names)},
                                   {"frames", std::move(frames)}};
        if (const int code = writeJsonFile(options.json, document); code != kExitOk)
            return code;
    }
    errno = 0;
    if (!options.dump_path.empty() &&
        !writePrimitivesObj(options.dump_path,
                            "vissort collide: one group per object id; face i is triangle i",
                            driver.positions(), objects))
        return fail(kExitFailure, cannotWrite(options.dump_path));
    return kExitOk;
}

} // namespace vissort::cli
