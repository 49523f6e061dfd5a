// `vissort bench oracle`: the oracles' cost on the synthetic setup-bound and fill-bound workloads
// (the CPU rasterizers) and on the real ones (the bunnies at triangle level, a stack of slabs at
// object level, along an orbit; the CPU rasterizers and OpenGL), every oracle measured in the same
// run so the figures are ratios on one machine.

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/bench_common.h"
#include "cli/environment.h"
#include "vissort/oracles.h"
#include "cli/commands.h"
#include "cli/json_output.h"
#include "vissort/gl_context.h"
#include "support/oracle_workloads.h"
#include "vissort/scene_orderer.h"

namespace vissort::cli {
namespace {

using Clock = BenchClock;

struct SyntheticResult {
    double bind_seconds = 0, draw_seconds = 0, query_seconds = 0;
};

// Best of `repeat` runs: a bind (the cpu oracle sets every triangle up there, the reference only
// transforms them and sets up in every draw and query), draws of every triangle back to front
// (each one passes), then queries of every triangle against the far background alone (nothing
// behind: every pixel is tested).
SyntheticResult runSynthetic(GeometryOracle& oracle, const ScreenTriangleWorkload& w, int repeat) {
    SyntheticResult best{1e300, 1e300, 1e300};
    for (int r = 0; r < repeat; ++r) {
        const auto start = Clock::now();
        oracle.bind(w.positions, w.view, w.primitives);
        best.bind_seconds = std::min(best.bind_seconds, secondsSince(start));
    }
    const auto count = uint32_t(w.primitives.size() - 1);
    uint32_t answered_behind = 0;
    for (int r = 0; r < repeat; ++r) {
        oracle.clear();
        auto start = Clock::now();
        for (uint32_t i = 0; i < count; ++i)
            oracle.draw(i);
        best.draw_seconds = std::min(best.draw_seconds, secondsSince(start));
        oracle.clear();
        oracle.draw(w.background);
        start = Clock::now();
        for (uint32_t i = 0; i < count; ++i)
            answered_behind += oracle.anyBehind(i) ? 1 : 0;
        best.query_seconds = std::min(best.query_seconds, secondsSince(start));
    }
    if (answered_behind != 0)
        throw std::runtime_error("bench workload broken: a query found fragments behind");
    return best;
}

struct Row {
    std::string workload, oracle, unit;
    double value;
    std::string detail;
};

} // namespace

int runOracleBench(const BenchOptions& options) {
    const int frame_count = options.frames.value_or(11);
    if (options.repeat < 1 || options.repeat > 100)
        return fail(kExitUsage, "--repeat must be 1..100");
    if (frame_count < 2 || frame_count > 1000)
        return fail(kExitUsage, "--frames must be 2..1000");
    if (options.gl_frames < 2 || options.gl_frames > 1000)
        return fail(kExitUsage, "--gl-frames must be 2..1000");

    const std::vector<OracleKind> kinds = benchmarkedOracles();
    std::vector<Row> rows;
    std::cout << "vissort bench oracle on " << machineName() << ", "
              << std::thread::hardware_concurrency() << " hardware threads\n";

    struct Case {
        const char* name;
        uint32_t count;
        double leg;
        uint32_t width, height;
        bool setup_bound;
    };
    const Case cases[] = {{"right triangles, 10 px legs, 1920x1080", 100000, 10, 1920, 1080, true},
                          {"right triangles, 100 px legs, 1600x1200", 2000, 100, 1600, 1200, false},
                          {"right triangles, 500 px legs, 1600x1200", 200, 500, 1600, 1200, false}};
    for (const Case& c : cases) {
        const ScreenTriangleWorkload w =
            makeRightTriangleWorkload(c.count, c.leg, c.width, c.height);
        const double pixels = c.count * c.leg * c.leg / 2;
        for (OracleKind kind : kinds) {
            Result<std::unique_ptr<GeometryOracle>> made = makeOracle(kind, environmentOracleOptions());
            if (!made) return fail(kExitFailure, made.error);
            GeometryOracle* oracle = made.value->get();
            const SyntheticResult r = runSynthetic(*oracle, w, options.repeat);
            if (c.setup_bound) {
                rows.push_back({std::string(c.name) + ", bind", oracleName(kind), "M triangles/s",
                                c.count / r.bind_seconds / 1e6, ""});
                rows.push_back({std::string(c.name) + ", bind + draws", oracleName(kind),
                                "M triangles/s", c.count / (r.bind_seconds + r.draw_seconds) / 1e6,
                                ""});
                rows.push_back({std::string(c.name) + ", draws", oracleName(kind), "M triangles/s",
                                c.count / r.draw_seconds / 1e6, ""});
                rows.push_back({std::string(c.name) + ", queries", oracleName(kind),
                                "M triangles/s", c.count / r.query_seconds / 1e6, ""});
            } else {
                rows.push_back({std::string(c.name) + ", draws", oracleName(kind), "G pixels/s",
                                pixels / r.draw_seconds / 1e9, ""});
                rows.push_back({std::string(c.name) + ", queries", oracleName(kind), "G pixels/s",
                                pixels / r.query_seconds / 1e9, ""});
            }
        }
    }

    // The real workloads, coherent frames on an orbit: the paper's dynamic scene at triangle
    // level (many tiny triangles), and a stack of 64 large slabs at object level (depth
    // complexity 64, fill-bound). The gl oracle runs fewer frames: through llvmpipe a bunnies
    // frame takes seconds.
    std::vector<std::pair<OracleKind, int>> real_oracles;
    for (OracleKind kind : kinds)
        real_oracles.push_back({kind, frame_count});
    if (Result<std::shared_ptr<GlContext>> context = GlContext::shared(); context) {
        real_oracles.push_back({OracleKind::gl, std::min(frame_count, options.gl_frames)});
        std::cout << "gl: " << (*context.value)->info().renderer << " ("
                  << (*context.value)->info().version << "), " << real_oracles.back().second
                  << " frames\n";
    } else {
        std::cout << "gl: not measured, " << context.error << '\n';
    }
    struct RealWorkload {
        const char* name;
        const char* scene;
        OrderLevel level;
    };
    const RealWorkload real[] = {{"bunnies (18, 66,132 triangles), triangle level, orbit, 1024x768",
                                  "builtin:bunnies", OrderLevel::triangle},
                                 {"slabs (64), object level, orbit, 1024x768",
                                  "builtin:slabs?layers=64", OrderLevel::object}};
    for (const RealWorkload& workload : real) {
        Result<Scene> loaded = loadScene(workload.scene);
        if (!loaded)
            return fail(kExitFailure, loaded.error);
        const Scene& scene = *loaded.value;
        const CameraSpec base =
            scene.camera.value_or(defaultCamera(scene.positions.bounds(), 1024.0 / 768));
        for (const auto& [kind, frames] : real_oracles) {
            Result<std::unique_ptr<GeometryOracle>> made = makeOracle(kind, environmentOracleOptions());
            if (!made) return fail(kExitFailure, made.error);
            GeometryOracle* oracle = made.value->get();
            SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()), workload.level, *oracle);
            TrianglePositions positions;
            std::vector<double> ms, queries, iterations;
            for (int f = 0; f < frames; ++f) {
                scene.frame(f * kFrameInterval, positions);
                const CameraSpec camera =
                    cameraOnPath(base, CameraPath::orbit, f, scene.positions.bounds());
                const ViewProjection vp = frameCamera(camera, positions.bounds(), 1024, 768);
                const FrameOrder frame = orderer.orderFrame(positions, vp);
                if (f == 0)
                    continue; // the first frame has no previous order to start from
                ms.push_back(frame.milliseconds);
                queries.push_back(double(frame.stats.queries));
                iterations.push_back(frame.stats.iterations);
            }
            const double frame_ms = median(ms);
            std::ostringstream detail;
            detail << median(queries) << " queries, " << median(iterations)
                   << " iterations per frame; " << std::setprecision(3)
                   << median(queries) / frame_ms / 1000 << " M queries/s";
            rows.push_back({workload.name, oracleName(kind), "ms per coherent frame (median)",
                            frame_ms, detail.str()});
        }
    }

    std::cout << std::left;
    for (const Row& row : rows) {
        std::cout << "  " << std::setw(66) << row.workload << std::setw(15) << row.oracle
                  << std::right << std::setw(10) << std::fixed << std::setprecision(3) << row.value
                  << ' ' << std::left << row.unit
                  << (row.detail.empty() ? "" : "  (" + row.detail + ")") << '\n';
    }
    if (!options.json_path.empty()) {
        nlohmann::json doc = {{"machine", machineName()}, {"rows", nlohmann::json::array()}};
        for (const Row& row : rows)
            doc["rows"].push_back({{"workload", row.workload},
                                   {"oracle", row.oracle},
                                   {"value", row.value},
                                   {"unit", row.unit},
                                   {"detail", row.detail}});
        if (const int code = writeJsonFile(options.json_path, doc); code != kExitOk)
            return code;
    }
    return kExitOk;
}

} // namespace vissort::cli
