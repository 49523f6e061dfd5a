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
    std::vector<bool> is_list; // per property, in order
};

/// An ASCII PLY body's list counts against the bytes after them: a list of c values takes at
/// least 2c - 1 more bytes (assimp 5.2.5 reserves a list's count before reading it: the
/// mesh_file fuzzer's 219-byte file asked for 27 GB). Scans what `body` holds (the whole file up
/// to kDeclaredSizeWholeFileBytes); a token that is not a count is left to assimp.
std::string asciiPlyListProblem(std::string_view body, const std::vector<PlyElement>& elements) {
    std::size_t at = 0;
    const auto next = [&]() -> std::string_view {
        while (at < body.size() && std::isspace(static_cast<unsigned char>(body[at])))
            ++at;
        const std::size_t begin = at;
        while (at < body.size() && !std::isspace(static_cast<unsigned char>(body[at])))
            ++at;
        return body.substr(begin, at - begin);
    };
    for (const PlyElement& element : elements)
        for (uint64_t record = 0; record < element.count; ++record)
            for (const bool list : element.is_list) {
                const std::string_view token = next();
                if (token.empty())
                    return {}; // the end of what was read
                if (!list)
                    continue;
                // assimp reads the leading digits, whatever follows them ("777...7\xff...").
                std::size_t digits = 0;
                while (digits < token.size() && token[digits] >= '0' && token[digits] <= '9')
                    ++digits;
                const std::optional<uint64_t> count = parseCount(token.substr(0, digits));
                if (digits == 0 || !count)
                    return {};
                const uint64_t after = body.size() - at;
                if (*count > 0 && saturatingMultiply(*count, 2) - 1 > after)
                    return "the ASCII PLY body has a list of " +
                           (digits <= 20 ? std::string(token.substr(0, digits))
                                         : std::to_string(digits) + "-digit") +
                           " values in '" + element.name + "' " + std::to_string(record) +
                           " with " + std::to_string(after) + " bytes left";
                for (uint64_t i = 0; i < *count; ++i)
                    if (next().empty())
                        return {};
            }
    return {};
}

/// Whether a header line is end_header: the lowercase word alone, spaces and tabs around it
/// (assimp matches it in lowercase only, and looped forever on "eNd_header").
bool isPlyEndHeader(std::string_view line) {
    constexpr std::string_view kToken = "end_header";
    std::size_t at = 0;
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t'))
        ++at;
    if (line.substr(at, kToken.size()) != kToken)
        return false;
    for (at += kToken.size(); at < line.size(); ++at)
        if (line[at] != ' ' && line[at] != '\t')
            return false;
    return true;
}

std::string byteName(char c) {
    static constexpr char kHex[] = "0123456789abcdef";
    const auto byte = static_cast<unsigned char>(c);
    return std::string("0x") + kHex[byte >> 4] + kHex[byte & 15];
}

std::string_view lineEndName(std::string_view end) {
    return end == "\n" ? "\\n" : end == "\r" ? "\\r" : "\\r\\n";
}

/// Problems of a PLY header that make assimp 5.2.5 fail badly whatever the counts, found by the
/// mesh_file fuzzer and by trying every line end around its lines:
///  - no end_header line: a read past its buffer (a segmentation fault) or an endless loop;
///  - an element declared twice (two "vertex" elements: it writes the second one's vertices
///    into the first one's array, past its end);
///  - a control character other than a tab before end_header (a vertical tab or form feed
///    next to end_header: an endless loop);
///  - line ends other than one kind throughout ("\n", "\r\n" or "\r"), or a blank line where
///    they are not "\n": assimp's line reader then loops forever ("\r\r", "\n\r" before
///    end_header) or silently drops a line ("\r\n\r\n" after an element: its properties go
///    to the element before).
/// Looks at every line, whether this file understands it or not.
std::string plyStructureProblem(std::string_view head, uint64_t file_size) {
    std::vector<std::string_view> elements;
    std::string_view line_end; // the header's kind, from its first line
    std::size_t at = 0;
    while (at < head.size()) {
        std::size_t end = at;
        while (end < head.size() && head[end] != '\n' && head[end] != '\r')
            ++end;
        const std::string_view text = head.substr(at, end - at);
        if (isPlyEndHeader(text))
            return {};
        for (std::size_t i = 0; i < text.size(); ++i)
            if (static_cast<unsigned char>(text[i]) < 0x20 && text[i] != '\t')
                return "the PLY header has the control character " + byteName(text[i]) +
                       " at byte " + std::to_string(at + i);
        const std::string_view this_end = head.substr(end, head.substr(end, 2) == "\r\n" ? 2 : 1);
        if (line_end.empty())
            line_end = this_end;
        else if (!this_end.empty() && this_end != line_end)
            return "the PLY header mixes line ends (" + std::string(lineEndName(line_end)) +
                   " and " + std::string(lineEndName(this_end)) + " at byte " +
                   std::to_string(end) + "), which assimp misreads: save it with one kind";
        if (text.empty() && line_end != "\n")
            return "the PLY header has a blank line at byte " + std::to_string(at) + " with " +
                   std::string(lineEndName(line_end)) +
                   " line ends, which assimp misreads: remove it";
        at = end + this_end.size();
        const std::vector<std::string_view> line = words(text);
        if (line.size() >= 2 && line[0] == "element") {
            if (std::find(elements.begin(), elements.end(), line[1]) != elements.end())
                return "the PLY header declares the element '" + std::string(line[1]) + "' twice";
            elements.push_back(line[1]);
        }
    }
    // No valid header is 64 KiB long.
    return "the PLY header has no end_header line (the word alone on its line)" +
           std::string(file_size > head.size() ? " in its first 64 KiB" : "");
}

// A header line as the messages quote it: printable bytes as they are, others as 0xNN, at most
// 40 characters.
std::string quotedLine(std::string_view text) {
    std::string quoted;
    for (char c : text.substr(0, 40))
        quoted += static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f
                      ? std::string(1, c)
                      : byteName(c);
    return "'" + quoted + (text.size() > 40 ? "...'" : "'");
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
        const std::string_view text = head.substr(at, end - at);
        const std::vector<std::string_view> line = words(text);
        at = end + 1;
        if (head[end] == '\r' && at < head.size() && head[at] == '\n')
            ++at;
        if (first) {
            if (line.empty())
                continue; // line ends before the magic
            first = false;
            // assimp takes any file starting with "ply" for PLY: a first line with more than
            // the magic ("ply`", found by the fuzzer) would reach it with the header unchecked.
            if (line.size() != 1 || lowercase(line[0]) != "ply")
                return "the PLY file starts with " + quotedLine(text) +
                       ", where the format has the line 'ply' alone";
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
        } else if (keyword == "property") {
            // Lines the PLY format does not have are refused, not left to assimp 5.2.5: the
            // mesh_file fuzzer found a 444-byte file with a mangled element line and property
            // type on which it grew to 15 GB over 44 s.
            if (elements.empty())
                return "the PLY header has a property before any element: " + quotedLine(text);
            PlyElement& element = elements.back();
            if (line.size() == 5 && lowercase(line[1]) == "list") {
                const uint64_t count_size = plyTypeSize(line[2]);
                if (count_size == 0 || plyTypeSize(line[3]) == 0)
                    return "the PLY header has a list of a type PLY does not have: " +
                           quotedLine(text);
                element.binary_bytes += count_size;
                element.is_list.push_back(true);
            } else if (line.size() == 3) {
                const uint64_t size = plyTypeSize(line[1]);
                if (size == 0)
                    return "the PLY header has a property of a type PLY does not have: " +
                           quotedLine(text);
                element.binary_bytes += size;
                element.is_list.push_back(false);
            } else {
                return "the PLY header has a property line PLY does not have: " + quotedLine(text);
            }
            ++element.properties;
        } else if (isPlyEndHeader(text)) {
            header_end = at;
        } else if (keyword == "element") {
            return "the PLY header has an element line PLY does not have (element NAME COUNT): " +
                   quotedLine(text);
        }
        // Any other line is skipped, as assimp skips it: exporters write lines of their own
        // (Blender 2.47: "Created by Blender3D 247 - www.blender.org, source file: ..."). The
        // lines that can make assimp allocate without bound are the element and property
        // lines, checked above.
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
        return binary ? std::string() : asciiPlyListProblem(head.substr(header_end), elements);
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

/// A binary glTF (GLB): the "glTF" magic, a version, the file's length, then chunks of a length
/// and a type. assimp 5.2.5 allocates the first chunk's declared length before reading it (the
/// mesh_file fuzzer's 536-byte file declared 1.67 GB and passed a 2 GB limit).
bool isBinaryGltf(std::string_view head) {
    return head.substr(0, 4) == "glTF";
}

std::string binaryGltfProblem(std::string_view head, uint64_t file_size) {
    constexpr uint64_t kHeaderBytes = 12, kChunkHeaderBytes = 8;
    const auto word = [&](std::size_t at) {
        uint64_t value = 0;
        for (std::size_t i = 0; i < 4; ++i)
            value |= static_cast<uint64_t>(uint8_t(head[at + i])) << (8 * i);
        return value;
    };
    if (head.size() < kHeaderBytes + kChunkHeaderBytes)
        return {}; // assimp refuses a file too small for its headers
    const uint64_t length = word(8), chunk = word(12);
    if (length > file_size)
        return "the binary glTF header declares " + std::to_string(length) +
               " bytes, but the file has " + std::to_string(file_size) + " bytes";
    if (chunk > file_size - std::min(file_size, kHeaderBytes + kChunkHeaderBytes))
        return "the binary glTF's first chunk declares " + std::to_string(chunk) +
               " bytes, more than the " + std::to_string(file_size) + "-byte file holds";
    return {};
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

/// A count no file of `file_size` bytes can hold: more elements than it has bytes.
std::string countProblem(std::string_view format, uint64_t count, std::size_t at,
                         uint64_t file_size) {
    return "the " + std::string(format) + " declares " + std::to_string(count) +
           " elements at byte " + std::to_string(at) + ", more than the file's " +
           std::to_string(file_size) + " bytes can hold";
}

/// Text DirectX (.x): assimp 5.2.5 resizes its arrays to every count it reads (vertices, faces,
/// normals, texture coordinates, colours, material indices, weights, keys) before reading the
/// elements: 300 million vertices in 83 bytes took 23 s and 3.5 GB. A count stands alone
/// between '{' or ';' and ';', and every element takes at least a byte, so such an unsigned
/// integer larger than the file is refused. List items follow ',' (DeclData's raw 32-bit words
/// are such a list, and large). Only a coordinate written as a large integer, without a decimal
/// point, could be refused wrongly; exporters write "%f". Skips comments, strings and GUIDs.
std::string directXTextProblem(std::string_view text, uint64_t file_size) {
    std::size_t at = 16; // past "xof 0302txt 0032"
    char before = '{';   // the last punctuation or word seen: '{', ';', ',', ... or 'w'
    while (at < text.size()) {
        const char c = text[at];
        if (c == '#' || (c == '/' && at + 1 < text.size() && text[at + 1] == '/')) {
            while (at < text.size() && text[at] != '\n' && text[at] != '\r')
                ++at;
        } else if (c == '"' || c == '<') {
            const char close = c == '"' ? '"' : '>';
            for (++at; at < text.size() && text[at] != close; ++at) {
            }
            ++at;
        } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
                   c == '-' || c == '+') {
            // A word or a number; only a plain unsigned integer can be a count.
            const std::size_t begin = at;
            bool digits_only = true;
            while (at < text.size() &&
                   (std::isalnum(static_cast<unsigned char>(text[at])) || text[at] == '_' ||
                    text[at] == '.' || text[at] == '-' || text[at] == '+')) {
                digits_only = digits_only && text[at] >= '0' && text[at] <= '9';
                ++at;
            }
            std::size_t next = at;
            while (next < text.size() && isSpace(text[next]))
                ++next;
            if (digits_only && (before == '{' || before == ';') && next < text.size() &&
                text[next] == ';') {
                const uint64_t count = leadingCount(text.substr(begin, at - begin));
                if (count > file_size)
                    return countProblem("DirectX file", count, begin, file_size);
            }
            before = 'w';
        } else {
            if (!isSpace(c))
                before = c;
            ++at;
        }
    }
    return {};
}

/// Binary DirectX (.x): the same counts as 32-bit integers in integer tokens and lists. Floats
/// have their own tokens, so every integer is a count or an index below a count, except the raw
/// vertex words of DeclData and FVFData objects: one larger than the file is refused (a cube's 24
/// vertices patched to 300 million: 15 s and 3.5 GB). Stops at a token it does not know, where
/// assimp decides.
std::string directXBinaryProblem(std::string_view bytes, uint64_t file_size) {
    const uint64_t float_bytes = bytes.substr(12, 4) == "0064" ? 8 : 4;
    const auto word = [&](std::size_t at) -> uint64_t {
        if (at + 4 > bytes.size())
            return 0;
        uint64_t value = 0;
        for (int i = 3; i >= 0; --i)
            value = value << 8 | static_cast<uint8_t>(bytes[at + std::size_t(i)]);
        return value;
    };
    std::size_t at = 16;
    std::string_view last_name;
    bool raw_words = false; // inside a DeclData or FVFData object
    while (at + 2 <= bytes.size()) {
        const unsigned token =
            static_cast<uint8_t>(bytes[at]) | unsigned(static_cast<uint8_t>(bytes[at + 1])) << 8;
        at += 2;
        switch (token) {
        case 1: // name: length, then the characters
            last_name = bytes.substr(std::min(at + 4, bytes.size()), std::size_t(word(at)));
            at = std::size_t(saturatingAdd(at + 4, word(at)));
            break;
        case 0x0a: // '{': a data object's name comes before it
            raw_words = last_name == "DeclData" || last_name == "FVFData";
            break;
        case 0x0b: // '}'
            raw_words = false;
            break;
        case 2: // string: length, the characters, then a terminating token
            at = std::size_t(saturatingAdd(at + 6, word(at)));
            break;
        case 3: // integer
            if (word(at) > file_size)
                return countProblem("binary DirectX file", word(at), at, file_size);
            at += 4;
            break;
        case 5: // GUID
            at += 16;
            break;
        case 6: { // integer list: a count, then the integers
            const uint64_t count = word(at);
            if (saturatingMultiply(count, 4) > file_size)
                return countProblem("binary DirectX file", count, at, file_size);
            for (uint64_t i = 0; !raw_words && i < count && at + 8 + 4 * i <= bytes.size(); ++i)
                if (word(at + 4 + 4 * i) > file_size)
                    return countProblem("binary DirectX file", word(at + 4 + 4 * i), at + 4 + 4 * i,
                                        file_size);
            at = std::size_t(saturatingAdd(at + 4, saturatingMultiply(count, 4)));
            break;
        }
        case 7: { // float list: a count, then the floats
            const uint64_t count = word(at);
            if (saturatingMultiply(count, float_bytes) > file_size)
                return countProblem("binary DirectX file", count, at, file_size);
            at = std::size_t(saturatingAdd(at + 4, saturatingMultiply(count, float_bytes)));
            break;
        }
        default: // punctuation and keywords carry nothing
            if (token < 0x0a || token > 0x3c)
                return {};
        }
    }
    return {};
}

/// ASCII Caligari trueSpace (.cob): "World Vertices N", "Texture Vertices N", "Faces N" and
/// "Face verts N" are followed by N elements, and assimp resizes its arrays to N first (300
/// million world vertices in 300 bytes: 22 s and 3.5 GB). Every element takes at least two
/// bytes.
std::string cobAsciiProblem(std::string_view text, uint64_t file_size) {
    uint64_t elements = 0;
    std::size_t at = 0, first_at = 0;
    while (at < text.size()) {
        std::size_t end = at;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r')
            ++end;
        const std::string_view line = skipSpaces(text.substr(at, end - at));
        for (const std::string_view key :
             {"World Vertices", "Texture Vertices", "Faces", "Face verts"}) {
            if (line.starts_with(key)) {
                if (elements == 0)
                    first_at = at;
                elements =
                    saturatingAdd(elements, leadingCount(skipSpaces(line.substr(key.size()))));
                break;
            }
        }
        at = end + 1;
    }
    if (saturatingMultiply(elements, 2) <= file_size)
        return {};
    return "the Caligari file declares " + std::to_string(elements) +
           " vertices, texture vertices and faces (the first count at byte " +
           std::to_string(first_at) + "), at least " +
           std::to_string(saturatingMultiply(elements, 2)) + " bytes, but the file has " +
           std::to_string(file_size) + " bytes";
}

/// Binary Caligari trueSpace (.cob): chunks of a 20-byte header (type, version, ids, size) and
/// `size` bytes. assimp 5.2.5 aborted the process (an exception thrown from a destructor) on a
/// chunk larger than the file, and resizes a polygon mesh's (PolH) vertex and texture vertex
/// arrays and reserves its faces for their counts before reading them (300 million vertices:
/// 3.5 GB): each must fit in its chunk. Stops where a chunk is not laid out as expected.
std::string cobBinaryProblem(std::string_view bytes, uint64_t file_size) {
    const auto number = [&](uint64_t at, int size) -> std::optional<uint64_t> {
        if (at + uint64_t(size) > bytes.size())
            return std::nullopt;
        uint64_t value = 0;
        for (int i = size - 1; i >= 0; --i)
            value = value << 8 | static_cast<uint8_t>(bytes[std::size_t(at) + std::size_t(i)]);
        return value;
    };
    constexpr uint64_t kFileHeader = 32, kChunkHeader = 20, kNodeInfo = 96; // axes, transform
    uint64_t at = kFileHeader;
    while (at + kChunkHeader <= bytes.size()) {
        const std::string type(bytes.substr(std::size_t(at), 4));
        const uint64_t size = *number(at + 16, 4), body = at + kChunkHeader;
        if (body + size > file_size)
            return "the binary Caligari file's chunk '" + type + "' at byte " + std::to_string(at) +
                   " declares " + std::to_string(size) + " bytes, but the file has " +
                   std::to_string(file_size - body) + " bytes after its header";
        if (type == "END ")
            return {};
        if (type == "PolH") {
            // The name (a 16-bit dupe count, a 16-bit length, the characters), then the node's
            // axes and transform, then the counts, each followed by its elements.
            const std::optional<uint64_t> name = number(body + 2, 2);
            uint64_t item = body + 4 + name.value_or(0) + kNodeInfo;
            for (const auto& [what, bytes_each] :
                 {std::pair{"vertices", 12}, std::pair{"texture vertices", 8},
                  std::pair{"faces", 5}}) {
                const std::optional<uint64_t> count = number(item, 4);
                if (!name || !count || item + 4 > body + size)
                    break;
                if (saturatingMultiply(*count, uint64_t(bytes_each)) > size)
                    return "the binary Caligari file's mesh at byte " + std::to_string(at) +
                           " declares " + std::to_string(*count) + " " + what + ", more than its " +
                           std::to_string(size) + "-byte chunk can hold";
                item += 4 + *count * uint64_t(bytes_each);
            }
        }
        at = body + size;
    }
    return {};
}

bool isBinaryCob(std::string_view head) {
    return head.starts_with("Caligari V") && head.size() >= 16 && head[15] == 'B';
}

bool isDirectX(std::string_view head, std::string_view kind) {
    return head.substr(0, 4) == "xof " && head.size() >= 16 && head.substr(8, 4) == kind;
}

bool isAsciiCob(std::string_view head) {
    return head.starts_with("Caligari V") && head.size() >= 16 && head[15] == 'A';
}

} // namespace

std::string declaredSizeProblem(std::string_view head, uint64_t file_size,
                                std::string_view extension) {
    const std::string ext = lowercase(extension);
    // By signature first: assimp finds a PLY reader by its "ply" magic whatever the extension,
    // and reads the magic after a line end (then hung where end_header was missing).
    const std::size_t magic = std::min(head.find_first_not_of("\r\n"), head.size());
    if (lowercase(head.substr(magic, 3)) == "ply")
        return plyProblem(head, file_size);
    // assimp finds these by their signatures too.
    if (isDirectX(head, "txt "))
        return directXTextProblem(head, file_size);
    if (isDirectX(head, "bin "))
        return directXBinaryProblem(head, file_size);
    if (isAsciiCob(head))
        return cobAsciiProblem(head, file_size);
    if (isBinaryCob(head))
        return cobBinaryProblem(head, file_size);
    if (isBinaryGltf(head))
        return binaryGltfProblem(head, file_size);
    if (ext == "stl")
        return binaryStlProblem(head, file_size);
    if (ext == "nff")
        return nffProblem(head, file_size);
    return offProblem(head, file_size, ext == "off");
}

bool declaredSizesNeedWholeFile(std::string_view extension, std::string_view head) {
    // An ASCII PLY's list counts are in its body (asciiPlyListProblem).
    const bool ascii_ply = lowercase(head.substr(0, 3)) == "ply" &&
                           head.substr(0, 512).find("format ascii") != std::string_view::npos;
    return lowercase(extension) == "nff" || isDirectX(head, "txt ") || isDirectX(head, "bin ") ||
           isAsciiCob(head) || isBinaryCob(head) || ascii_ply;
}

} // namespace vissort::detail
