#include "scene/off_faces.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>
#include <string_view>
#include <vector>

namespace vissort::detail {
namespace {

// The line without its comment, split at whitespace.
void tokensOf(const std::string& line, std::vector<std::string_view>& out) {
    out.clear();
    std::string_view text(line);
    text = text.substr(0, text.find('#'));
    std::size_t at = 0;
    while (at < text.size()) {
        while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])))
            ++at;
        std::size_t end = at;
        while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])))
            ++end;
        if (end > at)
            out.push_back(text.substr(at, end - at));
        at = end;
    }
}

bool parseInteger(std::string_view token, int64_t& value) {
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    return error == std::errc() && end == token.data() + token.size();
}

// The OFF keyword with assimp's optional prefixes, [ST][C][N][4][n]OFF; has_dimension for 'n'.
bool isOffKeyword(std::string_view token, bool& has_dimension) {
    std::size_t at = token.substr(0, 2) == "ST" ? 2 : 0;
    for (const char prefix : {'C', 'N', '4'})
        if (at < token.size() && token[at] == prefix)
            ++at;
    has_dimension = at < token.size() && token[at] == 'n';
    return token.substr(at + (has_dimension ? 1 : 0)) == "OFF";
}

} // namespace

Result<OffFaces> readOffFaces(std::istream& in) {
    using R = Result<OffFaces>;
    std::string line;
    std::vector<std::string_view> tokens;
    // The header's tokens, across lines: [keyword [dimension]] vertices faces [edges].
    std::vector<int64_t> counts;
    bool keyword_seen = false, dimension_due = false;
    while (counts.size() < 2 && std::getline(in, line)) {
        tokensOf(line, tokens);
        for (std::string_view token : tokens) {
            bool has_dimension = false;
            if (!keyword_seen && counts.empty() && isOffKeyword(token, has_dimension)) {
                keyword_seen = true;
                dimension_due = has_dimension;
                continue;
            }
            int64_t value = 0;
            if (!parseInteger(token, value) || value < 0)
                return R::failure("the OFF header's counts are not whole numbers");
            if (dimension_due) {
                dimension_due = false;
                continue;
            }
            if (counts.size() < 2)
                counts.push_back(value); // the edge count after them is unused
        }
    }
    if (counts.size() < 2)
        return R::failure("the OFF header has no vertex and face counts");
    const int64_t vertices = counts[0], faces = counts[1];
    int64_t read = 0;
    while (read < vertices && std::getline(in, line)) {
        tokensOf(line, tokens);
        read += tokens.empty() ? 0 : 1;
    }
    if (read < vertices)
        return R::failure("the file ends after " + std::to_string(read) + " of its " +
                          std::to_string(vertices) + " vertices");
    OffFaces result;
    for (int64_t face = 0; face < faces;) {
        if (!std::getline(in, line))
            return R::failure("the file ends after " + std::to_string(face) + " of its " +
                              std::to_string(faces) + " faces");
        tokensOf(line, tokens);
        if (tokens.empty())
            continue;
        int64_t corners = 0;
        if (!parseInteger(tokens[0], corners) || corners < 0)
            return R::failure("face " + std::to_string(face) + " does not start with its " +
                              "number of corners");
        if (int64_t(tokens.size()) - 1 < corners)
            return R::failure("face " + std::to_string(face) + " declares " +
                              std::to_string(corners) + " corners but lists " +
                              std::to_string(tokens.size() - 1));
        for (int64_t k = 1; k <= corners; ++k) {
            int64_t index = 0;
            if (!parseInteger(tokens[std::size_t(k)], index) || index < 0 || index >= vertices)
                return R::failure("face " + std::to_string(face) + " refers to vertex " +
                                  std::string(tokens[std::size_t(k)]) + ", but the file has " +
                                  std::to_string(vertices) + " vertices");
        }
        result.fan_triangles += corners >= 3 ? uint64_t(corners - 2) : 0;
        result.most_corners = std::max(result.most_corners, uint64_t(corners));
        ++face;
    }
    return R{result, {}};
}

} // namespace vissort::detail
