#pragma once
// What the benchmarks share: the clock, medians, the machine's name.

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace vissort::cli {

using BenchClock = std::chrono::steady_clock;

double secondsSince(BenchClock::time_point start);
/// The middle value (the upper one of an even count); 0 for none.
double median(std::vector<double> values);
/// Parses "2,4,8": each a whole number from 1 to 1000. False on anything else or an empty list.
bool parseCounts(const std::string& text, std::vector<uint32_t>& counts);
/// The CPU's model name from /proc/cpuinfo, or "unknown CPU".
std::string machineName();

} // namespace vissort::cli
