#include "harnesses/measurement.h"

#include <algorithm>
#include <fstream>
#include <thread>

namespace vissort::bench {

double secondsSince(BenchClock::time_point start) {
    return std::chrono::duration<double>(BenchClock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0 : values[values.size() / 2];
}

std::string machineName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0)
            return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

unsigned hardwareThreads() {
    return std::thread::hardware_concurrency();
}

} // namespace vissort::bench
