// Reads tetgen's .node and .ele files (https://wias-berlin.de/software/tetgen/fformats.html):
// the points and tetrahedra tetgen writes for a mesh, as a RawGrid of tetrahedra.
//  - .node: a header line `<#points> <dimension (3)> [<#attributes> [<boundary markers 0|1>]]`,
//    then a line per point `<index> <x> <y> <z> [attributes] [marker]`;
//  - .ele: a header line `<#tetrahedra> [<nodes per tetrahedron 4|10> [<#region attributes>]]`,
//    then a line per tetrahedron `<index> <n1> ... <n4|n10> [attributes]`.
// The header's optional fields default to 0 (4 nodes per tetrahedron) as tetgen reads them. '#'
// starts a comment anywhere. The first point's index (0 or 1) is the base of the numbering, which
// must be consecutive; a 10-node (quadratic) tetrahedron's corners are its first 4 nodes. The
// first point attribute, if any, is the scalar ("attribute 0").
//
// The formats are line-based, so each record must have exactly its values on its own line: a
// missing or extra value is then caught on its line instead of shifting every later record.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "grid/raw_grid.h"
#include "grid/token_messages.h"
#include "grid/token_scanner.h"

namespace vissort::detail {
namespace {

// How much of a token a message quotes.
constexpr std::size_t kQuoteChars = 32;

// One record: the tokens of a line, its first one already read.
struct Line {
    std::size_t number = 0;
    std::string_view first;
    std::string_view rest; // after the first token, comments included
};

// The next non-blank line's record, or an empty `first` at the end of the text.
Line nextLine(TokenScanner& scanner) {
    Line line;
    line.first = scanner.next();
    line.number = scanner.line();
    if (!line.first.empty())
        line.rest = scanner.restOfLine();
    return line;
}

uint64_t countTokens(const Line& line) {
    if (line.first.empty())
        return 0;
    TokenScanner rest(line.rest, '#');
    uint64_t count = 1;
    while (!rest.next().empty())
        ++count;
    return count;
}

// Whether `count` records of `tokens_per_record` tokens fit in what the scanner has left.
bool fits(uint64_t count, uint64_t tokens_per_record, const TokenScanner& scanner) {
    const uint64_t tokens_left = scanner.maxTokensLeft();
    return tokens_per_record == 0 || count <= tokens_left / tokens_per_record;
}

// "1 point", "2 points"; "1 tetrahedron", "2 tetrahedra".
std::string pluralize(uint64_t count, const char* noun, const char* nouns = nullptr) {
    if (count == 1)
        return "1 " + std::string(noun);
    return std::to_string(count) + " " + (nouns ? std::string(nouns) : std::string(noun) + "s");
}

struct Header {
    int64_t fields[4] = {0, 0, 0, 0};
    uint64_t present = 0; // how many the line gives
};

// A header line of 1 to `max_fields` integers, `required` of them present.
Result<Header> readHeader(const Line& line, const char* file, int required, int max_fields,
                          const char* layout) {
    const std::string where = std::string(file) + " line " + std::to_string(line.number) + ": ";
    if (line.first.empty())
        return Result<Header>::failure(std::string(file) + " is empty");
    const uint64_t count = countTokens(line);
    if (count < uint64_t(required) || count > uint64_t(max_fields))
        return Result<Header>::failure(where + "the header has " + pluralize(count, "value") +
                                       ", expected " + layout);
    Header header;
    TokenScanner rest(line.rest, '#');
    for (uint64_t i = 0; i < count; ++i) {
        const std::string_view token = i == 0 ? line.first : rest.next();
        const std::optional<int64_t> value = TokenScanner::parseInteger(token);
        if (!value || *value < 0)
            return Result<Header>::failure(where + "header value " + quoted(token, kQuoteChars) +
                                           " is not a count, expected " + layout);
        header.fields[i] = *value;
    }
    header.present = count;
    return Result<Header>{header, {}};
}

// A record's index: the first equals 0 or 1 (the base), each next one the previous plus 1.
std::string checkIndex(std::string_view token, const char* noun, uint64_t record, int64_t& base) {
    const std::optional<int64_t> index = TokenScanner::parseInteger(token);
    if (!index)
        return noun + std::string(" index ") + quoted(token, kQuoteChars) + " is not an integer";
    if (record == 0) {
        if (*index != 0 && *index != 1)
            return std::string("the first ") + noun + " is numbered " + std::to_string(*index) +
                   " (tetgen numbers from 0 or 1)";
        base = *index;
    } else if (*index != base + int64_t(record)) {
        return std::string(noun) + " " + std::to_string(*index) + " follows " + noun + " " +
               std::to_string(base + int64_t(record) - 1) + " (the numbering must be consecutive)";
    }
    return {};
}

// The rest of the text after the records: nothing but blank lines and comments.
std::string checkEnd(TokenScanner& scanner, const char* file, const std::string& records) {
    const std::string_view token = scanner.next();
    if (token.empty())
        return {};
    return std::string(file) + " line " + std::to_string(scanner.line()) + ": unexpected " +
           quoted(token, kQuoteChars) + " after the " + records;
}

Result<RawGrid> readNode(const std::string& node_bytes, int64_t& base) {
    TokenScanner scanner(node_bytes, '#');
    const Result<Header> header =
        readHeader(nextLine(scanner), ".node", 2, 4,
                   "<#points> <dimension> [<#attributes> [<boundary markers>]]");
    if (!header)
        return Result<RawGrid>::failure(header.error);
    const uint64_t count = uint64_t(header.value->fields[0]);
    const int64_t dimension = header.value->fields[1];
    const uint64_t attributes = uint64_t(header.value->fields[2]);
    const int64_t markers = header.value->fields[3];
    const std::string where = ".node line " + std::to_string(scanner.line()) + ": ";
    if (dimension != 3)
        return Result<RawGrid>::failure(where + "dimension " + std::to_string(dimension) +
                                        ", only 3D points are read");
    if (markers > 1)
        return Result<RawGrid>::failure(where + "boundary markers " + std::to_string(markers) +
                                        ", expected 0 or 1");
    // Bounded memory: a count beyond the grid limit, or that the bytes left cannot hold, is refused
    // before reserving for it (no overflow: each header field is below 2^63).
    if (count > kMaxGridPoints)
        return Result<RawGrid>::failure(where + pluralize(count, "point") +
                                        " declared, beyond the limit of " +
                                        std::to_string(kMaxGridPoints));
    const uint64_t tokens_per_point = 4 + attributes + uint64_t(markers);
    if (!fits(count, tokens_per_point, scanner))
        return Result<RawGrid>::failure(where + pluralize(count, "point") + " of " +
                                        std::to_string(tokens_per_point) +
                                        " values declared, more than the rest of the file holds");

    RawGrid grid;
    grid.points.reserve(count);
    if (attributes > 0) {
        grid.scalars.reserve(count);
        grid.scalar_name = "attribute 0";
    }
    for (uint64_t i = 0; i < count; ++i) {
        const Line line = nextLine(scanner);
        if (line.first.empty())
            return Result<RawGrid>::failure(".node line " + std::to_string(line.number) +
                                            ": the file ends after " + std::to_string(i) + " of " +
                                            pluralize(count, "point") + " declared");
        const std::string at = ".node line " + std::to_string(line.number) + ": ";
        const uint64_t values = countTokens(line);
        if (values != tokens_per_point)
            return Result<RawGrid>::failure(
                at + "point " + std::to_string(i + uint64_t(base)) + " has " +
                pluralize(values, "value") + ", expected " + std::to_string(tokens_per_point) +
                " (index, x, y, z, " + pluralize(attributes, "attribute") +
                (markers ? ", marker)" : ")"));
        if (std::string index = checkIndex(line.first, "point", i, base); !index.empty())
            return Result<RawGrid>::failure(at + index);
        TokenScanner rest(line.rest, '#');
        double xyz[3];
        for (double& coordinate : xyz) {
            const std::string_view token = rest.next();
            const std::optional<double> value = TokenScanner::parseDouble(token);
            if (!value)
                return Result<RawGrid>::failure(at + "point " + std::to_string(i + uint64_t(base)) +
                                                ": coordinate " + badNumber(token, kQuoteChars));
            coordinate = *value;
        }
        grid.points.push_back({xyz[0], xyz[1], xyz[2]});
        for (uint64_t a = 0; a < attributes; ++a) {
            const std::string_view token = rest.next();
            const std::optional<double> value = TokenScanner::parseDouble(token);
            if (!value)
                return Result<RawGrid>::failure(at + "point " + std::to_string(i + uint64_t(base)) +
                                                ": attribute " + badNumber(token, kQuoteChars));
            if (a == 0)
                grid.scalars.push_back(*value);
        }
        if (markers) {
            const std::string_view token = rest.next();
            if (!TokenScanner::parseInteger(token))
                return Result<RawGrid>::failure(at + "point " + std::to_string(i + uint64_t(base)) +
                                                ": boundary marker " + quoted(token, kQuoteChars) +
                                                " is not an integer");
        }
    }
    if (std::string end = checkEnd(scanner, ".node", pluralize(count, "point")); !end.empty())
        return Result<RawGrid>::failure(end);
    return Result<RawGrid>{std::move(grid), {}};
}

std::string readEle(const std::string& ele_bytes, int64_t base, RawGrid& grid) {
    TokenScanner scanner(ele_bytes, '#');
    const Result<Header> header =
        readHeader(nextLine(scanner), ".ele", 1, 3,
                   "<#tetrahedra> [<nodes per tetrahedron> [<#region attributes>]]");
    if (!header)
        return header.error;
    const uint64_t count = uint64_t(header.value->fields[0]);
    const int64_t nodes = header.value->present >= 2 ? header.value->fields[1] : 4;
    const uint64_t attributes = uint64_t(header.value->fields[2]);
    const std::string where = ".ele line " + std::to_string(scanner.line()) + ": ";
    if (nodes != 4 && nodes != 10)
        return where + std::to_string(nodes) + " nodes per tetrahedron, expected 4 or 10";
    if (count > kMaxGridTets)
        return where + pluralize(count, "tetrahedron", "tetrahedra") +
               " declared, beyond the limit of " + std::to_string(kMaxGridTets);
    const uint64_t tokens_per_tet = 1 + uint64_t(nodes) + attributes;
    if (!fits(count, tokens_per_tet, scanner))
        return where + pluralize(count, "tetrahedron", "tetrahedra") + " of " +
               std::to_string(tokens_per_tet) + " values declared, more than the rest of the " +
               "file holds";

    const uint64_t point_count = grid.points.size();
    grid.cell_types.reserve(count);
    grid.cell_offsets.reserve(count + 1);
    grid.cell_points.reserve(count * 4);
    int64_t ele_base = 0;
    for (uint64_t i = 0; i < count; ++i) {
        const Line line = nextLine(scanner);
        if (line.first.empty())
            return ".ele line " + std::to_string(line.number) + ": the file ends after " +
                   std::to_string(i) + " of " + pluralize(count, "tetrahedron", "tetrahedra") +
                   " declared";
        const std::string at = ".ele line " + std::to_string(line.number) + ": ";
        const uint64_t values = countTokens(line);
        if (values != tokens_per_tet)
            return at + "tetrahedron " + std::to_string(i + uint64_t(ele_base)) + " has " +
                   pluralize(values, "value") + ", expected " + std::to_string(tokens_per_tet) +
                   " (index, " + std::to_string(nodes) + " nodes, " +
                   pluralize(attributes, "attribute") + ")";
        if (std::string index = checkIndex(line.first, "tetrahedron", i, ele_base); !index.empty())
            return at + index;
        const std::string tet = "tetrahedron " + std::to_string(i + uint64_t(ele_base));
        TokenScanner rest(line.rest, '#');
        uint32_t corners[4];
        for (int64_t n = 0; n < nodes; ++n) {
            const std::string_view token = rest.next();
            const std::optional<int64_t> node = TokenScanner::parseInteger(token);
            if (!node)
                return at + tet + ": node " + quoted(token, kQuoteChars) + " is not an integer";
            // The quadratic nodes past the 4 corners are checked too: a wrong one is a broken file.
            if (*node < base || uint64_t(*node - base) >= point_count)
                return at + tet + ": node " + std::to_string(*node) + " is not one of the " +
                       pluralize(point_count, "point") + " numbered from " + std::to_string(base);
            if (n < 4)
                corners[n] = uint32_t(*node - base);
        }
        for (uint64_t a = 0; a < attributes; ++a) {
            const std::string_view token = rest.next();
            if (!TokenScanner::parseDouble(token))
                return at + tet + ": attribute " + badNumber(token, kQuoteChars);
        }
        grid.addCell(CellType::tetrahedron, corners);
    }
    return checkEnd(scanner, ".ele", pluralize(count, "tetrahedron", "tetrahedra"));
}

} // namespace

Result<RawGrid> readTetgen(const std::string& node_bytes, const std::string& ele_bytes) {
    int64_t base = 0;
    Result<RawGrid> grid = readNode(node_bytes, base);
    if (!grid)
        return grid;
    if (std::string error = readEle(ele_bytes, base, *grid.value); !error.empty())
        return Result<RawGrid>::failure(std::move(error));
    return grid;
}

} // namespace vissort::detail
