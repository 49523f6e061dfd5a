#pragma once
// Base64 (RFC 4648, section 4: the standard alphabet with '=' padding) decoding, for the binary
// data of VTK XML files. Internal to src/grid/.

#include <cstdint>
#include <string>
#include <string_view>

namespace vissort::detail {

/// The characters that encode byte_count bytes: 4 for every 3 bytes or part of 3.
inline uint64_t base64Length(uint64_t byte_count) {
    return byte_count / 3 * 4 + (byte_count % 3 != 0 ? 4 : 0);
}

/// Appends the bytes that text encodes to out; false (out then holds what was decoded) when text
/// is not whole groups of 4 characters of the alphabet, with '=' padding only at its end.
/// Whitespace is not skipped: callers remove it where the format allows it.
bool decodeBase64(std::string_view text, std::string& out);

} // namespace vissort::detail
