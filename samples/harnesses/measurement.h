#pragma once
// What the benchmark harnesses share: the clock, medians, the machine's name.

#include <chrono>
#include <string>
#include <vector>

namespace vissort::bench {

using BenchClock = std::chrono::steady_clock;

/// Seconds from start to now.
double secondsSince(BenchClock::time_point start);
/// The middle value (the upper one of an even count); 0 for none.
double median(std::vector<double> values);
/// The CPU's model name from /proc/cpuinfo, or "unknown CPU".
std::string machineName();
/// std::thread::hardware_concurrency(): the figures' "hardware threads" / "cores".
unsigned hardwareThreads();

} // namespace vissort::bench
