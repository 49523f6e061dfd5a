// `vissort bench transparency`: options, then bench/transparency_bench.h's figures as a table
// (a row at a time) and JSON.

#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/bench_common.h"
#include "cli/commands.h"
#include "cli/json_output.h"
#include "cli/transparency_records.h"
#include "harnesses/measurement.h"
#include "harnesses/transparency_bench.h"

namespace vissort::cli {

int runTransparencyBench(const BenchOptions& options) {
    using bench::kTransparencyLinkedList;
    using bench::kTransparencyMethods;
    using bench::kTransparencyVissort;
    bench::TransparencyBenchSettings settings;
    const int frames = options.frames.value_or(3);
    if (frames < 2 || frames > 100)
        return fail(kExitUsage, "--frames must be 2..100");
    settings.frames = frames;
    uint32_t width = 0, height = 0;
    if (auto error = parseSize(options.size.value_or("1024x1024"), width, height); !error.empty())
        return fail(kExitUsage, error);
    settings.width = width;
    settings.height = height;
    const Result<OrderLevel> parsed_level = parseOrderLevel(options.level);
    if (!parsed_level)
        return fail(kExitUsage, "--level: " + parsed_level.error);
    const OrderLevel level = *parsed_level.value;
    settings.level = level;
    if (!parseCounts(options.depths, settings.depths))
        return fail(kExitUsage, "--depths expects depth complexities of 1 to 1000 separated by "
                                "commas, got '" +
                                    options.depths + "'");
    if (const Result<SampleGrid> grid = sampleGridOf(options.samples); !grid)
        return fail(kExitUsage, "--" + grid.error);
    settings.samples = uint32_t(options.samples);
    Result<std::shared_ptr<GlContext>> context = GlContext::shared();
    if (!context)
        return fail(kExitFailure, context.error);
    settings.context = *context.value;
    const GlContextInfo& gl = settings.context->info();

    std::cout << "vissort bench transparency on " << bench::machineName()
              << "\n  OpenGL: " << gl.renderer << " (" << gl.version << ")\n  " << width << 'x'
              << height
              << (settings.samples > 1
                      ? " at 1 and " + std::to_string(settings.samples) + " samples a pixel"
                      : std::string())
              << ", vissort at " << orderLevelName(level)
              << " level with the cpu oracle; milliseconds per frame, "
              << "median of " << frames - 1 << " frame(s) on an orbit after an untimed first\n";
    nlohmann::json rows = nlohmann::json::array();
    const bool sampled = settings.samples > 1;
    const auto print_family = [&](const bench::TransparencyFamily& family) {
        std::cout << '\n'
                  << family.name << ": " << family.description << '\n'
                  << "     D  seen" << (sampled ? " samples" : "") << std::right;
        for (BlendMethod method : kTransparencyMethods)
            std::cout << std::setw(19) << blendMethodName(method);
        std::cout << "   errors against linked-list (max/255)\n";
    };
    // One line of a row: each method's ms (and its ratio over vissort's), then the errors.
    const auto print_line = [&](const std::vector<bench::TransparencyMeasured>& measured) {
        const double vissort_ms = measured[kTransparencyVissort].ms;
        for (std::size_t i = 0; i < measured.size(); ++i) {
            std::ostringstream cell;
            cell << std::fixed << std::setprecision(1) << measured[i].ms;
            if (i != kTransparencyVissort)
                cell << " (" << measured[i].ms / vissort_ms << "x)";
            std::cout << std::setw(19) << cell.str();
        }
        std::cout << "   ";
        for (std::size_t i = 0; i < measured.size(); ++i)
            if (i != kTransparencyLinkedList)
                std::cout << (i > 0 ? ", " : "") << blendMethodName(kTransparencyMethods[i]) << ' '
                          << measured[i].max_abs;
        std::cout << '\n';
    };
    const auto print_row = [&](const bench::TransparencyBenchRow& row) {
        std::cout << std::setw(6) << row.depth << std::setw(6) << row.seen;
        if (sampled)
            std::cout << std::setw(8) << 1;
        print_line(row.methods);
        if (sampled) {
            std::cout << std::setw(20) << settings.samples;
            print_line(row.sampled);
            // What the samples cost each method: its time at them over its time at one.
            std::cout << std::setw(20) << "cost";
            for (std::size_t i = 0; i < row.methods.size(); ++i) {
                std::ostringstream cell;
                cell << std::fixed << std::setprecision(2) << row.sampled[i].ms / row.methods[i].ms
                     << 'x';
                std::cout << std::setw(19) << cell.str();
            }
            std::cout << '\n';
        }
        std::cout << std::flush; // a row at a time: a long run shows its progress
        for (nlohmann::json& record : transparencyRecords(row))
            rows.push_back(std::move(record));
    };
    const Result<std::vector<bench::TransparencyBenchRow>> measured =
        bench::runTransparencyBench(settings, print_family, print_row);
    if (!measured)
        return fail(kExitFailure, measured.error);
    std::cout << "\n(x): a method's time over vissort's; seen: the most transparent layers at a "
                 "pixel, from depth peeling's passes\n";
    if (sampled)
        std::cout << "cost: a method's time at " << settings.samples
                  << " samples a pixel over its time at 1\n";
    if (!options.json.path.empty()) {
        const nlohmann::json document = {{"machine", bench::machineName()},
                                         {"gl_renderer", gl.renderer},
                                         {"size", {width, height}},
                                         {"level", orderLevelName(level)},
                                         {"frames", frames},
                                         {"samples", settings.samples},
                                         {"rows", rows}};
        if (const int code = writeJsonFile(options.json, document); code != kExitOk)
            return code;
    }
    return kExitOk;
}

} // namespace vissort::cli
