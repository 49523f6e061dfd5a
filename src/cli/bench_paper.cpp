// `vissort bench paper`: options, progress, then bench/paper_bench.h's figures as tables, and
// as files under --out: paper.json, paper.csv, figure6.csv and PNG plots with the paper's
// reported values marked.

#include <cerrno>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/json_output.h"
#include "cli/output_paths.h"
#include "cli/progress.h"
#include "figures/line_plot.h"
#include "harnesses/measurement.h"
#include "harnesses/paper_bench.h"
#include "vissort/image.h"
#if VISSORT_WITH_GL
#include "cli/transparency_records.h"
#include "vissort/gl_context.h"
#endif

namespace vissort::cli {
namespace {

using bench::PaperFrame;
using bench::PaperPath;

using bench::PaperMetric;

nlohmann::json optionalJson(const std::optional<double>& value) {
    return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

std::string cell(const std::optional<double>& value) {
    if (!value)
        return "";
    std::ostringstream text;
    text << *value;
    return text.str();
}

std::string shown(const std::optional<double>& value, int precision = 1) {
    if (!value)
        return "-";
    std::ostringstream text;
    text << std::fixed << std::setprecision(precision) << *value;
    return text.str();
}

nlohmann::json pathJson(const PaperPath& path) {
    const bench::PaperSummary s = bench::summarize(path);
    nlohmann::json frames = nlohmann::json::array();
    for (const PaperFrame& f : path.frames)
        frames.push_back({{"frame", f.frame},
                          {"cpu_queries", f.cpu_queries},
                          {"cpu_cycle_queries", f.cpu_cycle_queries},
                          {"cpu_cycles", f.cpu_cycles},
                          {"cpu_order_ms", f.cpu_order_ms},
                          {"gl_queries", f.gl_queries ? nlohmann::json(*f.gl_queries) : nullptr},
                          {"gl_order_ms", optionalJson(f.gl_order_ms)},
                          {"render_ms", optionalJson(f.render_ms)},
                          {"collide_ms", optionalJson(f.collide_ms)},
                          {"triangles_drawn", f.triangles_drawn}});
    nlohmann::json reported = nlohmann::json::array();
    for (const bench::PaperReported& r : path.reported)
        reported.push_back({{"what", r.what}, {"low_ms", r.low_ms}, {"high_ms", r.high_ms}});
    return {{"name", path.name},
            {"figure", path.figure},
            {"scene", path.specification},
            {"path", cameraPathName(path.path)},
            {"level", orderLevelName(path.level)},
            {"width", path.width},
            {"height", path.height},
            {"primitives", path.primitives},
            {"triangles", path.triangles},
            {"lod_error", path.lod_error},
            {"levels_ms", path.levels_ms},
            {"paper", reported},
            {"coherent_medians",
             {{"cpu_order_ms", optionalJson(s.cpu_order_ms)},
              {"gl_order_ms", optionalJson(s.gl_order_ms)},
              {"render_ms", optionalJson(s.render_ms)},
              {"collide_ms", optionalJson(s.collide_ms)},
              {"cpu_queries", optionalJson(s.cpu_queries)},
              {"cpu_cycle_queries", optionalJson(s.cpu_cycle_queries)},
              {"gl_queries", optionalJson(s.gl_queries)},
              {"cpu_queries_per_primitive", optionalJson(s.cpu_queries_per_primitive)},
              {"gl_queries_per_primitive", optionalJson(s.gl_queries_per_primitive)}}},
            {"frames", frames}};
}

} // namespace

std::vector<std::string> paperBenchFileNames() {
    return {"paper.json",
            "paper.csv",
            "figure6.csv",
            "figure6.png",
            "figure5-plant-ms.png",
            "figure5-plant-queries.png",
            "figure5-bunnies-ms.png",
            "figure5-bunnies-queries.png"};
}

namespace {

Status writeText(const std::filesystem::path& file, const std::string& text) {
    return writeTextFile(file.string(), [&](std::ostream& out) { out << text; });
}

std::string pathsCsv(const std::vector<PaperPath>& paths) {
    std::ostringstream csv;
    csv << "path,figure,scene,level,width,height,primitives,frame,cpu_queries,cpu_cycle_queries,"
           "cpu_order_ms,"
           "gl_queries,gl_order_ms,render_ms,collide_ms,lod_error,triangles_drawn\n";
    for (const PaperPath& path : paths)
        for (const PaperFrame& f : path.frames)
            csv << path.name << ',' << path.figure << ',' << path.specification << ','
                << orderLevelName(path.level) << ',' << path.width << ',' << path.height << ','
                << path.primitives << ',' << f.frame << ',' << f.cpu_queries << ','
                << f.cpu_cycle_queries << ',' << f.cpu_order_ms << ','
                << (f.gl_queries ? std::to_string(*f.gl_queries) : std::string()) << ','
                << cell(f.gl_order_ms) << ',' << cell(f.render_ms) << ',' << cell(f.collide_ms)
                << ',' << path.lod_error << ',' << f.triangles_drawn << '\n';
    return csv.str();
}

// A series of a per-frame value, frames without it (or with a value a log axis cannot show) left
// out.
samples::PlotSeries frameSeries(const std::string& name, const PaperPath& path,
                                PaperMetric metric) {
    samples::PlotSeries series{name, {}, {}};
    for (const PaperFrame& frame : path.frames)
        if (const std::optional<double> value = bench::metricOf(frame, metric);
            value && *value > 0) {
            series.x.push_back(frame.frame);
            series.y.push_back(*value);
        }
    return series;
}

// The paper's reported frame times as flat lines across the frames.
void addReported(std::vector<samples::PlotSeries>& series, const PaperPath& path) {
    const double last = path.frames.empty() ? 1 : path.frames.back().frame;
    for (const bench::PaperReported& r : path.reported) {
        std::vector<double> levels = {r.low_ms};
        if (r.high_ms != r.low_ms)
            levels.push_back(r.high_ms);
        for (const double ms : levels) {
            std::ostringstream name;
            name << r.what << " (" << std::lround(ms) << " ms)";
            series.push_back({name.str(), {0, last}, {ms, ms}, true});
        }
    }
}

Status writePlot(const std::filesystem::path& file, std::vector<samples::PlotSeries> series,
                 const std::string& title, const std::string& x_label, const std::string& y_label) {
    std::erase_if(series, [](const samples::PlotSeries& s) { return s.x.empty(); });
    if (series.empty())
        return {};
    const samples::Strip plot = samples::plotLines(series, title, x_label, y_label, 1000, 600);
    return writePng(file.string(), plot.width, plot.height, plot.rgba);
}

Status writePlots(const std::filesystem::path& out, const bench::PaperBenchResult& result) {
    const std::string machine = " (" + bench::machineName() + ")";
    const PaperPath& plant = result.paths[0];
    using enum PaperMetric;
    std::vector<samples::PlotSeries> plant_ms = {
        frameSeries("ordering, cpu oracle", plant, cpu_order_ms),
        frameSeries("ordering, gl oracle", plant, gl_order_ms),
        frameSeries("frame with transparency", plant, render_ms)};
    for (const PaperPath& path : result.paths)
        if (path.lod_error > 0) { // the ten-times plant, on the same walkthrough
            plant_ms.push_back(
                frameSeries("x10, levels of detail: ordering, cpu oracle", path, cpu_order_ms));
            plant_ms.push_back(
                frameSeries("x10, levels of detail: frame with transparency", path, render_ms));
        }
    addReported(plant_ms, plant);
    const std::string plant_what = "figure 5 (left): " + plant.specification + " walkthrough, " +
                                   std::to_string(plant.width) + "x" + std::to_string(plant.height);
    if (Status s = writePlot(out / "figure5-plant-ms.png", plant_ms, plant_what + machine, "frame",
                             "ms per frame");
        !s)
        return s;
    if (Status s = writePlot(
            out / "figure5-plant-queries.png",
            {frameSeries("cpu oracle", plant, cpu_queries),
             frameSeries("cpu oracle, of them the cycle search's", plant, cpu_cycle_queries),
             frameSeries("gl oracle", plant, gl_queries)},
            plant_what, "frame", "occlusion queries per frame");
        !s)
        return s;
    std::vector<samples::PlotSeries> bunnies_ms, bunnies_queries;
    for (std::size_t i = 1; i < result.paths.size(); ++i) {
        const PaperPath& path = result.paths[i];
        if (path.name.rfind("bunnies", 0) != 0)
            continue;
        const std::string viewer = path.path == CameraPath::fixed ? "static" : "moving";
        bunnies_ms.push_back(frameSeries(viewer + ": ordering", path, cpu_order_ms));
        bunnies_ms.push_back(frameSeries(viewer + ": with transparency", path, render_ms));
        bunnies_ms.push_back(frameSeries(viewer + ": collisions", path, collide_ms));
        bunnies_queries.push_back(frameSeries(viewer + ", cpu oracle", path, cpu_queries));
        bunnies_queries.push_back(frameSeries(viewer + ", gl oracle", path, gl_queries));
    }
    addReported(bunnies_ms, result.paths[1]);
    const std::string bunnies_what = "figure 5 (right): builtin:bunnies, " +
                                     std::to_string(plant.width) + "x" +
                                     std::to_string(plant.height);
    if (Status s = writePlot(out / "figure5-bunnies-ms.png", bunnies_ms, bunnies_what + machine,
                             "frame", "ms per frame");
        !s)
        return s;
    if (Status s = writePlot(out / "figure5-bunnies-queries.png", bunnies_queries, bunnies_what,
                             "frame", "occlusion queries per frame");
        !s)
        return s;
#if VISSORT_WITH_GL
    std::vector<samples::PlotSeries> figure6;
    for (const char* family : {"slabs", "plant"})
        for (const std::size_t m : {bench::kTransparencyVissort, bench::kTransparencyPeel,
                                    bench::kTransparencyDualPeel, bench::kTransparencyLinkedList}) {
            samples::PlotSeries series{std::string(family) + ": " +
                                           blendMethodName(bench::kTransparencyMethods[m]),
                                       {},
                                       {}};
            for (const bench::TransparencyBenchRow& row : result.figure6)
                if (row.family == family && row.methods[m].ms > 0) {
                    series.x.push_back(row.depth);
                    series.y.push_back(row.methods[m].ms);
                }
            figure6.push_back(series);
        }
    const auto& f6 = result.figure6_settings;
    if (Status s =
            writePlot(out / "figure6.png", figure6,
                      "figure 6: frame time against depth complexity, " + std::to_string(f6.width) +
                          "x" + std::to_string(f6.height) + machine,
                      "depth complexity D", "ms per frame");
        !s)
        return s;
#endif
    return {};
}

#if VISSORT_WITH_GL
std::string figure6Csv(const std::vector<bench::TransparencyBenchRow>& rows) {
    std::ostringstream csv;
    csv << "family,scene,depth,seen,method,ms,order_ms,passes,max_abs_vs_linked_list\n";
    for (const bench::TransparencyBenchRow& row : rows)
        for (std::size_t m = 0; m < row.methods.size(); ++m) {
            const bench::TransparencyMeasured& measured = row.methods[m];
            csv << row.family << ',' << row.specification << ',' << row.depth << ',' << row.seen
                << ',' << blendMethodName(bench::kTransparencyMethods[m]) << ',' << measured.ms
                << ',' << measured.order_ms << ',' << measured.passes << ',' << measured.max_abs
                << '\n';
        }
    return csv.str();
}

// Settings, and the rows as `bench transparency --json` writes them (a record a method).
nlohmann::json figure6Json(const bench::PaperBenchResult& result) {
    nlohmann::json rows = nlohmann::json::array();
    for (const bench::TransparencyBenchRow& row : result.figure6)
        for (nlohmann::json& record : transparencyRecords(row))
            rows.push_back(std::move(record));
    const auto& s = result.figure6_settings;
    return {{"width", s.width},
            {"height", s.height},
            {"level", orderLevelName(s.level)},
            {"frames", s.frames},
            {"rows", rows}};
}
#endif

void printSummary(const std::vector<PaperPath>& paths) {
    std::cout << std::left << std::setw(19) << "path" << std::setw(9) << "figure" << std::right
              << std::setw(10) << "prims" << std::setw(11) << "cpu ms" << std::setw(11) << "queries"
              << std::setw(10) << "q/prim" << std::setw(11) << "gl ms" << std::setw(10)
              << "gl q/prim" << std::setw(13) << "transp. ms" << std::setw(12) << "collide ms"
              << "   paper\n";
    for (const PaperPath& path : paths) {
        const bench::PaperSummary s = bench::summarize(path);
        std::string paper;
        for (const bench::PaperReported& r : path.reported)
            paper += (paper.empty() ? "" : "; ") + std::string(r.what);
        std::cout << std::left << std::setw(19) << path.name << std::setw(9) << path.figure
                  << std::right << std::setw(10) << path.primitives << std::setw(11)
                  << shown(s.cpu_order_ms) << std::setw(11) << shown(s.cpu_queries, 0)
                  << std::setw(10) << shown(s.cpu_queries_per_primitive, 2) << std::setw(11)
                  << shown(s.gl_order_ms) << std::setw(10) << shown(s.gl_queries_per_primitive, 2)
                  << std::setw(13) << shown(s.render_ms) << std::setw(12) << shown(s.collide_ms)
                  << "   " << paper << '\n';
    }
    // The levels of detail against the plant at full detail (issue 37's targets: at most 2x).
    const bench::PaperSummary plant = bench::summarize(paths[0]);
    for (const PaperPath& path : paths) {
        if (!(path.lod_error > 0))
            continue;
        const bench::PaperSummary s = bench::summarize(path);
        std::cout << path.name << ": " << path.specification << ", " << path.triangles
                  << " triangles, levels of detail within " << path.lod_error << " px (built in "
                  << shown(path.levels_ms / 1000, 1) << " s)";
        std::vector<double> drawn;
        for (const PaperFrame& f : path.frames)
            if (f.frame > 0)
                drawn.push_back(double(f.triangles_drawn));
        if (!drawn.empty())
            std::cout << ", " << shown(bench::median(drawn), 0) << " ordered a frame";
        const auto ratio = [](const std::optional<double>& a, const std::optional<double>& b) {
            return a && b && *b > 0 ? std::optional(*a / *b) : std::nullopt;
        };
        std::cout << "; against " << paths[0].name << " at full detail: ordering "
                  << shown(ratio(s.cpu_order_ms, plant.cpu_order_ms), 2) << "x, frame "
                  << shown(ratio(s.render_ms, plant.render_ms), 2) << "x\n";
    }
}

} // namespace

int runPaperBench(const BenchOptions& options) {
    bench::PaperBenchSettings settings;
    settings.quick = options.quick;
    if (options.frames) {
        if (*options.frames < 2 || *options.frames > 10000)
            return fail(kExitUsage, "--frames must be 2..10000 for bench paper");
        settings.frames = *options.frames;
    }
    if (options.gl_frames) {
        if (*options.gl_frames < 0)
            return fail(kExitUsage, "--gl-frames must be 0 or more");
        settings.gl_frames = *options.gl_frames;
    }
    if (options.size) {
        if (auto error = parseSize(*options.size, settings.width, settings.height); !error.empty())
            return fail(kExitUsage, error);
    }
    if (!(options.lod_error >= 0 && options.lod_error <= 1e6))
        return fail(kExitUsage, "--lod-error must be 0 (every triangle) or a number of pixels up "
                                "to 1e6, got " +
                                    std::to_string(options.lod_error));
    settings.lod_error = float(options.lod_error);
    const std::filesystem::path out = options.out_dir;
    std::error_code error;
    std::filesystem::create_directories(out, error);
    if (error || !std::filesystem::is_directory(out))
        return fail(kExitFailure, "--out " + options.out_dir + ": cannot create the folder (" +
                                      error.message() + ")");
    std::string gl_line;
#if VISSORT_WITH_GL
    if (Result<std::shared_ptr<GlContext>> context = GlContext::shared(); context) {
        settings.context = *context.value;
        gl_line = settings.context->info().renderer + " (" + settings.context->info().version + ")";
        if (const int gl_frames = bench::paperGlFrames(settings); gl_frames > 0)
            gl_line += "; the gl oracle on the first " + std::to_string(gl_frames) + " frames";
        else
            gl_line += options.gl_frames ? "; the gl oracle not measured (--gl-frames 0)"
                                         : "; the gl oracle not measured on a software renderer "
                                           "(--gl-frames N measures it: minutes a frame)";
    } else {
        gl_line = "not measured: " + context.error;
    }
#else
    gl_line = "not measured: this vissort was built without OpenGL (VISSORT_WITH_GL=OFF)";
#endif
    std::cout << "vissort bench paper" << (settings.quick ? " --quick" : "") << " on "
              << bench::machineName() << ", " << bench::hardwareThreads() << " cores\n"
              << "  OpenGL: " << gl_line << "\n  medians over the coherent frames (all but the "
              << "first); cpu oracle on one thread\n";
    Result<bench::PaperBenchResult> result = [&] {
        std::optional<Progress> progress;
        return bench::runPaperBench(settings, [&](const std::string& what, int done, int total) {
            if (!progress)
                progress.emplace("bench paper", uint64_t(total), "step");
            progress->update(done, what);
        });
    }();
    if (!result)
        return fail(kExitInput, result.error);
    const bench::PaperBenchResult& measured = *result.value;
    printSummary(measured.paths);

    nlohmann::json paths = nlohmann::json::array();
    for (const PaperPath& path : measured.paths)
        paths.push_back(pathJson(path));
    nlohmann::json document = {{"benchmark", "paper"},
                               {"machine", bench::machineName()},
                               {"cores", bench::hardwareThreads()},
                               {"quick", settings.quick},
                               {"gl_frames", bench::paperGlFrames(settings)},
                               {"gl", gl_line},
                               {"paths", paths},
                               {"figure6", nullptr}};
#if VISSORT_WITH_GL
    if (settings.context) {
        document["figure6"] = figure6Json(measured);
        if (Status s = writeText(out / "figure6.csv", figure6Csv(measured.figure6)); !s)
            return fail(kExitFailure, s.error);
    }
#endif
    if (const int code = writeJsonFile(JsonOutput{(out / "paper.json").string(), true}, document);
        code != kExitOk)
        return code;
    if (Status s = writeText(out / "paper.csv", pathsCsv(measured.paths)); !s)
        return fail(kExitFailure, s.error);
    if (Status s = writePlots(out, measured); !s)
        return fail(kExitFailure, s.error);
    std::cout << "wrote " << (out / "paper.json").string() << ", paper.csv"
              << (settings.context ? ", figure6.csv" : "") << " and the plots (figure5-*.png"
              << (settings.context ? ", figure6.png" : "") << ")\n";
    return kExitOk;
}

} // namespace vissort::cli
