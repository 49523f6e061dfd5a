// The colours the command line reads and prints: --background's forms.
#include "cli/colour_options.h"

#include <algorithm>
#include <charconv>

#include "cli/command_line_errors.h"

namespace vissort::cli {

std::string backgroundText(const Rgba& c) {
    return formatNumber(c.r) + ',' + formatNumber(c.g) + ',' + formatNumber(c.b);
}

Result<Rgba> parseBackground(const std::string& text) {
    if (text.empty())
        return {kDefaultBackground, {}};
    const auto bad = [&] {
        return Result<Rgba>::failure("expects R,G,B or R,G,B,A (each in [0, 1]) or #RRGGBB, got '" +
                                     text + "'");
    };
    if (text[0] == '#') {
        unsigned value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data() + 1, end, value, 16);
        if (text.size() != 7 || ec != std::errc() || ptr != end)
            return bad();
        return {Rgba{float((value >> 16) & 255) / 255, float((value >> 8) & 255) / 255,
                     float(value & 255) / 255, 1.0f},
                {}};
    }
    float channels[4] = {0, 0, 0, 1};
    std::size_t start = 0, count = 0;
    while (start <= text.size() && count < 5) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        double value = 0;
        const char* first = text.data() + start;
        const auto [ptr, ec] = std::from_chars(first, text.data() + comma, value);
        if (ec != std::errc() || ptr != text.data() + comma || !(value >= 0 && value <= 1) ||
            count == 4)
            return bad();
        channels[count++] = float(value);
        start = comma + 1;
    }
    if (count < 3)
        return bad();
    return {Rgba{channels[0], channels[1], channels[2], channels[3]}, {}};
}

} // namespace vissort::cli
