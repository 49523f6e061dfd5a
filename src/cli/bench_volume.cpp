// `vissort bench volume`: options, then bench/volume_bench.h's figures as a table, JSON and a
// plot.

#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/bench_common.h"
#include "cli/commands.h"
#include "cli/json_output.h"
#include "figures/line_plot.h"
#include "harnesses/measurement.h"
#include "harnesses/volume_bench.h"

namespace vissort::cli {

int runVolumeBench(const BenchOptions& options) {
    constexpr uint32_t kMostCells = 5'000'000;
    std::vector<uint32_t> cells;
    if (!parseCounts(options.cells, cells, kMostCells))
        return fail(kExitUsage, "--cells must be numbers of tetrahedra from 1 to " +
                                    std::to_string(kMostCells) + ", comma-separated, got '" +
                                    options.cells + "'");
    bench::VolumeBenchSettings settings;
    settings.cells.assign(cells.begin(), cells.end());
    settings.frames = options.frames.value_or(5);
    if (settings.frames < 1)
        return fail(kExitUsage, "--frames must be at least 1");
    if (const std::string error =
            parseSize(options.size.value_or("512x512"), settings.width, settings.height);
        !error.empty())
        return fail(kExitUsage, error);

    std::cout << "bench volume: a cube (convex) and a knot (not) of about each --cells tetrahedra, "
              << settings.width << "x" << settings.height << ", " << settings.frames
              << " timed frames of an orbit after one untimed, tf " << settings.tf << "; "
              << bench::machineName() << ", " << bench::hardwareThreads() << " cores\n";
    std::cout << std::setw(24) << "grid" << std::setw(10) << "cells" << std::setw(10) << "method"
              << std::setw(11) << "median ms" << std::setw(10) << "order ms" << std::setw(13)
              << "Mcells/s" << std::setw(14) << "queries/cell" << std::setw(11) << "max error"
              << '\n';
    nlohmann::json rows = nlohmann::json::array();
    std::vector<samples::PlotSeries> series;
    const auto series_of = [&](const std::string& name) -> samples::PlotSeries& {
        for (samples::PlotSeries& s : series)
            if (s.name == name)
                return s;
        series.push_back({});
        series.back().name = name;
        return series.back();
    };
    bench::runVolumeBench(
        settings,
        [](const std::string& grid) {
            std::cerr << "bench volume: " << grid << "..." << std::endl;
        },
        [&](const bench::VolumeBenchRow& r) {
            std::cout << std::setw(24) << r.grid << std::setw(10) << r.cells << std::setw(10)
                      << r.method << std::fixed << std::setprecision(1) << std::setw(11)
                      << r.median_ms << std::setw(10) << r.median_order_ms << std::setprecision(2)
                      << std::setw(13) << r.cells_per_second / 1e6 << std::setw(14)
                      << r.queries_per_cell << std::setw(6) << r.max_error << "/255" << std::endl;
            std::cout.unsetf(std::ios::fixed);
            rows.push_back({{"grid", r.grid},
                            {"cells", r.cells},
                            {"convex", r.convex},
                            {"method", r.method},
                            {"median_ms", r.median_ms},
                            {"median_order_ms", r.median_order_ms},
                            {"median_composite_ms", r.median_composite_ms},
                            {"cells_per_second", r.cells_per_second},
                            {"queries_per_cell", r.queries_per_cell},
                            {"list_segments_per_cell", r.list_segments_per_cell},
                            {"max_error", r.max_error},
                            {"pixels_over_one", r.pixels_over_one}});
            samples::PlotSeries& line = series_of(r.method + (r.convex ? " (cube)" : " (knot)"));
            line.x.push_back(double(r.cells));
            line.y.push_back(r.median_ms);
        });
    if (!options.json.path.empty()) {
        const nlohmann::json document = {{"benchmark", "volume"},
                                         {"machine", bench::machineName()},
                                         {"cores", bench::hardwareThreads()},
                                         {"frames", settings.frames},
                                         {"size", {settings.width, settings.height}},
                                         {"rows", rows}};
        if (const int code = writeJsonFile(options.json, document); code != kExitOk)
            return code;
    }
    if (!options.plot_path.empty()) {
        const samples::Strip plot =
            samples::plotLines(series, "volume: ms per frame (" + bench::machineName() + ")",
                               "tetrahedra", "ms per frame", 900, 560);
        if (Status error = writeImage(options.plot_path, plot.width, plot.height, plot.rgba);
            !error)
            return fail(kExitFailure, error.error);
    }
    return kExitOk;
}

} // namespace vissort::cli
