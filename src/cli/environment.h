#pragma once
// The environment variables the vissort command reads, in one place (the library reads none;
// README.md, "Environment"):
//   VISSORT_THREADS      threads of the cpu oracle's passes (default 1; 0: one per core); the
//                        `--threads` option of order, render and view wins over it
//   VISSORT_SIMD=0       the cpu oracle's scalar rows instead of AVX2 (benchmarks of the fallback)
//   VISSORT_GL_PLATFORM  auto, device or surfaceless: where the OpenGL context is made
//   LP_NUM_THREADS       set to 0 unless set: Mesa's llvmpipe then draws on the calling thread,
//                        4 times faster for the oracle's many small draws and queries
//   VISSORT_TEST_PAUSE_BEFORE_RENAME=S  for the tests of a run killed mid-write: each written
//                        file is held S seconds before its rename (atomic_file.h), said on stderr

#include <CLI/CLI.hpp>

#include "vissort/oracles.h"
#include "vissort/result.h"

namespace vissort::cli {

/// Reads the variables above and applies what the process needs before any work (LP_NUM_THREADS,
/// the shared GL context's platform). A one-line message when one holds a bad value.
Status applyEnvironment();

/// `--threads N` on a command whose ordering runs on the cpu oracle: its passes' threads, the
/// calling one included (default 1; 0: one per core); over VISSORT_THREADS.
void addThreadsOption(CLI::App& command);

/// The oracle options the environment and `--threads` ask for (threads, SIMD), for every oracle the
/// command makes. Valid after applyEnvironment.
const OracleOptions& environmentOracleOptions();

} // namespace vissort::cli
