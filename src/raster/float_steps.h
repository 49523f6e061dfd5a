#pragma once
// The neighbouring floats, inline: std::nextafter is a library call, and the tile bounds of
// FastCpuOracle step floats on every tile a draw or query visits (3% of a setup-bound draw).

#include <bit>
#include <cstdint>
#include <limits>

namespace vissort::detail {

/// std::nextafter(f, -infinity) for any f but NaN: floats of one sign are ordered as their bits.
inline float nextDown(float f) {
    if (f == 0) return -std::numeric_limits<float>::denorm_min();
    if (f == -std::numeric_limits<float>::infinity()) return f;
    const uint32_t bits = std::bit_cast<uint32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits - 1 : bits + 1);
}

/// std::nextafter(f, +infinity) for any f but NaN.
inline float nextUp(float f) { return -nextDown(-f); }

} // namespace vissort::detail
