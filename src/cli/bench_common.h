#pragma once
// What the bench commands' option parsing shares (the measurements are in bench/).

#include <cstdint>
#include <string>
#include <vector>

namespace vissort::cli {

/// Parses "2,4,8": each a whole number from 1 to most. False on anything else or an empty list.
bool parseCounts(const std::string& text, std::vector<uint32_t>& counts, uint32_t most = 1000);

} // namespace vissort::cli
