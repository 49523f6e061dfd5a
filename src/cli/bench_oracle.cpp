// `vissort bench oracle`: options, then bench/oracle_bench.h's figures as a table and JSON.

#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/environment.h"
#include "cli/json_output.h"
#include "harnesses/measurement.h"
#include "harnesses/oracle_bench.h"

namespace vissort::cli {

int runOracleBench(const BenchOptions& options) {
    bench::OracleBenchSettings settings;
    settings.frames = options.frames.value_or(11);
    settings.repeat = options.repeat;
    settings.gl_frames = options.gl_frames.value_or(5);
    settings.oracle_options = environmentOracleOptions();
    if (settings.repeat < 1 || settings.repeat > 100)
        return fail(kExitUsage, "--repeat must be 1..100");
    if (settings.frames < 2 || settings.frames > 1000)
        return fail(kExitUsage, "--frames must be 2..1000");
    if (settings.gl_frames < 2 || settings.gl_frames > 1000)
        return fail(kExitUsage, "--gl-frames must be 2..1000");

    std::cout << "vissort bench oracle on " << bench::machineName() << ", "
              << bench::hardwareThreads() << " hardware threads\n";
    const Result<bench::OracleBenchResult> result = bench::runOracleBench(settings);
    if (!result)
        return fail(kExitFailure, result.error);
    std::cout << result.value->gl_line << '\n';
    std::cout << std::left;
    for (const bench::OracleBenchRow& row : result.value->rows) {
        std::cout << "  " << std::setw(66) << row.workload << std::setw(15) << row.oracle
                  << std::right << std::setw(10) << std::fixed << std::setprecision(3) << row.value
                  << ' ' << std::left << row.unit
                  << (row.detail.empty() ? "" : "  (" + row.detail + ")") << '\n';
    }
    if (!options.json.path.empty()) {
        nlohmann::json doc = {{"machine", bench::machineName()}, {"rows", nlohmann::json::array()}};
        for (const bench::OracleBenchRow& row : result.value->rows)
            doc["rows"].push_back({{"workload", row.workload},
                                   {"oracle", row.oracle},
                                   {"value", row.value},
                                   {"unit", row.unit},
                                   {"detail", row.detail}});
        if (const int code = writeJsonFile(options.json, doc); code != kExitOk)
            return code;
    }
    return kExitOk;
}

} // namespace vissort::cli
