// Base64 decoding (RFC 4648, section 4), strict: the VTK XML reader relies on each encoded
// segment having exactly the length its byte count implies, so a bad character or a short group
// is an error rather than something skipped.

#include "grid/base64_decode.h"

#include <array>

namespace vissort::detail {

namespace {

// 0-63 for the alphabet's characters, 64 for the rest.
constexpr std::array<uint8_t, 256> makeDecodeTable() {
    std::array<uint8_t, 256> table{};
    for (auto& entry : table)
        entry = 64;
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (uint8_t i = 0; i < 64; ++i)
        table[uint8_t(alphabet[i])] = i;
    return table;
}
constexpr std::array<uint8_t, 256> kDecodeTable = makeDecodeTable();

} // namespace

bool decodeBase64(std::string_view text, std::string& out) {
    if (text.size() % 4 != 0)
        return false;
    out.reserve(out.size() + text.size() / 4 * 3);
    for (std::size_t i = 0; i < text.size(); i += 4) {
        const bool last_group = i + 4 == text.size();
        // Padding: "xx==" encodes one byte, "xxx=" two; only the last group may have it.
        std::size_t padding = 0;
        if (last_group && text[i + 3] == '=')
            padding = text[i + 2] == '=' ? 2 : 1;
        uint32_t bits = 0;
        for (std::size_t k = 0; k < 4 - padding; ++k) {
            const uint8_t value = kDecodeTable[uint8_t(text[i + k])];
            if (value == 64)
                return false;
            bits |= uint32_t(value) << (18 - 6 * k);
        }
        out.push_back(char(bits >> 16));
        if (padding < 2)
            out.push_back(char((bits >> 8) & 0xff));
        if (padding < 1)
            out.push_back(char(bits & 0xff));
    }
    return true;
}

} // namespace vissort::detail
