#include "cli/bench_common.h"

#include <algorithm>
#include <charconv>

namespace vissort::cli {

bool parseCounts(const std::string& text, std::vector<uint32_t>& counts, uint32_t most) {
    counts.clear();
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        uint32_t count = 0;
        const char* first = text.data() + start;
        const char* last = text.data() + comma;
        if (std::from_chars(first, last, count).ptr != last || first == last || count < 1 ||
            count > most)
            return false;
        counts.push_back(count);
        start = comma + 1;
    }
    return !counts.empty();
}

} // namespace vissort::cli
