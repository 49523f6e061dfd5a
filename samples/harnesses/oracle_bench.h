#pragma once
// `vissort bench oracle`: the oracles' cost on the synthetic setup-bound and fill-bound workloads
// (the CPU rasterizers) and on the real ones (the bunnies at triangle level, a stack of slabs at
// object level, along an orbit; the CPU rasterizers and OpenGL), every oracle measured in the same
// run so the figures are ratios on one machine.

#include <string>
#include <vector>

#include "vissort/oracles.h"
#include "vissort/result.h"

namespace vissort::bench {

struct OracleBenchSettings {
    int repeat = 3;               // runs per synthetic case (the best is kept), 1..100
    int frames = 11;              // frames of the real workloads, the first untimed, 2..1000
    int gl_frames = 5;            // frames through the gl oracle (at most frames), 2..1000
    OracleOptions oracle_options; // every oracle's (threads, SIMD)
};

/// One figure: a workload through one oracle.
struct OracleBenchRow {
    std::string workload, oracle, unit;
    double value = 0;
    std::string detail; // the real workloads: queries and iterations per frame
};

struct OracleBenchResult {
    /// "gl: RENDERER (VERSION), N frames", or "gl: not measured, REASON".
    std::string gl_line;
    std::vector<OracleBenchRow> rows;
};

/// Measures every benchmarked oracle (and gl when this build and machine have it) on every
/// workload. A one-line message when an oracle or a scene cannot be made; throws
/// std::runtime_error when a synthetic workload answers wrongly.
Result<OracleBenchResult> runOracleBench(const OracleBenchSettings& settings);

} // namespace vissort::bench
