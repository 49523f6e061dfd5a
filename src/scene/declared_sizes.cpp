// Declared element counts against file sizes (see declared_sizes.h for why). Each format's
// bound is the fewest bytes an element can take in that format, so that no valid file is ever
// refused:
//  - OFF (text): a vertex or face is a line with at least one character and a line end (assimp's
//    line reader skips empty lines), so n elements take at least 2n - 1 bytes;
//  - ASCII PLY: each property value is a token of at least one character and a separator (a
//    list's count is a token too), so an element takes at least 2 bytes per property;
//  - binary PLY: the sum of its scalar properties' sizes and its lists' count sizes (a list can
//    be empty); an element without properties counts as 1 byte, since assimp still makes one
//    record for each;
//  - binary STL: exactly 84 + 50 n bytes (header, count, n facets of 50 bytes);
//  - classic NFF: a polygon's vertex is a line; generated spheres and cones get a budget.
// Counts are read as 64-bit, saturating: a count assimp would wrap to 32 bits is refused too.

#include "scene/declared_sizes.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <optional>
#include <vector>

namespace vissort::detail {
namespace {

constexpr uint64_t kSaturated = std::numeric_limits<uint64_t>::max();

uint64_t saturatingAdd(uint64_t a, uint64_t b) {
    return a > kSaturated - b ? kSaturated : a + b;
}

uint64_t saturatingMultiply(uint64_t a, uint64_t b) {
    return b != 0 && a > kSaturated / b ? kSaturated : a * b;
}

std::string lowercase(std::string_view text) {
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return lower;
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

/// A decimal count made of digits only (saturating), or nothing.
std::optional<uint64_t> parseCount(std::string_view token) {
    if (token.empty())
        return std::nullopt;
    uint64_t value = 0;
    for (const char c : token) {
        if (c < '0' || c > '9')
            return std::nullopt;
        value = saturatingAdd(saturatingMultiply(value, 10), static_cast<uint64_t>(c - '0'));
    }
    return value;
}

/// Whitespace-separated tokens of the OFF header, skipping '#' comments to the end of a line.
class OffTokens {
public:
    explicit OffTokens(std::string_view text) : text_(text) {}

    std::string_view next() {
        skipSpaceAndComments();
        const std::size_t begin = at_;
        while (at_ < text_.size() && !isSpace(text_[at_]) && text_[at_] != '#')
            ++at_;
        return text_.substr(begin, at_ - begin);
    }
    /// Where the next token starts.
    std::size_t nextOffset() {
        skipSpaceAndComments();
        return at_;
    }

private:
    void skipSpaceAndComments() {
        for (;;) {
            while (at_ < text_.size() && isSpace(text_[at_]))
                ++at_;
            if (at_ < text_.size() && text_[at_] == '#') {
                while (at_ < text_.size() && text_[at_] != '\n' && text_[at_] != '\r')
                    ++at_;
                continue;
            }
            break;
        }
    }

    std::string_view text_;
    std::size_t at_ = 0;
};

/// The OFF keyword with assimp's optional prefixes, in its order: [ST][C][N][4][n]OFF.
/// Sets has_dimension for the 'n' prefix (a dimension count follows the keyword).
bool isOffKeyword(std::string_view token, bool& has_dimension) {
    std::size_t at = 0;
    if (token.substr(at, 2) == "ST")
        at += 2;
    for (const char prefix : {'C', 'N', '4'})
        if (at < token.size() && token[at] == prefix)
            ++at;
    has_dimension = at < token.size() && token[at] == 'n';
    if (has_dimension)
        ++at;
    return token.substr(at) == "OFF";
}

std::string offProblem(std::string_view head, uint64_t file_size, bool off_extension) {
    OffTokens tokens(head);
    std::string_view token = tokens.next();
    bool has_dimension = false;
    if (isOffKeyword(token, has_dimension)) {
        if (has_dimension)
            tokens.next();
        token = tokens.next();
    } else if (!off_extension) {
        return {}; // not an OFF file
    }
    // assimp also reads the counts of a file without the keyword (the format allows it).
    const std::optional<uint64_t> vertices = parseCount(token);
    const std::optional<uint64_t> faces = parseCount(tokens.next());
    if (!vertices || !faces)
        return {}; // a header assimp will refuse on its own
    tokens.next(); // the edge count, unused
    const uint64_t first_element = tokens.nextOffset();
    const uint64_t body = file_size > first_element ? file_size - first_element : 0;
    const uint64_t elements = saturatingAdd(*vertices, *faces);
    const uint64_t needed = elements == 0 ? 0 : saturatingMultiply(elements, 2) - 1;
    if (needed <= body)
        return {};
    return "the OFF header declares " + std::to_string(*vertices) + " vertices and " +
           std::to_string(*faces) + " faces, at least " +
           std::to_string(saturatingAdd(needed, first_element)) + " bytes with the header, but " +
           "the file has " + std::to_string(file_size) + " bytes";
}

/// Bytes of one value of a PLY scalar type, 0 when the name is not one.
uint64_t plyTypeSize(std::string_view type) {
    const std::string t = lowercase(type);
    if (t == "char" || t == "int8" || t == "uchar" || t == "uint8")
        return 1;
    if (t == "short" || t == "int16" || t == "ushort" || t == "uint16")
        return 2;
    if (t == "int" || t == "int32" || t == "uint" || t == "uint32" || t == "float" ||
        t == "float32")
        return 4;
    if (t == "double" || t == "float64")
        return 8;
    return 0;
}

std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && isSpace(line[at]))
            ++at;
        const std::size_t begin = at;
        while (at < line.size() && !isSpace(line[at]))
            ++at;
        if (at > begin)
            out.push_back(line.substr(begin, at - begin));
    }
    return out;
}

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    uint64_t binary_bytes = 0; // fewest bytes of one element in a binary file
    uint64_t properties = 0;
};

/// Problems of a PLY header that make assimp 5.2.5 fail badly whatever the counts, found by the
/// mesh_file fuzzer: no end_header line (a read past its buffer, a segmentation fault, or with
/// "eNd_header" an endless loop; assimp matches it in lowercase only), and an element declared
/// twice (two "vertex" elements: it writes the second one's vertices into the first one's
/// array, past its end). Looks at every line, whether this file understands it or not.
std::string plyStructureProblem(std::string_view head, uint64_t file_size) {
    std::vector<std::string_view> elements;
    std::size_t at = 0;
    while (at < head.size()) {
        std::size_t end = at;
        while (end < head.size() && head[end] != '\n' && head[end] != '\r')
            ++end;
        const std::vector<std::string_view> line = words(head.substr(at, end - at));
        at = end + 1;
        if (line.empty())
            continue;
        if (line[0] == "end_header")
            return {};
        if (line[0] == "element" && line.size() >= 2) {
            if (std::find(elements.begin(), elements.end(), line[1]) != elements.end())
                return "the PLY header declares the element '" + std::string(line[1]) + "' twice";
            elements.push_back(line[1]);
        }
    }
    // No valid header is 64 KiB long.
    return "the PLY header has no end_header line" +
           std::string(file_size > head.size() ? " in its first 64 KiB" : "");
}

std::string plyProblem(std::string_view head, uint64_t file_size) {
    if (std::string problem = plyStructureProblem(head, file_size); !problem.empty())
        return problem;
    bool binary = false, has_format = false;
    std::vector<PlyElement> elements;
    std::size_t at = 0, header_end = 0;
    bool first = true;
    while (header_end == 0) {
        std::size_t end = at;
        while (end < head.size() && head[end] != '\n' && head[end] != '\r')
            ++end;
        if (end == head.size())
            return {}; // end_header without a line end: the file has no body
        const std::vector<std::string_view> line = words(head.substr(at, end - at));
        at = end + 1;
        if (head[end] == '\r' && at < head.size() && head[at] == '\n')
            ++at;
        if (first) {
            first = false;
            if (line.size() != 1 || lowercase(line[0]) != "ply")
                return {};
            continue;
        }
        if (line.empty())
            continue;
        const std::string keyword = lowercase(line[0]);
        if (keyword == "comment" || keyword == "obj_info") {
            continue;
        } else if (keyword == "format" && line.size() >= 2) {
            const std::string format = lowercase(line[1]);
            if (format != "ascii" && format != "binary_little_endian" &&
                format != "binary_big_endian")
                return {};
            binary = format != "ascii";
            has_format = true;
        } else if (keyword == "element" && line.size() == 3) {
            const std::optional<uint64_t> count = parseCount(line[2]);
            if (!count)
                return {};
            elements.push_back({std::string(line[1]), *count, 0, 0});
        } else if (keyword == "property" && !elements.empty()) {
            PlyElement& element = elements.back();
            if (line.size() == 5 && lowercase(line[1]) == "list") {
                const uint64_t count_size = plyTypeSize(line[2]);
                if (count_size == 0 || plyTypeSize(line[3]) == 0)
                    return {};
                element.binary_bytes += count_size;
            } else if (line.size() == 3) {
                const uint64_t size = plyTypeSize(line[1]);
                if (size == 0)
                    return {};
                element.binary_bytes += size;
            } else {
                return {};
            }
            ++element.properties;
        } else if (line[0] == "end_header") {
            header_end = at;
        } else {
            return {}; // a header this does not understand: assimp decides
        }
    }
    if (!has_format || elements.empty())
        return {};

    uint64_t needed = 0;
    for (const PlyElement& element : elements) {
        const uint64_t bytes = binary ? std::max<uint64_t>(element.binary_bytes, 1)
                                      : 2 * std::max<uint64_t>(element.properties, 1);
        needed = saturatingAdd(needed, saturatingMultiply(element.count, bytes));
    }
    // The last ASCII token needs no separator after it.
    if (!binary && needed > 0)
        --needed;
    const uint64_t body = file_size > header_end ? file_size - header_end : 0;
    if (needed <= body)
        return {};
    std::string declared;
    for (const PlyElement& element : elements)
        declared += (declared.empty() ? "" : ", ") + std::to_string(element.count) + " '" +
                    element.name + "'";
    return "the " + std::string(binary ? "binary" : "ASCII") + " PLY header declares " + declared +
           " elements, at least " + std::to_string(saturatingAdd(needed, header_end)) +
           " bytes with the " + std::to_string(header_end) + "-byte header, but the file has " +
           std::to_string(file_size) + " bytes";
}

std::string binaryStlProblem(std::string_view head, uint64_t file_size) {
    constexpr uint64_t kHeaderBytes = 84, kFacetBytes = 50;
    std::size_t at = 0;
    while (at < head.size() && isSpace(head[at]))
        ++at;
    if (lowercase(head.substr(at, 5)) == "solid")
        return {}; // ASCII (or binary with a matching size, which assimp tries first)
    if (file_size < kHeaderBytes || head.size() < kHeaderBytes)
        return {}; // assimp refuses a file too small for the header
    const auto byte = [&](std::size_t i) { return static_cast<uint64_t>(uint8_t(head[80 + i])); };
    const uint64_t facets = byte(0) | byte(1) << 8 | byte(2) << 16 | byte(3) << 24;
    const uint64_t expected = kHeaderBytes + kFacetBytes * facets;
    if (expected == file_size)
        return {};
    return "the binary STL header declares " + std::to_string(facets) + " triangles, " +
           std::to_string(expected) + " bytes, but the file has " + std::to_string(file_size) +
           " bytes";
}

/// The digits at the start of `text` as a saturating count (0 without digits), like assimp's
/// strtoul10 but without its 32-bit wrap.
uint64_t leadingCount(std::string_view text) {
    uint64_t value = 0;
    for (std::size_t i = 0; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i)
        value = saturatingAdd(saturatingMultiply(value, 10), static_cast<uint64_t>(text[i] - '0'));
    return value;
}

std::string_view skipSpaces(std::string_view text) {
    std::size_t at = 0;
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t'))
        ++at;
    return text.substr(at);
}

/// Classic NFF (not NFF2, whose first line is "nff"): the whole file, since its counts can be
/// anywhere. A polygon line "p N" ("pp N", "tpp N") is followed by N vertex lines; assimp
/// resizes its arrays to N first, and crashed (segmentation fault) on "p 300000000" in a
/// 70-byte file. "tess T" makes every later sphere "s" one of 20 x 4^T triangles and every cone
/// "c" about 4 T: generated, not read, so they get a budget rather than a proportion.
std::string nffProblem(std::string_view text, uint64_t file_size) {
    constexpr uint64_t kMaxGeneratedTriangles = 5'000'000;
    if (lowercase(skipSpaces(text.substr(0, 4))).starts_with("nff"))
        return {};
    uint64_t polygon_vertices = 0, generated = 0, tess = 4; // assimp's default level
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = at;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r')
            ++end;
        const std::string_view line = skipSpaces(text.substr(at, end - at));
        at = end + 1;
        const std::vector<std::string_view> tokens = words(line);
        if (tokens.empty())
            continue;
        if (line.starts_with("tpp") || line.starts_with("pp") || line.starts_with("p")) {
            const std::size_t keyword = line.starts_with("tpp")  ? 3
                                        : line.starts_with("pp") ? 2
                                                                 : 1;
            polygon_vertices =
                saturatingAdd(polygon_vertices, leadingCount(skipSpaces(line.substr(keyword))));
        } else if (tokens[0] == "tess" && tokens.size() >= 2) {
            tess = leadingCount(tokens[1]);
        } else if (tokens[0] == "s") {
            uint64_t sphere = 20;
            for (uint64_t level = 0; level < tess && sphere < kSaturated / 4; ++level)
                sphere *= 4;
            generated = saturatingAdd(generated, sphere);
        } else if (tokens[0] == "c") {
            generated = saturatingAdd(generated, saturatingMultiply(tess, 4));
        }
    }
    // A vertex line takes at least one character and a line end.
    if (saturatingMultiply(polygon_vertices, 2) > file_size)
        return "the NFF file declares " + std::to_string(polygon_vertices) +
               " polygon vertices, at least " +
               std::to_string(saturatingMultiply(polygon_vertices, 2)) +
               " bytes, but the file has " + std::to_string(file_size) + " bytes";
    if (generated > kMaxGeneratedTriangles)
        return "the NFF file's spheres and cones (tess " + std::to_string(tess) +
               ") would make more than " + std::to_string(kMaxGeneratedTriangles) + " triangles";
    return {};
}

} // namespace

std::string declaredSizeProblem(std::string_view head, uint64_t file_size,
                                std::string_view extension) {
    const std::string ext = lowercase(extension);
    // By signature first: assimp finds a PLY reader by its "ply" magic whatever the extension.
    if (lowercase(head.substr(0, 3)) == "ply")
        return plyProblem(head, file_size);
    if (ext == "stl")
        return binaryStlProblem(head, file_size);
    if (ext == "nff")
        return nffProblem(head, file_size);
    return offProblem(head, file_size, ext == "off");
}

bool declaredSizesNeedWholeFile(std::string_view extension) {
    return lowercase(extension) == "nff";
}

} // namespace vissort::detail
