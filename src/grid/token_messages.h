#pragma once
// How the grid readers show pieces of their files in error messages: cut short and with control
// characters replaced, so that a message stays one short line whatever the file holds, and why a
// token is not a finite number. Each reader passes its own length limit (tetgen's and Medit's
// readers quote 32 characters, the VTK readers 40). Internal to src/grid/.

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "grid/token_scanner.h"

namespace vissort::detail {

/// text as a message shows it: at most max_chars characters ("..." after them when it is longer),
/// control characters (a name's %0A, binary data read as a token) as '?'.
inline std::string shown(std::string_view text, std::size_t max_chars) {
    std::string shown_text(text.substr(0, max_chars));
    for (char& c : shown_text)
        if (uint8_t(c) < 32 || c == 127)
            c = '?';
    if (text.size() > max_chars)
        shown_text += "...";
    return shown_text;
}

/// shown(text, max_chars) between single quotes.
inline std::string quoted(std::string_view text, std::size_t max_chars) {
    // Appended rather than "'" + shown(): GCC 12 warns falsely (-Wrestrict) on that at -O2.
    std::string quoted_text = "'";
    quoted_text += shown(text, max_chars);
    quoted_text += '\'';
    return quoted_text;
}

/// Names as a message lists them: quoted, the first 10, then how many more.
inline std::string listed(const std::vector<std::string>& names, std::size_t max_chars) {
    std::string list;
    for (std::size_t i = 0; i < names.size() && i < 10; ++i) {
        if (i > 0)
            list += ", ";
        list += quoted(names[i], max_chars);
    }
    if (names.size() > 10)
        list += " and " + std::to_string(names.size() - 10) + " more";
    return list;
}

/// Why a token is not a finite number: "'nan' is not finite", "'1e999' is out of range" or "'x'
/// is not a number" (the token quoted to max_chars); "a value is missing" for an empty one.
inline std::string badNumber(std::string_view token, std::size_t max_chars) {
    if (token.empty())
        return "a value is missing";
    const std::string_view digits = withoutPlusSign(token);
    double value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end == digits.data() + digits.size() && error == std::errc::result_out_of_range)
        return quoted(token, max_chars) + " is out of range";
    if (error == std::errc() && end == digits.data() + digits.size() && !std::isfinite(value))
        return quoted(token, max_chars) + " is not finite";
    return quoted(token, max_chars) + " is not a number";
}

} // namespace vissort::detail
