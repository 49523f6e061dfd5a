// `vissort bench oracle`'s measurements (oracle_bench.h).

#include "harnesses/oracle_bench.h"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "harnesses/measurement.h"
#include "harnesses/oracle_workloads.h"
#include "scenes/scene_library.h"
#include "vissort/frame_driver.h"
#include "vissort/scene_orderer.h"
#if VISSORT_WITH_GL
#include "vissort/gl_context.h"
#endif

namespace vissort::bench {
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

} // namespace

Result<OracleBenchResult> runOracleBench(const OracleBenchSettings& settings) {
    using Failed = Result<OracleBenchResult>;
    const std::vector<OracleKind> kinds = benchmarkedOracles();
    OracleBenchResult result;
    std::vector<OracleBenchRow>& rows = result.rows;

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
            Result<std::unique_ptr<GeometryOracle>> made =
                makeOracle(kind, settings.oracle_options);
            if (!made)
                return Failed::failure(made.error);
            GeometryOracle* oracle = made.value->get();
            const SyntheticResult r = runSynthetic(*oracle, w, settings.repeat);
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
        real_oracles.push_back({kind, settings.frames});
#if VISSORT_WITH_GL
    if (Result<std::shared_ptr<GlContext>> context = GlContext::shared(); context) {
        real_oracles.push_back({OracleKind::gl, std::min(settings.frames, settings.gl_frames)});
        std::ostringstream line;
        line << "gl: " << (*context.value)->info().renderer << " ("
             << (*context.value)->info().version << "), " << real_oracles.back().second
             << " frames";
        result.gl_line = line.str();
    } else {
        result.gl_line = "gl: not measured, " + context.error;
    }
#else
    result.gl_line =
        "gl: not measured, this vissort was built without OpenGL (VISSORT_WITH_GL=OFF)";
#endif
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
        Result<Scene> loaded = samples::loadScene(workload.scene);
        if (!loaded)
            return Failed::failure(loaded.error);
        const Scene& scene = *loaded.value;
        const CameraSpec base =
            scene.camera.value_or(defaultCamera(scene.positions.bounds(), 1024.0 / 768));
        for (const auto& [kind, frames] : real_oracles) {
            Result<std::unique_ptr<GeometryOracle>> made =
                makeOracle(kind, settings.oracle_options);
            if (!made)
                return Failed::failure(made.error);
            GeometryOracle* oracle = made.value->get();
            SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                 workload.level, *oracle);
            FrameDriver driver(scene, base, CameraPath::orbit, 1024, 768);
            std::vector<double> ms, queries, iterations;
            for (int f = 0; f < frames; ++f) {
                driver.seek(f);
                const FrameOrder frame = orderer.orderFrame(driver.positions(), driver.view());
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
    return Result<OracleBenchResult>{std::move(result), {}};
}

} // namespace vissort::bench
