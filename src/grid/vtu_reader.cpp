// Reads VTK XML unstructured grids (.vtu), after "VTK File Formats" (The VTK User's Guide, 11th
// ed., "XML File Formats") and VTK's vtkXMLDataParser, which settles the binary layouts the
// guide leaves open:
//  - a "binary" DataArray holds base64 text. Uncompressed, one header integer (UInt32 or UInt64,
//    the header_type) gives the data's byte count, and header and data are encoded together.
//    Compressed (vtkZLibDataCompressor), the header is [blocks, block size, the last block's size
//    (0 when full), each block's compressed size], encoded on its own, then the zlib-compressed
//    blocks, encoded together;
//  - an "appended" DataArray has the same layouts at its offset after the '_' that opens
//    AppendedData: raw bytes (offsets in bytes) or base64 (offsets in characters). Raw appended
//    data are not XML text, so the document handed to pugixml ends at the AppendedData tag, as
//    vtkXMLDataParser::ParseBuffer ends it.
// Header integers and data follow the file's byte_order. Several pieces are concatenated, their
// point indices offset by the points of the pieces before.
//
// Every count is checked before anything is allocated for it: against the characters of an
// ASCII array, the bytes a base64 text or raw data can hold, and for compressed data against
// zlib's largest ratio (1032:1), so that a small hostile file cannot ask for gigabytes.

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <pugixml.hpp>
#include <zlib.h>

#include "grid/base64_decode.h"
#include "grid/binary_values.h"
#include "grid/raw_grid.h"
#include "grid/token_messages.h"
#include "grid/token_scanner.h"
#include "grid/vtk_cell_types.h"

namespace vissort::detail {

namespace {

struct ElementTypeName {
    const char* name;
    NumericType type;
};

constexpr ElementTypeName kElementTypes[] = {
    {"Int8", NumericType::int8},       {"UInt8", NumericType::uint8},
    {"Int16", NumericType::int16},     {"UInt16", NumericType::uint16},
    {"Int32", NumericType::int32},     {"UInt32", NumericType::uint32},
    {"Int64", NumericType::int64},     {"UInt64", NumericType::uint64},
    {"Float32", NumericType::float32}, {"Float64", NumericType::float64},
};

std::optional<NumericType> findElementType(std::string_view name) {
    for (const ElementTypeName& entry : kElementTypes)
        if (name == entry.name)
            return entry.type;
    return std::nullopt;
}

/// No real file comes near this many bytes; below it, sizes in bytes or base64 characters cannot
/// overflow 64 bits.
constexpr uint64_t kMaxDataBytes = uint64_t(1) << 60;

/// zlib's deflate compresses at most 1032:1 (RFC 1950/1951 streams: a 258-byte match in about 2
/// bits); the slack covers a block's stream header and checksum.
uint64_t maxInflatedSize(uint64_t compressed) {
    return compressed * 1032 + 64;
}

/// An attribute that must be a whole non-negative number.
std::optional<uint64_t> parseCount(const char* text) {
    const std::optional<int64_t> value = TokenScanner::parseInteger(text);
    if (!value || *value < 0)
        return std::nullopt;
    return uint64_t(*value);
}

/// A DataArray's NumberOfComponents: 1 when absent, nullopt when not a whole number (pugixml's
/// as_ullong would read "3x" as 3 and "-1" as 0).
std::optional<uint64_t> componentsOf(const pugi::xml_node& array) {
    const pugi::xml_attribute attribute = array.attribute("NumberOfComponents");
    return attribute ? parseCount(attribute.value()) : std::optional<uint64_t>(1);
}

/// How much of a name or token a message quotes.
constexpr std::size_t kShownChars = 40;

bool isXmlSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

class VtuReader {
public:
    VtuReader(std::string_view bytes, const std::string& scalar_name)
        : bytes_(bytes), wanted_scalar_(scalar_name) {}

    Result<RawGrid> read() {
        if (!readDocument())
            return Result<RawGrid>::failure(std::move(error_));
        return {std::move(grid_), {}};
    }

private:
    bool fail(const std::string& problem) {
        error_ = piece_prefix_ + problem;
        return false;
    }

    /// Parses the XML, cut before any appended data, and reads the pieces.
    bool readDocument() {
        std::string_view xml = bytes_;
        std::string cut;
        const std::size_t tag = bytes_.find("<AppendedData");
        if (tag != std::string_view::npos) {
            const std::size_t close = bytes_.find('>', tag);
            if (close == std::string_view::npos)
                return fail("the AppendedData tag is not closed");
            // The tag is made empty and the document closed after it.
            cut.assign(bytes_.substr(0, close));
            cut += bytes_[close - 1] == '/' ? ">" : "/>";
            cut += "\n</VTKFile>\n";
            xml = cut;
            std::size_t start = close + 1;
            while (start < bytes_.size() && isXmlSpace(bytes_[start]))
                ++start;
            if (start < bytes_.size() && bytes_[start] == '_') {
                appended_ = bytes_.substr(start + 1);
                has_appended_ = true;
            }
        }
        pugi::xml_document document;
        const pugi::xml_parse_result parsed = document.load_buffer(xml.data(), xml.size());
        if (!parsed)
            return fail("not valid XML: " + std::string(parsed.description()) + " at byte " +
                        std::to_string(parsed.offset));
        const pugi::xml_node root = document.child("VTKFile");
        if (!root)
            return fail("not a VTK XML file: it has no VTKFile element");
        const std::string type = root.attribute("type").as_string();
        if (type != "UnstructuredGrid")
            return fail("VTKFile type " + quoted(type, kShownChars) +
                        ": vissort reads UnstructuredGrid");

        const std::string byte_order = root.attribute("byte_order").as_string("LittleEndian");
        if (byte_order == "BigEndian") {
            big_endian_ = true;
        } else if (byte_order != "LittleEndian") {
            return fail("unknown byte_order " + quoted(byte_order, kShownChars));
        }
        const std::string header_type = root.attribute("header_type").as_string("UInt32");
        if (header_type == "UInt64") {
            header_size_ = 8;
        } else if (header_type != "UInt32") {
            return fail("unknown header_type " + quoted(header_type, kShownChars) +
                        ": UInt32 or UInt64 expected");
        }
        compressor_ = root.attribute("compressor").as_string();

        if (has_appended_) {
            const std::string encoding =
                root.child("AppendedData").attribute("encoding").as_string("base64");
            if (encoding == "raw") {
                appended_raw_ = true;
            } else if (encoding != "base64") {
                return fail("unknown AppendedData encoding " + quoted(encoding, kShownChars));
            }
        }

        const pugi::xml_node grid = root.child("UnstructuredGrid");
        if (!grid)
            return fail("VTKFile has no UnstructuredGrid element");
        uint64_t pieces = 0;
        for (pugi::xml_node piece = grid.child("Piece"); piece; piece = piece.next_sibling("Piece"))
            ++pieces;
        if (pieces == 0)
            return fail("UnstructuredGrid has no Piece");
        uint64_t index = 0;
        for (pugi::xml_node piece = grid.child("Piece"); piece;
             piece = piece.next_sibling("Piece"), ++index) {
            if (pieces > 1)
                piece_prefix_ = "piece " + std::to_string(index) + ": ";
            if (!readPiece(piece, index))
                return false;
        }
        piece_prefix_.clear();
        for (uint64_t i = 0; i < grid_.points.size(); ++i) {
            const Vec3& p = grid_.points[i];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                return fail("point " + std::to_string(i) + " has a coordinate that is not finite");
        }
        for (uint64_t i = 0; i < grid_.scalars.size(); ++i)
            if (!std::isfinite(grid_.scalars[i]))
                return fail("the scalar " + quoted(grid_.scalar_name, kShownChars) + " of point " +
                            std::to_string(i) + " is not finite");
        return true;
    }

    bool readPiece(pugi::xml_node piece, uint64_t index) {
        const std::optional<uint64_t> points =
            parseCount(piece.attribute("NumberOfPoints").value());
        const std::optional<uint64_t> cells = parseCount(piece.attribute("NumberOfCells").value());
        if (!points)
            return fail("Piece NumberOfPoints " +
                        quoted(piece.attribute("NumberOfPoints").value(), kShownChars) +
                        " is not a count");
        if (!cells)
            return fail("Piece NumberOfCells " +
                        quoted(piece.attribute("NumberOfCells").value(), kShownChars) +
                        " is not a count");
        const uint64_t point_base = grid_.points.size();
        const uint64_t cell_base = grid_.cell_types.size() + grid_.skipped_cells;
        if (*points > kMaxGridPoints - point_base)
            return fail("Piece NumberOfPoints " + std::to_string(*points) +
                        " makes more points than vissort's limit of " +
                        std::to_string(kMaxGridPoints));
        if (*cells > kMaxGridTets - cell_base)
            return fail("Piece NumberOfCells " + std::to_string(*cells) +
                        " makes more cells than vissort's limit of " +
                        std::to_string(kMaxGridTets));

        if (*points > 0) {
            const pugi::xml_node array = piece.child("Points").child("DataArray");
            if (!array)
                return fail("Points has no DataArray");
            const std::optional<uint64_t> components = componentsOf(array);
            if (components != 3)
                return fail("Points DataArray has " +
                            (components ? std::to_string(*components)
                                        : quoted(array.attribute("NumberOfComponents").value(),
                                                 kShownChars)) +
                            " components instead of 3");
            std::vector<double> coordinates;
            if (!readArray(array, "Points", *points * 3, 1, coordinates))
                return false;
            grid_.points.reserve(point_base + *points);
            for (uint64_t i = 0; i < *points; ++i)
                grid_.points.push_back(
                    {coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]});
        }
        if (*cells > 0 && !readCells(piece.child("Cells"), *cells, point_base, *points, cell_base))
            return false;
        return readPointData(piece.child("PointData"), *points, index);
    }

    bool readCells(pugi::xml_node cells_node, uint64_t cells, uint64_t point_base, uint64_t points,
                   uint64_t cell_base) {
        const pugi::xml_node connectivity_array =
            cells_node.find_child_by_attribute("DataArray", "Name", "connectivity");
        const pugi::xml_node offsets_array =
            cells_node.find_child_by_attribute("DataArray", "Name", "offsets");
        const pugi::xml_node types_array =
            cells_node.find_child_by_attribute("DataArray", "Name", "types");
        for (const auto& [array, name] :
             {std::pair{connectivity_array, "connectivity"}, std::pair{offsets_array, "offsets"},
              std::pair{types_array, "types"}})
            if (!array)
                return fail("Cells has no DataArray named '" + std::string(name) + "'");
        // offsets: each cell's end in connectivity.
        std::vector<int64_t> offsets, connectivity, types;
        if (!readArray(offsets_array, "Cells offsets", cells, 1, offsets))
            return false;
        int64_t previous = 0;
        for (uint64_t i = 0; i < cells; ++i) {
            if (offsets[i] < previous)
                return fail("Cells offsets decrease at cell " + std::to_string(cell_base + i) +
                            " (" + std::to_string(offsets[i]) + " after " +
                            std::to_string(previous) + ")");
            previous = offsets[i];
        }
        if (!readArray(connectivity_array, "Cells connectivity", uint64_t(offsets.back()), 1,
                       connectivity) ||
            !readArray(types_array, "Cells types", cells, 1, types))
            return false;
        grid_.cell_types.reserve(grid_.cell_types.size() + cells);
        grid_.cell_offsets.reserve(grid_.cell_offsets.size() + cells);
        grid_.cell_points.reserve(grid_.cell_points.size() + connectivity.size());
        for (uint64_t i = 0; i < cells; ++i) {
            const uint64_t begin = i == 0 ? 0 : uint64_t(offsets[i - 1]);
            const std::string problem =
                addVtkCell(grid_, cell_base + i, types[i], connectivity.data() + begin,
                           uint64_t(offsets[i]) - begin, point_base, points);
            if (!problem.empty())
                return fail(problem);
        }
        return true;
    }

    /// The scalars: in the first piece, the array named scalar_name, else the one PointData's
    /// Scalars attribute names, else the first of one component, else the first; in the next
    /// pieces, the array of the same name. The first component of an array of several.
    bool readPointData(pugi::xml_node point_data, uint64_t points, uint64_t index) {
        std::vector<pugi::xml_node> arrays;
        for (pugi::xml_node array = point_data.child("DataArray"); array;
             array = array.next_sibling("DataArray"))
            if (findElementType(array.attribute("type").as_string()))
                arrays.push_back(array);
        auto named = [&](const std::string& name) {
            if (name.empty())
                return pugi::xml_node();
            for (pugi::xml_node array : arrays)
                if (name == array.attribute("Name").as_string())
                    return array;
            return pugi::xml_node();
        };
        pugi::xml_node chosen;
        if (index == 0) {
            if (!wanted_scalar_.empty()) {
                chosen = named(wanted_scalar_);
                if (!chosen) {
                    std::vector<std::string> names;
                    for (pugi::xml_node array : arrays)
                        names.push_back(array.attribute("Name").as_string());
                    return fail("no point array named " + quoted(wanted_scalar_, kShownChars) +
                                ": " +
                                (names.empty() ? "the file has none"
                                               : "the file has " + listed(names, kShownChars)));
                }
            } else if (const pugi::xml_node active =
                           named(point_data.attribute("Scalars").as_string());
                       active) {
                chosen = active;
            } else {
                for (pugi::xml_node array : arrays)
                    if (componentsOf(array) == 1) {
                        chosen = array;
                        break;
                    }
                if (!chosen && !arrays.empty())
                    chosen = arrays.front();
            }
            if (!chosen)
                return true;
            has_scalars_ = true;
            grid_.scalar_name = chosen.attribute("Name").as_string();
        } else {
            if (!has_scalars_)
                return true;
            chosen = named(grid_.scalar_name);
            if (!chosen)
                return fail("no point array named " + quoted(grid_.scalar_name, kShownChars));
        }
        const std::string what = "PointData array " + quoted(grid_.scalar_name, kShownChars);
        const std::optional<uint64_t> parsed_components = componentsOf(chosen);
        if (!parsed_components)
            return fail(what + " has NumberOfComponents " +
                        quoted(chosen.attribute("NumberOfComponents").value(), kShownChars) +
                        ", not a whole number");
        const uint64_t components = *parsed_components;
        uint64_t count;
        if (components == 0)
            return fail(what + " has 0 components");
        if (__builtin_mul_overflow(points, components, &count))
            return fail(what + " has " + std::to_string(components) +
                        " components, more than any file holds");
        std::vector<double> values;
        if (!readArray(chosen, what, count, components, values))
            return false;
        grid_.scalars.insert(grid_.scalars.end(), values.begin(), values.end());
        return true;
    }

    /// Reads a DataArray of count values, keeping every stride-th (the first component of each
    /// tuple): as doubles, or as integers (which needs an integer type).
    template <class T>
    bool readArray(pugi::xml_node array, const std::string& what, uint64_t count, uint64_t stride,
                   std::vector<T>& out) {
        const std::string type_name = array.attribute("type").as_string();
        const std::optional<NumericType> type = findElementType(type_name);
        if (!type)
            return fail(what + " has the unknown type " + quoted(type_name, kShownChars) +
                        ": vissort reads Int8 to Int64, UInt8 to UInt64, Float32 and Float64");
        if (std::is_same_v<T, int64_t> && isFloat(*type))
            return fail(what + " has type " + shown(type_name, kShownChars) +
                        ": an integer type is needed");
        if (count > kMaxDataBytes / 8)
            return fail(what + " declares " + std::to_string(count) +
                        " values, more than any file holds");
        const std::string format = array.attribute("format").as_string();
        if (format == "ascii")
            return readAsciiArray(array, what, count, stride, out);

        std::string decoded;
        const uint64_t byte_count = count * numericSize(*type);
        if (format == "binary") {
            // Inline base64: whitespace may break the text; the array must fill it exactly.
            std::string text;
            for (const char c : std::string_view(array.child_value()))
                if (!isXmlSpace(c))
                    text.push_back(c);
            if (!readEncoded(text, false, true, what, byte_count, decoded))
                return false;
        } else if (format == "appended") {
            if (!has_appended_)
                return fail(what + " is appended, but the file has no AppendedData");
            const std::optional<uint64_t> offset = parseCount(array.attribute("offset").value());
            if (!offset)
                return fail(what + " offset " +
                            quoted(array.attribute("offset").value(), kShownChars) +
                            " is not a count");
            if (*offset > appended_.size())
                return fail(what + " offset " + std::to_string(*offset) +
                            " is beyond the appended data's " + std::to_string(appended_.size()) +
                            (appended_raw_ ? " bytes" : " characters"));
            if (!readEncoded(appended_.substr(*offset), appended_raw_, false, what, byte_count,
                             decoded))
                return false;
        } else {
            return fail(what + " has the unknown format " + quoted(format, kShownChars));
        }

        const auto* data = reinterpret_cast<const unsigned char*>(decoded.data());
        const std::string problem =
            appendBinaryValues(*type, data, count, stride, big_endian_, out);
        if (!problem.empty())
            return fail(what + " " + problem);
        return true;
    }

    template <class T>
    bool readAsciiArray(pugi::xml_node array, const std::string& what, uint64_t count,
                        uint64_t stride, std::vector<T>& out) {
        TokenScanner scan(array.child_value());
        if (count > scan.maxTokensLeft())
            return fail(what + " declares " + std::to_string(count) +
                        " values, more than its text can hold");
        out.reserve(count / stride + 1);
        for (uint64_t i = 0; i < count; ++i) {
            const std::string_view token = scan.next();
            if (token.empty())
                return fail(what + " has " + std::to_string(i) + " values instead of " +
                            std::to_string(count));
            const std::optional<T> value = parseAsciiValue<T>(token);
            if (!value)
                return fail(what + " " + badAsciiValue<T>(token, kShownChars));
            if (i % stride == 0)
                out.push_back(*value);
        }
        if (!scan.atEnd())
            return fail(what + " has more values than the " + std::to_string(count) + " expected");
        return true;
    }

    /// Decodes what starts at source (raw bytes, or base64 characters without whitespace) into
    /// byte_count bytes, compressed or not as the file says; exact: the array must end where
    /// source does (inline data).
    bool readEncoded(std::string_view source, bool raw, bool exact, const std::string& what,
                     uint64_t byte_count, std::string& out) {
        Segments segments{source, raw, what, *this};
        if (compressor_.empty()) {
            // [byte count][data], one segment.
            std::string header;
            if (!segments.read(0, header_size_, header))
                return false;
            const uint64_t declared = loadBits(
                reinterpret_cast<const unsigned char*>(header.data()), header_size_, big_endian_);
            if (declared != byte_count)
                return fail(what + " holds " + std::to_string(declared) + " bytes instead of the " +
                            std::to_string(byte_count) + " its values need");
            std::string all;
            if (!segments.read(0, header_size_ + byte_count, all))
                return false;
            if (exact && segments.length(header_size_ + byte_count) != source.size())
                return fail(what + " has data beyond its " + std::to_string(byte_count) + " bytes");
            out = all.substr(header_size_);
            return true;
        }
        if (compressor_ != "vtkZLibDataCompressor")
            return fail("compressor " + shown(compressor_, kShownChars) +
                        " is not supported: vissort reads vtkZLibDataCompressor");

        // [blocks][block size][last block size][compressed sizes...], one segment; the blocks,
        // another.
        std::string header;
        if (!segments.read(0, 3 * header_size_, header))
            return false;
        auto word = [&](uint64_t i) {
            return loadBits(reinterpret_cast<const unsigned char*>(header.data()) +
                                i * header_size_,
                            header_size_, big_endian_);
        };
        const uint64_t blocks = word(0), block_size = word(1), last_size = word(2);
        if (blocks > segments.maxBytes() / header_size_)
            return fail(what + " declares " + std::to_string(blocks) +
                        " compressed blocks, more than its data can hold");
        const uint64_t header_bytes = (3 + blocks) * header_size_;
        header.clear();
        if (!segments.read(0, header_bytes, header))
            return false;
        if (blocks > 0 && block_size == 0)
            return fail(what + " has compressed blocks of 0 bytes");
        if (last_size > block_size)
            return fail(what + ": the last compressed block (" + std::to_string(last_size) +
                        " bytes) is larger than its blocks (" + std::to_string(block_size) + ")");
        // The blocks but the last hold block_size bytes; the last, last_size (block_size if 0).
        uint64_t total = 0;
        if (blocks > 0 &&
            (__builtin_mul_overflow(blocks - 1, block_size, &total) ||
             __builtin_add_overflow(total, last_size == 0 ? block_size : last_size, &total)))
            total = UINT64_MAX;
        if (total != byte_count)
            return fail(what + " decompresses to " +
                        (total == UINT64_MAX ? std::string("too many") : std::to_string(total)) +
                        " bytes instead of the " + std::to_string(byte_count) + " its values need");
        std::vector<uint64_t> compressed_sizes(blocks);
        uint64_t compressed_total = 0;
        for (uint64_t i = 0; i < blocks; ++i) {
            compressed_sizes[i] = word(3 + i);
            const uint64_t inflated = i + 1 == blocks && last_size != 0 ? last_size : block_size;
            if (compressed_sizes[i] > segments.maxBytes() ||
                inflated > maxInflatedSize(compressed_sizes[i]))
                return fail(what + ": compressed block " + std::to_string(i) + " of " +
                            std::to_string(compressed_sizes[i]) + " bytes cannot hold " +
                            std::to_string(inflated));
            compressed_total += compressed_sizes[i]; // at most blocks * maxBytes(): no overflow
        }
        const uint64_t data_start = segments.length(header_bytes);
        std::string compressed;
        if (!segments.read(data_start, compressed_total, compressed))
            return false;
        if (exact && data_start + segments.length(compressed_total) != source.size())
            return fail(what + " has data beyond its " + std::to_string(compressed_total) +
                        " compressed bytes");
        out.resize(byte_count);
        uint64_t from = 0, to = 0;
        for (uint64_t i = 0; i < blocks; ++i) {
            const uint64_t inflated = i + 1 == blocks && last_size != 0 ? last_size : block_size;
            uLongf length = uLongf(inflated);
            const int status = uncompress(reinterpret_cast<Bytef*>(out.data() + to), &length,
                                          reinterpret_cast<const Bytef*>(compressed.data() + from),
                                          uLong(compressed_sizes[i]));
            if (status != Z_OK || length != inflated)
                return fail(what + ": compressed block " + std::to_string(i) +
                            " does not decompress" +
                            (status == Z_OK ? " to " + std::to_string(inflated) + " bytes"
                                            : ": zlib " + std::string(zError(status))));
            from += compressed_sizes[i];
            to += inflated;
        }
        return true;
    }

    /// The encoded segments of one array: raw bytes, or base64 text in which each segment is
    /// padded on its own.
    struct Segments {
        std::string_view source;
        bool raw;
        const std::string& what;
        VtuReader& reader;

        /// The characters (or bytes) that hold a segment of bytes.
        uint64_t length(uint64_t bytes) const { return raw ? bytes : base64Length(bytes); }
        /// The most bytes the source could hold.
        uint64_t maxBytes() const { return raw ? source.size() : source.size() / 4 * 3; }

        /// Decodes the first bytes of the segment that starts at start (bytes or characters).
        bool read(uint64_t start, uint64_t bytes, std::string& out) const {
            const uint64_t needed = length(bytes);
            if (start > source.size() || needed > source.size() - start)
                return reader.fail(
                    what + " is cut short: it needs " + std::to_string(needed) +
                    (raw ? " bytes" : " base64 characters") + ", but " +
                    std::to_string(start > source.size() ? 0 : source.size() - start) +
                    " are left");
            const std::string_view chunk = source.substr(start, needed);
            if (raw) {
                out.assign(chunk);
                return true;
            }
            out.clear();
            if (!decodeBase64(chunk, out))
                return reader.fail(what + " has invalid base64 data");
            // Decoding may give more bytes than asked when the segment goes on past them.
            if (out.size() < bytes)
                return reader.fail(what + " has invalid base64 padding");
            out.resize(bytes);
            return true;
        }
    };

    std::string_view bytes_;
    std::string wanted_scalar_;
    std::string error_;
    std::string piece_prefix_;

    bool big_endian_ = false;
    uint64_t header_size_ = 4;
    std::string compressor_;
    bool has_appended_ = false, appended_raw_ = false;
    std::string_view appended_;

    RawGrid grid_;
    bool has_scalars_ = false;
};

} // namespace

Result<RawGrid> readVtu(const std::string& bytes, const std::string& scalar_name) {
    return VtuReader(bytes, scalar_name).read();
}

} // namespace vissort::detail
