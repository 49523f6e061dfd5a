#include "scenes/scene_parameters.h"

#include "vissort/closest_name.h"

#include <charconv>
#include <sstream>
#include <system_error>

namespace vissort::detail {
namespace {

// Accepts exactly what std::from_chars accepts and nothing around it: no spaces, no '+', no
// hexadecimal, and for integers no fractions, so "1.5" or "12x" are errors rather than silently
// 1 or 12.
template <class Number> std::errc parseWhole(const std::string& text, Number& value) {
    const char* end = text.data() + text.size();
    const auto [stop, code] = std::from_chars(text.data(), end, value);
    if (code != std::errc{})
        return code;
    return stop == end ? std::errc{} : std::errc::invalid_argument;
}

} // namespace

ParameterReader::ParameterReader(std::string scene, const SceneParameters& parameters)
    : scene_(std::move(scene)), parameters_(parameters) {}

const std::string* ParameterReader::find(const std::string& key) {
    known_keys_.insert(key);
    const auto it = parameters_.find(key);
    return it == parameters_.end() ? nullptr : &it->second;
}

void ParameterReader::fail(std::string message) {
    if (first_error_.empty())
        first_error_ = scene_ + ": " + std::move(message);
}

int64_t ParameterReader::integer(const std::string& key, int64_t default_value, int64_t min,
                                 int64_t max) {
    const std::string* text = find(key);
    if (!text)
        return default_value;
    const std::string range =
        " (allowed " + std::to_string(min) + " to " + std::to_string(max) + ")";
    int64_t value = 0;
    const std::errc code = parseWhole(*text, value);
    if (code == std::errc::result_out_of_range) {
        fail("parameter " + key + "=" + *text + " is out of range" + range);
        return default_value;
    }
    if (code != std::errc{}) {
        fail("parameter " + key + "='" + *text + "' is not an integer");
        return default_value;
    }
    if (value < min || value > max) {
        fail("parameter " + key + "=" + *text + " is out of range" + range);
        return default_value;
    }
    return value;
}

double ParameterReader::number(const std::string& key, double default_value, double min,
                               double max) {
    const std::string* text = find(key);
    if (!text)
        return default_value;
    // Digits with at most one point: from_chars alone would also take "1e3", "inf" and "nan".
    std::size_t digits = 0, points = 0;
    for (const char c : *text) {
        digits += c >= '0' && c <= '9';
        points += c == '.';
    }
    double value = 0;
    if (digits == 0 || points > 1 || digits + points != text->size() ||
        parseWhole(*text, value) != std::errc{}) {
        fail("parameter " + key + "='" + *text + "' is not a decimal number");
        return default_value;
    }
    if (value < min || value > max) {
        std::ostringstream range;
        range << " (allowed " << min << " to " << max << ")";
        fail("parameter " + key + "=" + *text + " is out of range" + range.str());
        return default_value;
    }
    return value;
}

uint64_t ParameterReader::seed(const std::string& key, uint64_t default_value) {
    const std::string* text = find(key);
    if (!text)
        return default_value;
    uint64_t value = 0;
    const std::errc code = parseWhole(*text, value);
    if (code == std::errc::result_out_of_range) {
        fail("parameter " + key + "=" + *text + " is out of range (allowed 0 to 2^64-1)");
        return default_value;
    }
    if (code != std::errc{}) {
        fail("parameter " + key + "='" + *text + "' is not a non-negative integer");
        return default_value;
    }
    return value;
}

std::string ParameterReader::error() const {
    if (!first_error_.empty())
        return first_error_;
    for (const auto& [key, value] : parameters_) {
        if (known_keys_.count(key))
            continue;
        std::string accepted;
        for (const std::string& known : known_keys_)
            accepted += (accepted.empty() ? "" : ", ") + known;
        return scene_ + ": unknown parameter '" + key + "' (" + didYouMeanFirst(key, known_keys_) +
               "accepted: " + accepted + ")";
    }
    return {};
}

} // namespace vissort::detail
