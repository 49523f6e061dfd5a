#pragma once
// The JSON records of a `bench transparency` row, one per method: what `bench transparency
// --json` writes and `bench paper`'s figure 6 holds.

#include <nlohmann/json.hpp>

#include "harnesses/transparency_bench.h"

namespace vissort::cli {

/// {"scene", "specification", "depth", "depth_seen", "method", "samples", "ms", "order_ms",
/// "passes", "fragments", "ms_over_vissort", "error": {"max_abs", "rmse"} (not for linked-list,
/// the reference)} for each method of the row at 1 sample a pixel, and when the row has them,
/// again at row.samples a pixel (row.sampled) with "ms_over_one_sample" added.
nlohmann::json transparencyRecords(const bench::TransparencyBenchRow& row);

} // namespace vissort::cli
