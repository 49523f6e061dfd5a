// Reads legacy VTK files (.vtk) of DATASET UNSTRUCTURED_GRID, ASCII or BINARY, after "VTK File
// Formats" (The VTK User's Guide, 11th ed., and the version 5.1 additions of VTK 9: CELLS as
// OFFSETS and CONNECTIVITY arrays, METADATA blocks), with VTK's own vtkDataReader settling what
// the description leaves open: keywords are case-insensitive, binary data are big-endian and
// start on the line after their header, an array may be followed by a METADATA block that a
// blank line ends, names are %XX-encoded, vtkIdType is written as a 4-byte int.
//
// Keeps the points, the cells and one point scalar array; every other section is skipped, which
// for BINARY files means knowing each section's size. Every declared count is checked against
// the bytes left before anything is allocated for it.

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grid/binary_values.h"
#include "grid/raw_grid.h"
#include "grid/token_messages.h"
#include "grid/token_scanner.h"
#include "grid/vtk_cell_types.h"

namespace vissort::detail {

namespace {

/// A legacy data type: one of the numeric types, or bit or string, which a BINARY file sizes
/// apart (bits packed 8 to a byte, strings by their length prefixes).
struct ValueType {
    std::optional<NumericType> numeric; // nullopt for bit and string
    bool is_bit = false;
    bool is_string = false;
};

bool isIntegral(ValueType type) {
    return type.numeric && !isFloat(*type.numeric);
}

struct ValueTypeName {
    const char* name; // lowercase: the file's is matched in any case
    ValueType type;
};

constexpr ValueTypeName kValueTypeNames[] = {
    {"bit", {std::nullopt, true, false}},
    {"char", {NumericType::int8}},
    {"signed_char", {NumericType::int8}},
    {"unsigned_char", {NumericType::uint8}},
    {"short", {NumericType::int16}},
    {"unsigned_short", {NumericType::uint16}},
    // vtkDataWriter writes vtkIdType arrays as 4-byte ints.
    {"int", {NumericType::int32}},
    {"vtkidtype", {NumericType::int32}},
    {"vtktypeint32", {NumericType::int32}},
    {"unsigned_int", {NumericType::uint32}},
    {"vtktypeuint32", {NumericType::uint32}},
    // VTK no longer writes "long"; its reader takes it as 8 bytes on 64-bit Linux.
    {"long", {NumericType::int64}},
    {"vtktypeint64", {NumericType::int64}},
    {"unsigned_long", {NumericType::uint64}},
    {"vtktypeuint64", {NumericType::uint64}},
    {"float", {NumericType::float32}},
    {"double", {NumericType::float64}},
    {"string", {std::nullopt, false, true}},
    {"utf8_string", {std::nullopt, false, true}},
};

std::optional<ValueType> parseValueType(std::string_view name) {
    const std::string lower = lowerCase(name);
    for (const ValueTypeName& entry : kValueTypeNames)
        if (lower == entry.name)
            return entry.type;
    return std::nullopt;
}

/// How much of a name or token a message quotes.
constexpr std::size_t kShownChars = 40;

/// VTK writes names with %XX escapes for spaces and other special characters.
std::string decodeName(std::string_view encoded) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9')
            return c - '0';
        if (c >= 'a' && c <= 'f')
            return c - 'a' + 10;
        if (c >= 'A' && c <= 'F')
            return c - 'A' + 10;
        return -1;
    };
    std::string name;
    for (std::size_t i = 0; i < encoded.size(); ++i) {
        if (encoded[i] == '%' && i + 2 < encoded.size() && hex(encoded[i + 1]) >= 0 &&
            hex(encoded[i + 2]) >= 0) {
            name.push_back(char(hex(encoded[i + 1]) * 16 + hex(encoded[i + 2])));
            i += 2;
        } else {
            name.push_back(encoded[i]);
        }
    }
    return name;
}

bool isBlank(std::string_view line) {
    for (char c : line)
        if (c != ' ' && c != '\t' && c != '\r')
            return false;
    return true;
}

class LegacyReader {
public:
    LegacyReader(std::string_view text, const std::string& scalar_name)
        : text_(text), scan_(text), wanted_scalar_(scalar_name) {}

    Result<RawGrid> read() {
        if (!readHeader() || !readSections() || !finish())
            return Result<RawGrid>::failure(std::move(error_));
        return {std::move(grid_), {}};
    }

private:
    // Which data attributes the sections that follow belong to.
    enum class Attributes { none, points, cells };

    std::string_view next() {
        const std::string_view token = scan_.next();
        token_start_ = std::size_t(token.data() - text_.data());
        return token;
    }

    /// Where the last token is: its line in an ASCII file; in a BINARY one, whose line numbers
    /// the binary data blur, its byte offset.
    std::string where() const {
        return binary_ ? "byte " + std::to_string(token_start_)
                       : "line " + std::to_string(scan_.line());
    }

    bool fail(const std::string& problem) {
        error_ = where() + ": " + problem;
        return false;
    }

    /// Problems of a whole section (its counts, its structure) are placed at its header line:
    /// markHeader() is called on a header's first token.
    void markHeader() { header_where_ = where(); }
    bool failHeader(const std::string& problem) {
        error_ = header_where_ + ": " + problem;
        return false;
    }

    bool readCount(const std::string& what, uint64_t& count) {
        const std::string_view token = next();
        if (token.empty())
            return fail(what + ": the file ends where a count should be");
        const std::optional<int64_t> value = TokenScanner::parseInteger(token);
        if (!value || *value < 0)
            return fail(what + ": " + quoted(token, kShownChars) + " is not a count");
        count = uint64_t(*value);
        return true;
    }

    bool readType(const std::string& what, ValueType& type) {
        const std::string_view token = next();
        if (token.empty())
            return fail(what + ": the file ends where a data type should be");
        const std::optional<ValueType> parsed = parseValueType(token);
        if (!parsed)
            return fail(what + " has the unknown data type " + quoted(token, kShownChars));
        type = *parsed;
        return true;
    }

    bool readName(const std::string& what, std::string& name) {
        const std::string_view token = next();
        if (token.empty())
            return fail(what + ": the file ends where a name should be");
        name = decodeName(token);
        return true;
    }

    bool expectKeyword(const char* keyword, const std::string& after) {
        const std::string_view token = next();
        if (lowerCase(token) != lowerCase(keyword))
            return fail("expected " + std::string(keyword) + " after " + after + ", found " +
                        quoted(token, kShownChars));
        return true;
    }

    /// count = tuples * components, or false when that overflows.
    bool valueCount(const std::string& what, uint64_t tuples, uint64_t components,
                    uint64_t& count) {
        if (__builtin_mul_overflow(tuples, components, &count))
            return failHeader(what + " declares " + std::to_string(tuples) + " tuples of " +
                              std::to_string(components) + " components, more than any file holds");
        return true;
    }

    /// Reads count values of type that follow their header line, keeping every stride-th one
    /// (the first component of each tuple) in out, or skipping them all when out is null, and
    /// the METADATA block that may follow (whose COMPONENT_NAMES has one line per component).
    /// Integral T needs an integral type.
    template <class T>
    bool readValues(ValueType type, uint64_t count, uint64_t stride, const std::string& what,
                    std::vector<T>* out, uint64_t components = 1) {
        if (type.is_string) {
            if (!skipStrings(count, what))
                return false;
            skipMetadata(components);
            return true;
        }
        if (binary_) {
            // The data start on the line after their header (vtkDataReader's getline).
            scan_.restOfLine();
            const std::size_t start = scan_.position();
            const uint64_t left = text_.size() - start;
            uint64_t bytes = count / 8 + (count % 8 != 0); // bits, 8 to a byte
            if (type.numeric) {
                const uint64_t size = numericSize(*type.numeric);
                bytes = count > left / size ? left + 1 : count * size;
            }
            if (bytes > left)
                return failHeader(what + " declares " + std::to_string(count) +
                                  " values, more than the " + std::to_string(left) +
                                  " bytes left can hold");
            // Arrays are kept only of numeric types: out is null for bits.
            if (out) {
                const auto* data = reinterpret_cast<const unsigned char*>(text_.data() + start);
                const std::string problem =
                    appendBinaryValues(*type.numeric, data, count, stride, true, *out);
                if (!problem.empty())
                    return fail(what + " " + problem);
            }
            scan_.seek(start + bytes);
        } else {
            if (count > scan_.maxTokensLeft())
                return failHeader(
                    what + " declares " + std::to_string(count) + " values, more than the " +
                    std::to_string(text_.size() - scan_.position()) + " bytes left can hold");
            if (out)
                out->reserve(count / stride + 1);
            for (uint64_t i = 0; i < count; ++i) {
                const std::string_view token = next();
                if (token.empty())
                    return fail(what + ": the file ends after " + std::to_string(i) + " of " +
                                std::to_string(count) + " values");
                const std::optional<T> value = parseAsciiValue<T>(token);
                if (!value)
                    return fail(what + " " + badAsciiValue<T>(token, kShownChars));
                if (out && i % stride == 0)
                    out->push_back(*value);
            }
        }
        skipMetadata(components);
        return true;
    }

    /// String arrays are never kept: skipped line by line (ASCII) or by their length prefixes
    /// (BINARY: the top two bits of the first byte say whether the length takes 1, 2, 4 or 8
    /// bytes, big-endian, those two bits masked off but for the 8-byte form).
    bool skipStrings(uint64_t count, const std::string& what) {
        scan_.restOfLine();
        std::size_t pos = scan_.position();
        for (uint64_t i = 0; i < count; ++i) {
            if (pos >= text_.size())
                return failHeader(what + ": the file ends after " + std::to_string(i) + " of " +
                                  std::to_string(count) + " strings");
            if (!binary_) {
                scan_.restOfLine();
                pos = scan_.position();
                continue;
            }
            const auto first = uint8_t(text_[pos]);
            const uint64_t header = first >> 6 == 3   ? 1
                                    : first >> 6 == 2 ? 2
                                    : first >> 6 == 1 ? 4
                                                      : 8;
            if (header > text_.size() - pos)
                return failHeader(what + ": string " + std::to_string(i) + " is cut short");
            uint64_t length =
                loadBits(reinterpret_cast<const unsigned char*>(text_.data() + pos), header, true);
            if (header < 8)
                length &= (uint64_t(1) << (8 * header - 2)) - 1;
            pos += header;
            if (length > text_.size() - pos)
                return failHeader(what + ": string " + std::to_string(i) + " is cut short");
            pos += length;
        }
        scan_.seek(pos);
        return true;
    }

    /// Skips a METADATA block if one follows an array of components: text even in a BINARY
    /// file, lines of COMPONENT_NAMES (one per component, empty for an unnamed one) and
    /// INFORMATION keys (a NAME line and a DATA line each), ended by a blank line.
    void skipMetadata(uint64_t components) {
        if (lowerCase(scan_.peek()) != "metadata")
            return;
        next();
        skipMetadataBlock(components);
    }
    void skipMetadataBlock(uint64_t components) {
        scan_.restOfLine();
        // Every loop stops at the end of the text, whatever count a line declares.
        auto at_end = [&] { return scan_.position() >= text_.size(); };
        while (!at_end()) {
            const std::string_view line = scan_.restOfLine();
            if (isBlank(line))
                return;
            TokenScanner words(line);
            const std::string keyword = lowerCase(words.next());
            if (keyword == "component_names") {
                for (uint64_t i = 0; i < components && !at_end(); ++i)
                    scan_.restOfLine();
            } else if (keyword == "information") {
                const std::optional<int64_t> keys = words.nextInteger();
                // Blank lines may come before a key's NAME line; its DATA line follows. (The
                // strings of a string vector key, on lines of their own, are skipped as unknown
                // lines are.)
                for (int64_t key = 0; keys && key < *keys && !at_end(); ++key) {
                    std::string_view name_line;
                    do {
                        name_line = scan_.restOfLine();
                    } while (isBlank(name_line) && !at_end());
                    scan_.restOfLine();
                }
            }
        }
    }

    bool readHeader() {
        const std::string_view first = scan_.restOfLine();
        const std::string_view prefix = "# vtk datafile version";
        if (lowerCase(first.substr(0, prefix.size())) != prefix) {
            token_start_ = 0;
            return fail("not a legacy VTK file: it should start with '# vtk DataFile Version'");
        }
        scan_.restOfLine(); // the title
        const std::string_view format = next();
        if (lowerCase(format) == "ascii") {
            binary_ = false;
        } else if (lowerCase(format) == "binary") {
            binary_ = true;
        } else {
            return fail("expected ASCII or BINARY, found " + quoted(format, kShownChars));
        }
        if (!expectKeyword("DATASET", std::string(format)))
            return false;
        const std::string_view dataset = next();
        if (lowerCase(dataset) != "unstructured_grid")
            return fail("DATASET " + shown(dataset, kShownChars) +
                        ": vissort reads UNSTRUCTURED_GRID");
        return true;
    }

    bool readSections() {
        for (;;) {
            const std::string_view token = next();
            if (token.empty())
                return true;
            markHeader();
            const std::string keyword = lowerCase(token);
            bool ok;
            if (keyword == "points") {
                ok = readPoints();
            } else if (keyword == "cells") {
                ok = readCells();
            } else if (keyword == "cell_types") {
                ok = readCellTypes();
            } else if (keyword == "point_data") {
                ok = startAttributes(Attributes::points);
            } else if (keyword == "cell_data") {
                ok = startAttributes(Attributes::cells);
            } else if (keyword == "field") {
                ok = readField();
            } else if (keyword == "metadata") {
                skipMetadataBlock(0);
                ok = true;
            } else if (attributes_ != Attributes::none) {
                ok = readAttribute(keyword, token);
            } else {
                ok = fail("unknown section " + quoted(token, kShownChars));
            }
            if (!ok)
                return false;
        }
    }

    bool readPoints() {
        if (have_points_)
            return fail("a second POINTS section");
        uint64_t count;
        ValueType type;
        if (!readCount("POINTS", count) || !readType("POINTS", type))
            return false;
        if (count > kMaxGridPoints)
            return failHeader("POINTS declares " + std::to_string(count) +
                              " points, more than vissort's limit of " +
                              std::to_string(kMaxGridPoints));
        if (!type.numeric)
            return fail("POINTS need a numeric data type");
        std::vector<double> coordinates;
        if (!readValues(type, count * 3, 1, "POINTS", &coordinates, 3))
            return false;
        grid_.points.resize(count);
        for (uint64_t i = 0; i < count; ++i)
            grid_.points[i] = {coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]};
        have_points_ = true;
        return true;
    }

    bool readCells() {
        if (have_cells_)
            return fail("a second CELLS section");
        uint64_t first, second;
        if (!readCount("CELLS", first) || !readCount("CELLS", second))
            return false;
        have_cells_ = true;
        if (lowerCase(scan_.peek()) == "offsets")
            return readOffsetCells(first, second);

        // The classic form: per cell, its number of corners and then the corners; first cells,
        // second numbers in all, written as 4-byte ints.
        if (first > kMaxGridTets)
            return failHeader("CELLS declares " + std::to_string(first) +
                              " cells, more than vissort's limit of " +
                              std::to_string(kMaxGridTets));
        std::vector<int64_t> numbers;
        if (!readValues(ValueType{NumericType::int32}, second, 1, "CELLS", &numbers))
            return false;
        if (first > numbers.size())
            return failHeader("CELLS declares " + std::to_string(first) + " cells in " +
                              std::to_string(second) + " numbers");
        // The corners are moved down over the counts, in place.
        cell_offsets_.reserve(first + 1);
        cell_offsets_.push_back(0);
        uint64_t read = 0, written = 0;
        for (uint64_t cell = 0; cell < first; ++cell) {
            if (read >= numbers.size())
                return failHeader("CELLS: the numbers end in cell " + std::to_string(cell) +
                                  " of " + std::to_string(first));
            const int64_t corners = numbers[read++];
            if (corners < 0 || uint64_t(corners) > numbers.size() - read)
                return failHeader("CELLS: cell " + std::to_string(cell) + " has " +
                                  std::to_string(corners) + " corners, more than the numbers left");
            for (int64_t k = 0; k < corners; ++k)
                numbers[written++] = numbers[read++];
            cell_offsets_.push_back(written);
        }
        if (read != numbers.size())
            return failHeader("CELLS declares " + std::to_string(second) + " numbers, but its " +
                              std::to_string(first) + " cells use " + std::to_string(read));
        numbers.resize(written);
        cell_connectivity_ = std::move(numbers);
        return true;
    }

    /// Version 5.1's form: CELLS offsets connectivity, then OFFSETS (cells + 1 of them, from 0)
    /// and CONNECTIVITY arrays, each with its type.
    bool readOffsetCells(uint64_t offset_count, uint64_t connectivity_count) {
        const uint64_t cells = offset_count == 0 ? 0 : offset_count - 1;
        if (cells > kMaxGridTets)
            return failHeader("CELLS declares " + std::to_string(cells) +
                              " cells, more than vissort's limit of " +
                              std::to_string(kMaxGridTets));
        ValueType type;
        next(); // OFFSETS
        markHeader();
        if (!readType("OFFSETS", type))
            return false;
        if (!isIntegral(type))
            return fail("OFFSETS need an integer data type");
        std::vector<int64_t> offsets;
        if (!readValues(type, offset_count, 1, "OFFSETS", &offsets))
            return false;
        if (offset_count == 0) {
            cell_offsets_.assign(1, 0);
        } else {
            if (offsets.front() != 0)
                return failHeader("OFFSETS start at " + std::to_string(offsets.front()) +
                                  ", not 0");
            for (uint64_t i = 1; i < offsets.size(); ++i)
                if (offsets[i] < offsets[i - 1])
                    return failHeader("OFFSETS decrease at cell " + std::to_string(i - 1));
            if (uint64_t(offsets.back()) != connectivity_count)
                return failHeader("OFFSETS end at " + std::to_string(offsets.back()) +
                                  ", but CELLS declares " + std::to_string(connectivity_count) +
                                  " CONNECTIVITY values");
            cell_offsets_.assign(offsets.begin(), offsets.end());
        }
        if (!expectKeyword("CONNECTIVITY", "OFFSETS"))
            return false;
        markHeader();
        if (!readType("CONNECTIVITY", type))
            return false;
        if (!isIntegral(type))
            return fail("CONNECTIVITY needs an integer data type");
        return readValues(type, connectivity_count, 1, "CONNECTIVITY", &cell_connectivity_);
    }

    bool readCellTypes() {
        if (have_cell_types_)
            return fail("a second CELL_TYPES section");
        uint64_t count;
        if (!readCount("CELL_TYPES", count))
            return false;
        if (count > kMaxGridTets)
            return failHeader("CELL_TYPES declares " + std::to_string(count) +
                              " cells, more than vissort's limit of " +
                              std::to_string(kMaxGridTets));
        have_cell_types_ = true;
        return readValues(ValueType{NumericType::int32}, count, 1, "CELL_TYPES", &cell_types_);
    }

    bool startAttributes(Attributes attributes) {
        const bool points = attributes == Attributes::points;
        const std::string what = points ? "POINT_DATA" : "CELL_DATA";
        if (!readCount(what, attribute_count_))
            return false;
        if (points) {
            if (!have_points_)
                return fail("POINT_DATA comes before POINTS");
            if (attribute_count_ != grid_.points.size())
                return failHeader("POINT_DATA has " + std::to_string(attribute_count_) +
                                  " values, but POINTS has " + std::to_string(grid_.points.size()));
        } else {
            if (!have_cells_ && !have_cell_types_)
                return fail("CELL_DATA comes before CELLS");
            const uint64_t cells =
                have_cells_ ? cell_offsets_.size() - 1 : uint64_t(cell_types_.size());
            if (attribute_count_ != cells)
                return failHeader("CELL_DATA has " + std::to_string(attribute_count_) +
                                  " values, but the file has " + std::to_string(cells) + " cells");
        }
        attributes_ = attributes;
        return true;
    }

    /// Reads or skips one array of point or cell data (tuples of components values of type),
    /// keeping it as the scalars when it is a point array that the choice prefers: the one named
    /// scalar_name, else SCALARS before a one-component FIELD array before any FIELD array
    /// (rank 0, 1, 2), the first of the best rank.
    bool readDataArray(const std::string& what, const std::string& name, ValueType type,
                       uint64_t tuples, uint64_t components, int rank) {
        uint64_t count;
        if (!valueCount(what, tuples, components, count))
            return false;
        const bool candidate = attributes_ == Attributes::points && type.numeric && components > 0;
        bool keep = false;
        if (candidate) {
            point_array_names_.push_back(name);
            keep = wanted_scalar_.empty() ? rank < scalars_rank_
                                          : name == wanted_scalar_ && scalars_rank_ > 2;
        }
        if (!keep)
            return readValues<double>(type, count, 1, what, nullptr, components);
        std::vector<double> values;
        if (!readValues(type, count, components, what, &values, components))
            return false;
        grid_.scalars = std::move(values);
        grid_.scalar_name = name;
        scalars_rank_ = rank;
        return true;
    }

    /// Skips a section of colours, a name and a number: COLOR_SCALARS (the number its
    /// components, a tuple per point or cell) or a LOOKUP_TABLE (the number its RGBA colours).
    /// Colours are written as floats in ASCII files, as unsigned chars in BINARY ones.
    bool skipColours(const std::string& section, bool is_table) {
        std::string name;
        uint64_t number;
        if (!readName(section, name) || !readCount(section, number))
            return false;
        const std::string what = section + " " + quoted(name, kShownChars);
        const uint64_t tuples = is_table ? number : attribute_count_;
        const uint64_t components = is_table ? 4 : number;
        uint64_t count;
        return valueCount(what, tuples, components, count) &&
               readValues<double>(ValueType{binary_ ? NumericType::uint8 : NumericType::float32},
                                  count, 1, what, nullptr, components);
    }

    bool readAttribute(const std::string& keyword, std::string_view token) {
        const uint64_t n = attribute_count_;
        std::string name;
        ValueType type;
        if (keyword == "scalars") {
            if (!readName("SCALARS", name) || !readType("SCALARS", type))
                return false;
            const std::string what = "SCALARS " + quoted(name, kShownChars);
            uint64_t components = 1;
            std::string_view key = next();
            if (lowerCase(key) != "lookup_table") {
                const std::optional<int64_t> parsed = TokenScanner::parseInteger(key);
                if (!parsed || *parsed < 1)
                    return fail(what + ": expected a number of components or LOOKUP_TABLE, found " +
                                quoted(key, kShownChars));
                components = uint64_t(*parsed);
                key = next();
                if (lowerCase(key) != "lookup_table")
                    return fail(what + ": expected LOOKUP_TABLE, found " +
                                quoted(key, kShownChars));
            }
            std::string table;
            if (!readName(what + " LOOKUP_TABLE", table))
                return false;
            return readDataArray(what, name, type, n, components, 0);
        }
        if (keyword == "color_scalars")
            return skipColours("COLOR_SCALARS", false);
        if (keyword == "lookup_table")
            return skipColours("LOOKUP_TABLE", true);
        uint64_t components = 0;
        if (keyword == "vectors" || keyword == "normals")
            components = 3;
        if (keyword == "tensors")
            components = 9;
        if (keyword == "tensors6")
            components = 6;
        if (keyword == "global_ids" || keyword == "pedigree_ids" || keyword == "edge_flags")
            components = 1;
        const std::string section(token);
        if (keyword == "texture_coordinates") {
            if (!readName(section, name) || !readCount(section, components))
                return false;
        } else if (components != 0) {
            if (!readName(section, name))
                return false;
        } else {
            return fail("unknown section " + quoted(section, kShownChars) + " in " +
                        (attributes_ == Attributes::points ? "POINT_DATA" : "CELL_DATA"));
        }
        if (!readType(section, type))
            return false;
        const std::string what = section + " " + quoted(name, kShownChars);
        uint64_t count;
        return valueCount(what, n, components, count) &&
               readValues<double>(type, count, 1, what, nullptr, components);
    }

    /// FIELD name k, then k arrays "name components tuples type" (or NULL_ARRAY): at the
    /// dataset's level (TIME, CYCLE), in CELL_DATA, or in POINT_DATA as scalar candidates.
    bool readField() {
        std::string field_name;
        uint64_t arrays;
        if (!readName("FIELD", field_name) || !readCount("FIELD", arrays))
            return false;
        for (uint64_t i = 0; i < arrays; ++i) {
            const std::string_view token = next();
            if (token.empty())
                return fail("FIELD " + quoted(field_name, kShownChars) + ": the file ends after " +
                            std::to_string(i) + " of its " + std::to_string(arrays) + " arrays");
            if (token == "NULL_ARRAY")
                continue;
            markHeader();
            const std::string name = decodeName(token);
            const std::string what = "FIELD array " + quoted(name, kShownChars);
            uint64_t components, tuples;
            ValueType type;
            if (!readCount(what, components) || !readCount(what, tuples) || !readType(what, type))
                return false;
            if (attributes_ == Attributes::points && tuples != attribute_count_)
                return fail(what + " has " + std::to_string(tuples) +
                            " tuples, but POINT_DATA has " + std::to_string(attribute_count_));
            if (attributes_ != Attributes::points) {
                uint64_t count;
                if (!valueCount(what, tuples, components, count) ||
                    !readValues<double>(type, count, 1, what, nullptr, components))
                    return false;
                continue;
            }
            if (!readDataArray(what, name, type, tuples, components, components == 1 ? 1 : 2))
                return false;
        }
        return true;
    }

    /// The checks that need the whole file; their problems have no place in it to name.
    bool finish() {
        error_ = finalProblem();
        return error_.empty();
    }
    std::string finalProblem() {
        if (!have_points_)
            return "the file has no POINTS";
        if (!have_cells_)
            return "the file has no CELLS";
        if (!have_cell_types_)
            return "the file has no CELL_TYPES";
        const uint64_t cells = cell_offsets_.size() - 1;
        if (cell_types_.size() != cells)
            return "CELL_TYPES has " + std::to_string(cell_types_.size()) +
                   " cells, but CELLS has " + std::to_string(cells);
        for (uint64_t i = 0; i < grid_.points.size(); ++i) {
            const Vec3& p = grid_.points[i];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                return "point " + std::to_string(i) + " has a coordinate that is not finite";
        }
        if (!wanted_scalar_.empty() && grid_.scalar_name != wanted_scalar_) {
            return "no point array named " + quoted(wanted_scalar_, kShownChars) + ": " +
                   (point_array_names_.empty()
                        ? "the file has none"
                        : "the file has " + listed(point_array_names_, kShownChars));
        }
        for (uint64_t i = 0; i < grid_.scalars.size(); ++i)
            if (!std::isfinite(grid_.scalars[i]))
                return "the scalar " + quoted(grid_.scalar_name, kShownChars) + " of point " +
                       std::to_string(i) + " is not finite";
        grid_.cell_types.reserve(cells);
        grid_.cell_offsets.reserve(cells + 1);
        grid_.cell_points.reserve(cell_connectivity_.size());
        for (uint64_t cell = 0; cell < cells; ++cell) {
            const uint64_t begin = cell_offsets_[cell];
            std::string problem =
                addVtkCell(grid_, cell, cell_types_[cell], cell_connectivity_.data() + begin,
                           cell_offsets_[cell + 1] - begin, 0, grid_.points.size());
            if (!problem.empty())
                return problem;
        }
        return {};
    }

    std::string_view text_;
    TokenScanner scan_;
    std::string wanted_scalar_;
    bool binary_ = false;
    std::size_t token_start_ = 0;
    std::string header_where_;
    std::string error_;

    RawGrid grid_;
    bool have_points_ = false, have_cells_ = false, have_cell_types_ = false;
    std::vector<uint64_t> cell_offsets_;
    std::vector<int64_t> cell_connectivity_;
    std::vector<int64_t> cell_types_;

    Attributes attributes_ = Attributes::none;
    uint64_t attribute_count_ = 0;
    std::vector<std::string> point_array_names_;
    int scalars_rank_ = 3; // none kept yet
};

} // namespace

Result<RawGrid> readVtkLegacy(const std::string& bytes, const std::string& scalar_name) {
    return LegacyReader(bytes, scalar_name).read();
}

} // namespace vissort::detail
