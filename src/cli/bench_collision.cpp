// `vissort bench collision`: options, then bench/collision_bench.h's figures as a table, JSON
// and a plot.

#include <algorithm>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/bench_common.h"
#include "cli/commands.h"
#include "cli/json_output.h"
#include "figures/line_plot.h"
#include "harnesses/collision_bench.h"
#include "harnesses/measurement.h"
#if VISSORT_WITH_GL
#include "vissort/transparency_renderer.h" // writePng
#endif

namespace vissort::cli {

namespace {

// "vissort,bullet": each a collision method; false with the error on anything else.
bool parseMethods(const std::string& text, std::vector<CollisionMethod>& methods,
                  std::string& error) {
    methods.clear();
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const Result<CollisionMethod> method =
            parseCollisionMethod(std::string_view(text).substr(start, comma - start));
        if (!method) {
            error = "--methods: " + method.error;
            return false;
        }
        methods.push_back(*method.value);
        start = comma + 1;
    }
    return true;
}

} // namespace

int runCollisionBench(const BenchOptions& options) {
    constexpr uint32_t kMostBodies = 100'000;
    bench::CollisionBenchSettings settings;
    if (!parseCounts(options.counts, settings.counts, kMostBodies))
        return fail(kExitUsage, "--counts must be numbers of bodies from 1 to " +
                                    std::to_string(kMostBodies) + ", comma-separated, got '" +
                                    options.counts + "'");
    if (options.collision_scene != "bunnies" && options.collision_scene != "pile")
        return fail(kExitUsage,
                    "--scene must be bunnies or pile, got '" + options.collision_scene + "'");
    settings.scene = options.collision_scene;
    std::string error;
    if (!parseMethods(options.methods, settings.methods, error))
        return fail(kExitUsage, error);
    if (!parseCounts(options.threads, settings.threads, 256))
        return fail(kExitUsage,
                    "--threads must be thread counts from 1 to 256, comma-separated, got '" +
                        options.threads + "'");
    const int frames = options.frames.value_or(30);
    if (frames < 1)
        return fail(kExitUsage, "--frames must be at least 1");
    settings.frames = frames;
    const std::vector<bench::CollisionContender> methods =
        bench::collisionContenders(settings.methods, settings.threads);
    const std::string scene = "builtin:" + settings.scene + "?n=N";

    std::cout << "bench collision: " << scene << ", " << frames
              << " timed frames each after one untimed; " << bench::machineName() << ", "
              << bench::hardwareThreads() << " cores (brute and fcl: one thread)\n";
    std::cout << std::setw(6) << "N" << std::setw(12) << "method" << std::setw(11) << "median ms"
              << std::setw(13) << "object pairs" << std::setw(15) << "triangle pairs"
              << std::setw(13) << "intersecting" << std::setw(8) << "missed" << std::setw(10)
              << "invented" << '\n';
    nlohmann::json rows = nlohmann::json::array();
    std::vector<samples::PlotSeries> series(methods.size());
    for (std::size_t i = 0; i < methods.size(); ++i)
        series[i].name = methods[i].name;
    std::size_t method_index = 0;
    std::vector<bench::CollisionBenchRow> measured;
    try {
        measured = bench::runCollisionBench(
            settings,
            [&](uint32_t n) {
                std::cerr << "bench collision: " << settings.scene << " n=" << n << "..."
                          << std::endl;
            },
            [&](const bench::CollisionBenchRow& m) {
                std::cout << std::setw(6) << m.n << std::setw(12) << m.method << std::setw(11)
                          << std::fixed << std::setprecision(2) << m.median_ms << std::setw(13)
                          << std::setprecision(1) << m.object_pairs << std::setw(15)
                          << std::setprecision(0) << m.triangle_pairs << std::setw(13)
                          << m.intersecting << std::setw(8) << m.missed << std::setw(10)
                          << m.invented << std::endl;
                std::cout.unsetf(std::ios::fixed);
                rows.push_back({{"n", m.n},
                                {"scene", settings.scene},
                                {"triangles", m.triangles},
                                {"method", m.method},
                                {"threads", m.threads},
                                {"median_ms", m.median_ms},
                                {"object_pairs", m.object_pairs},
                                {"triangle_pairs", m.triangle_pairs},
                                {"intersecting", m.intersecting},
                                {"missed", m.missed},
                                {"invented", m.invented}});
                samples::PlotSeries& line = series[method_index++ % methods.size()];
                line.x.push_back(m.n);
                line.y.push_back(m.median_ms);
            });
    } catch (const std::runtime_error& e) {
        return fail(kExitInput, e.what());
    }
    // The target of docs/collision.md: bullet's median over vissort's on the same threads.
    nlohmann::json speedups = nlohmann::json::array();
    const std::vector<bench::CollisionSpeedup> ratios =
        bench::bulletOverVissort(measured, settings);
    if (!ratios.empty()) {
        std::cout << "bullet / vissort, same threads:";
        for (const bench::CollisionSpeedup& r : ratios) {
            std::cout << "  N=" << r.n << " " << r.threads << "t " << std::fixed
                      << std::setprecision(2) << r.bullet_over_vissort << "x";
            std::cout.unsetf(std::ios::fixed);
            speedups.push_back({{"n", r.n},
                                {"threads", r.threads},
                                {"bullet_over_vissort", r.bullet_over_vissort}});
        }
        std::cout << '\n';
    }
    if (!options.json.path.empty()) {
        const nlohmann::json document = {{"benchmark", "collision"},
                                         {"machine", bench::machineName()},
                                         {"cores", bench::hardwareThreads()},
                                         {"scene", settings.scene},
                                         {"frames", frames},
                                         {"rows", rows},
                                         {"speedups", speedups}};
        if (const int code = writeJsonFile(options.json, document); code != kExitOk)
            return code;
    }
    if (!options.plot_path.empty()) {
#if !VISSORT_WITH_GL
        return fail(kExitFailure, "--plot: this vissort was built without OpenGL "
                                  "(VISSORT_WITH_GL=OFF) and writes no PNG");
#else
        const samples::Strip plot = samples::plotLines(
            series, "collision: ms per frame, " + scene + " (" + bench::machineName() + ")",
            "bodies N (" + scene + ")", "ms per frame", 900, 560, samples::AxisScale::logarithmic);
        if (Status error = writeImage(options.plot_path, plot.width, plot.height, plot.rgba);
            !error)
            return fail(kExitFailure, error.error);
#endif
    }
    return kExitOk;
}

} // namespace vissort::cli
