#include "cli/bench_common.h"

#include <algorithm>
#include <charconv>
#include <fstream>

namespace vissort::cli {

double secondsSince(BenchClock::time_point start) {
    return std::chrono::duration<double>(BenchClock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0 : values[values.size() / 2];
}

bool parseCounts(const std::string& text, std::vector<uint32_t>& counts) {
    counts.clear();
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        uint32_t count = 0;
        const char* first = text.data() + start;
        const char* last = text.data() + comma;
        if (std::from_chars(first, last, count).ptr != last || first == last || count < 1 ||
            count > 1000)
            return false;
        counts.push_back(count);
        start = comma + 1;
    }
    return !counts.empty();
}

std::string machineName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0)
            return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

} // namespace vissort::cli
