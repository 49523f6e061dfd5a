// `vissort bench collision`: options, then bench/collision_bench.h's figures as a table, JSON
// and a plot.

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

int runCollisionBench(const BenchOptions& options) {
    std::vector<uint32_t> counts;
    if (!parseCounts(options.counts, counts))
        return fail(kExitUsage,
                    "--counts must be bunny counts from 1 to 1000, comma-separated, got '" +
                        options.counts + "'");
    const int frames = options.frames.value_or(30);
    if (frames < 1)
        return fail(kExitUsage, "--frames must be at least 1");
    bench::CollisionBenchSettings settings;
    settings.counts = counts;
    settings.frames = frames;
    const std::vector<bench::CollisionContender> methods = bench::collisionContenders();

    std::cout << "bench collision: builtin:bunnies?n=N, " << frames
              << " timed frames each after one untimed; " << bench::machineName() << ", "
              << bench::hardwareThreads() << " cores (vissort-1t and the peers: one thread)\n";
    std::cout << std::setw(5) << "N" << std::setw(12) << "method" << std::setw(11) << "median ms"
              << std::setw(13) << "object pairs" << std::setw(15) << "triangle pairs"
              << std::setw(13) << "intersecting" << std::setw(8) << "missed" << std::setw(10)
              << "invented" << '\n';
    nlohmann::json rows = nlohmann::json::array();
    std::vector<samples::PlotSeries> series(methods.size());
    for (std::size_t i = 0; i < methods.size(); ++i)
        series[i].name = methods[i].name;
    std::size_t method_index = 0;
    bench::runCollisionBench(
        settings,
        [](uint32_t n) { std::cerr << "bench collision: " << n << " bunnies..." << std::endl; },
        [&](const bench::CollisionBenchRow& m) {
            std::cout << std::setw(5) << m.bunnies << std::setw(12) << m.method << std::setw(11)
                      << std::fixed << std::setprecision(2) << m.median_ms << std::setw(13)
                      << std::setprecision(1) << m.object_pairs << std::setw(15)
                      << std::setprecision(0) << m.triangle_pairs << std::setw(13) << m.intersecting
                      << std::setw(8) << m.missed << std::setw(10) << m.invented << std::endl;
            std::cout.unsetf(std::ios::fixed);
            rows.push_back({{"bunnies", m.bunnies},
                            {"triangles", m.triangles},
                            {"method", m.method},
                            {"median_ms", m.median_ms},
                            {"object_pairs", m.object_pairs},
                            {"triangle_pairs", m.triangle_pairs},
                            {"intersecting", m.intersecting},
                            {"missed", m.missed},
                            {"invented", m.invented}});
            samples::PlotSeries& line = series[method_index++ % methods.size()];
            line.x.push_back(m.bunnies);
            line.y.push_back(m.median_ms);
        });
    if (!options.json.path.empty()) {
        const nlohmann::json document = {{"benchmark", "collision"},
                                         {"machine", bench::machineName()},
                                         {"cores", bench::hardwareThreads()},
                                         {"frames", frames},
                                         {"rows", rows}};
        if (const int code = writeJsonFile(options.json, document); code != kExitOk)
            return code;
    }
    if (!options.plot_path.empty()) {
#if !VISSORT_WITH_GL
        return fail(kExitFailure, "--plot: this vissort was built without OpenGL "
                                  "(VISSORT_WITH_GL=OFF) and writes no PNG");
#else
        const samples::Strip plot = samples::plotLines(
            series, "collision: ms per frame, deforming bunnies (" + bench::machineName() + ")",
            "bunnies N (builtin:bunnies?n=N)", "ms per frame", 900, 560);
        if (Status error = writeImage(options.plot_path, plot.width, plot.height, plot.rgba);
            !error)
            return fail(kExitFailure, error.error);
#endif
    }
    return kExitOk;
}

} // namespace vissort::cli
