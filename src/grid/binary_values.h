#pragma once
// The numeric types of VTK's data arrays and how their values are read: from binary data in
// either byte order (big-endian in legacy .vtk files, the file's byte_order in .vtu ones) or from
// ASCII tokens. What both VTK readers share, so that a value reads, and its problems are worded,
// the same way in both. Internal to src/grid/.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "grid/token_messages.h"
#include "grid/token_scanner.h"

namespace vissort::detail {

/// The numeric element types of VTK arrays, by their size and kind in binary data.
enum class NumericType : uint8_t {
    int8,
    uint8,
    int16,
    uint16,
    int32,
    uint32,
    int64,
    uint64,
    float32,
    float64
};

/// Bytes per value in binary data: 1, 2, 4 or 8.
inline uint64_t numericSize(NumericType type) {
    switch (type) {
    case NumericType::int8:
    case NumericType::uint8:
        return 1;
    case NumericType::int16:
    case NumericType::uint16:
        return 2;
    case NumericType::int32:
    case NumericType::uint32:
    case NumericType::float32:
        return 4;
    case NumericType::int64:
    case NumericType::uint64:
    case NumericType::float64:
        return 8;
    }
    return 0;
}

inline bool isFloat(NumericType type) {
    return type == NumericType::float32 || type == NumericType::float64;
}

/// The size bytes (at most 8) of one binary value as its bits, in the file's byte order.
inline uint64_t loadBits(const unsigned char* bytes, uint64_t size, bool big_endian) {
    uint64_t bits = 0;
    if (big_endian)
        for (uint64_t i = 0; i < size; ++i)
            bits = bits << 8 | bytes[i];
    else
        for (uint64_t i = 0; i < size; ++i)
            bits |= uint64_t(bytes[i]) << (8 * i);
    return bits;
}

/// A binary value of type, as loadBits() gives its bits, as a double.
inline double realFromBits(NumericType type, uint64_t bits) {
    switch (type) {
    case NumericType::int8:
        return double(int8_t(bits));
    case NumericType::int16:
        return double(int16_t(bits));
    case NumericType::int32:
        return double(int32_t(bits));
    case NumericType::int64:
        return double(int64_t(bits));
    case NumericType::float32: {
        const uint32_t narrow = uint32_t(bits);
        float value;
        std::memcpy(&value, &narrow, sizeof value);
        return value;
    }
    case NumericType::float64: {
        double value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }
    default:
        return double(bits); // the unsigned types
    }
}

/// An integral binary value of type as an int64_t; nullopt for an unsigned 64-bit value beyond it.
inline std::optional<int64_t> integerFromBits(NumericType type, uint64_t bits) {
    switch (type) {
    case NumericType::int8:
        return int8_t(bits);
    case NumericType::int16:
        return int16_t(bits);
    case NumericType::int32:
        return int32_t(bits);
    case NumericType::int64:
        return int64_t(bits);
    case NumericType::uint64:
        if (bits > uint64_t(INT64_MAX))
            return std::nullopt;
        return int64_t(bits);
    default:
        return int64_t(bits); // the unsigned types narrower than 64 bits
    }
}

/// Appends every stride-th of count binary values of type at data, in the given byte order, to
/// out: as doubles, or as int64_t (which needs an integral type). The caller has checked that
/// data holds them. Returns the problem, "value N is out of range" for an unsigned 64-bit value
/// beyond int64_t, or an empty string.
template <class T>
std::string appendBinaryValues(NumericType type, const unsigned char* data, uint64_t count,
                               uint64_t stride, bool big_endian, std::vector<T>& out) {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, int64_t>);
    const uint64_t size = numericSize(type);
    out.reserve(count / stride + 1);
    for (uint64_t i = 0; i < count; i += stride) {
        const uint64_t bits = loadBits(data + i * size, size, big_endian);
        if constexpr (std::is_same_v<T, double>) {
            out.push_back(realFromBits(type, bits));
        } else {
            const std::optional<int64_t> value = integerFromBits(type, bits);
            if (!value)
                return "value " + std::to_string(bits) + " is out of range";
            out.push_back(*value);
        }
    }
    return {};
}

/// An ASCII number, NaN and infinities included (a skipped array may hold them; kept values are
/// checked for being finite apart, with a message that says so). Overflow reads as infinity.
inline std::optional<double> parseReal(std::string_view token) {
    token = withoutPlusSign(token);
    double value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (token.empty() || end != token.data() + token.size())
        return std::nullopt;
    if (error == std::errc::result_out_of_range)
        return HUGE_VAL;
    if (error != std::errc())
        return std::nullopt;
    return value;
}

/// An ASCII value of an array read as T: a number (parseReal) for double, a whole integer for
/// int64_t.
template <class T> std::optional<T> parseAsciiValue(std::string_view token) {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, int64_t>);
    if constexpr (std::is_same_v<T, double>)
        return parseReal(token);
    else
        return TokenScanner::parseInteger(token);
}

/// Why parseAsciiValue<T>() refused token, for a message: "value 'x' is not a number" (or "not an
/// integer"), the token cut at max_chars.
template <class T> std::string badAsciiValue(std::string_view token, std::size_t max_chars) {
    return "value " + quoted(token, max_chars) +
           (std::is_same_v<T, double> ? " is not a number" : " is not an integer");
}

} // namespace vissort::detail
