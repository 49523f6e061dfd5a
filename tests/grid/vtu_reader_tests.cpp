// Tests of src/grid/vtu_reader.cpp: a hand-written ASCII file checked value by value; the same
// grid encoded here in every layout the reader knows (base64 and appended raw or base64, UInt32
// and UInt64 headers, zlib in one or many blocks, either byte order); the files VTK 9.1 itself
// wrote (tests/data/grids/vtu_mixed_*.vtu); several pieces; and every class of problem.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <zlib.h>

#include "grid/raw_grid.h"
#include "reader_test_support.h"

namespace vissort::detail {
namespace {

std::string base64(const std::string& bytes) {
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t bits = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size())
            bits |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size())
            bits |= uint8_t(bytes[i + 2]);
        text += alphabet[bits >> 18];
        text += alphabet[(bits >> 12) & 63];
        text += i + 1 < bytes.size() ? alphabet[(bits >> 6) & 63] : '=';
        text += i + 2 < bytes.size() ? alphabet[bits & 63] : '=';
    }
    return text;
}

/// How VtuWriter encodes the arrays.
struct Layout {
    std::string format = "ascii"; // "binary" or "appended"
    bool raw = false;             // appended data: raw, else base64
    uint64_t block_size = 0;      // zlib blocks of this many bytes; 0: not compressed
    int header_size = 4;
    bool big_endian = false;
};

/// A VTK XML file built array by array in one layout.
class VtuWriter {
public:
    explicit VtuWriter(Layout layout) : layout_(std::move(layout)) {}

    std::string array(const std::string& type, const std::string& name,
                      const std::vector<double>& values, int components = 1) {
        std::string xml = "<DataArray type=\"" + type + "\" Name=\"" + name +
                          "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"" +
                          layout_.format + "\"";
        if (layout_.format == "ascii") {
            xml += ">";
            for (double value : values) {
                std::ostringstream text;
                text << value;
                xml += " " + text.str();
            }
            return xml + "</DataArray>\n";
        }
        const std::string payload = encode(binary(type, values));
        if (layout_.format == "binary")
            return xml + ">\n" + payload + "\n</DataArray>\n";
        xml += " offset=\"" + std::to_string(appended_.size()) + "\"/>\n";
        appended_ += payload;
        return xml;
    }

    std::string file(const std::string& pieces) const {
        std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
                          "version=\"1.0\" byte_order=\"" +
                          std::string(layout_.big_endian ? "BigEndian" : "LittleEndian") +
                          "\" header_type=\"" + (layout_.header_size == 8 ? "UInt64" : "UInt32") +
                          "\"" +
                          (layout_.block_size ? " compressor=\"vtkZLibDataCompressor\"" : "") +
                          ">\n<UnstructuredGrid>\n" + pieces + "</UnstructuredGrid>\n";
        if (layout_.format == "appended")
            xml += "<AppendedData encoding=\"" + std::string(layout_.raw ? "raw" : "base64") +
                   "\">\n   _" + appended_ + "\n</AppendedData>\n";
        return xml + "</VTKFile>\n";
    }

    std::string word(uint64_t value, int size) const {
        std::string bytes;
        for (int i = 0; i < size; ++i)
            bytes.push_back(char(value >> (8 * i)));
        if (layout_.big_endian)
            std::reverse(bytes.begin(), bytes.end());
        return bytes;
    }

private:
    std::string binary(const std::string& type, const std::vector<double>& values) const {
        std::string bytes;
        for (double value : values) {
            if (type == "Float32") {
                const float narrow = float(value);
                uint32_t bits;
                std::memcpy(&bits, &narrow, 4);
                bytes += word(bits, 4);
            } else if (type == "Float64") {
                uint64_t bits;
                std::memcpy(&bits, &value, 8);
                bytes += word(bits, 8);
            } else if (type == "UInt8") {
                bytes += word(uint64_t(value), 1);
            } else if (type == "Int32") {
                bytes += word(uint64_t(int64_t(value)), 4);
            } else {
                bytes += word(uint64_t(int64_t(value)), 8); // Int64
            }
        }
        return bytes;
    }

    std::string encode(const std::string& data) const {
        const bool text = layout_.format == "binary" || !layout_.raw;
        if (layout_.block_size == 0) {
            const std::string all = word(data.size(), layout_.header_size) + data;
            return text ? base64(all) : all;
        }
        const uint64_t size = layout_.block_size;
        const uint64_t blocks = (data.size() + size - 1) / size;
        std::string header = word(blocks, layout_.header_size) + word(size, layout_.header_size) +
                             word(data.size() % size, layout_.header_size);
        std::string compressed;
        for (uint64_t b = 0; b < blocks; ++b) {
            const std::string block = data.substr(b * size, size);
            uLongf length = compressBound(uLong(block.size()));
            std::string out(length, '\0');
            compress(reinterpret_cast<Bytef*>(out.data()), &length,
                     reinterpret_cast<const Bytef*>(block.data()), uLong(block.size()));
            out.resize(length);
            header += word(length, layout_.header_size);
            compressed += out;
        }
        return text ? base64(header) + base64(compressed) : header + compressed;
    }

    Layout layout_;
    std::string appended_;
};

const std::vector<double> kPoints = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1,   0,   0, 0,
                                     1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0.5, 2};
const std::vector<double> kTemperature = {0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4};

/// A hexahedron, a tetrahedron and a triangle over 9 points, with a vector and a scalar.
std::string hexTetTriangle(Layout layout) {
    VtuWriter writer(std::move(layout));
    std::vector<double> velocity;
    for (int i = 0; i < 9; ++i)
        velocity.insert(velocity.end(), {-1.0 * i, 2.0 * i, 3.0 * i});
    std::string piece = "<Piece NumberOfPoints=\"9\" NumberOfCells=\"3\">\n<PointData>\n";
    piece += writer.array("Float32", "velocity", velocity, 3);
    piece += writer.array("Float64", "temperature", kTemperature);
    piece += "</PointData>\n<Points>\n" + writer.array("Float32", "Points", kPoints, 3);
    piece += "</Points>\n<Cells>\n";
    piece += writer.array("Int64", "connectivity", {0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 8, 0, 1, 2});
    piece += writer.array("Int32", "offsets", {8, 12, 15});
    piece += writer.array("UInt8", "types", {12, 10, 5});
    piece += "</Cells>\n</Piece>\n";
    return writer.file(piece);
}

void expectHexTetTriangle(const RawGrid& grid) {
    ASSERT_EQ(grid.points.size(), 9u);
    for (std::size_t i = 0; i < 9; ++i)
        EXPECT_EQ(grid.points[i], (Vec3{kPoints[3 * i], kPoints[3 * i + 1], kPoints[3 * i + 2]}))
            << i;
    EXPECT_EQ(grid.cell_types,
              (std::vector<CellType>{CellType::hexahedron, CellType::tetrahedron}));
    EXPECT_EQ(grid.cell_offsets, (std::vector<uint64_t>{0, 8, 12}));
    EXPECT_EQ(grid.cell_points, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 8}));
    EXPECT_EQ(grid.skipped_cells, 1u);
    EXPECT_EQ(grid.scalar_name, "temperature");
    EXPECT_EQ(grid.scalars, kTemperature);
}

TEST(VtuReader, HandWrittenAscii) {
    const Result<RawGrid> grid = readVtu(R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
  <UnstructuredGrid>
    <Piece NumberOfPoints="9" NumberOfCells="3">
      <PointData Scalars="temperature">
        <DataArray type="Int32" Name="id" format="ascii">1 2 3 4 5 6 7 8 9</DataArray>
        <DataArray type="Float64" Name="temperature" format="ascii">
          0 0.5 1 1.5 2
          2.5 3 3.5 4
        </DataArray>
      </PointData>
      <CellData>
        <DataArray type="Float64" Name="quality" format="ascii">1 2 3</DataArray>
      </CellData>
      <Points>
        <DataArray type="Float32" NumberOfComponents="3" format="ascii">
          0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1 0.5 0.5 2
          <InformationKey name="L2_NORM_RANGE" location="vtkDataArray" length="2">
            <Value index="0">0</Value>
          </InformationKey>
        </DataArray>
      </Points>
      <Cells>
        <DataArray type="Int32" Name="connectivity" format="ascii">
          0 1 2 3 4 5 6 7 4 5 6 8 0 1 2
        </DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">8 12 15</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">12 10 5</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)");
    ASSERT_TRUE(grid) << grid.error;
    expectHexTetTriangle(*grid.value);
}

TEST(VtuReader, EveryEncodingReadsTheSame) {
    std::vector<Layout> layouts = {{"ascii"}};
    for (const char* format : {"binary", "appended"})
        for (bool raw : {false, true})
            for (uint64_t block_size : {0, 16, 12, 1 << 15})
                for (int header_size : {4, 8})
                    for (bool big_endian : {false, true})
                        if (!raw || std::string(format) == "appended")
                            layouts.push_back({format, raw, block_size, header_size, big_endian});
    for (const Layout& layout : layouts) {
        SCOPED_TRACE(layout.format + (layout.raw ? " raw" : "") + " blocks " +
                     std::to_string(layout.block_size) + " header " +
                     std::to_string(layout.header_size) + (layout.big_endian ? " BE" : " LE"));
        const Result<RawGrid> grid = readVtu(hexTetTriangle(layout));
        ASSERT_TRUE(grid) << grid.error;
        expectHexTetTriangle(*grid.value);
    }
}

const char* kVtkWrittenFiles[] = {"vtu_mixed_ascii.vtu",
                                  "vtu_mixed_binary.vtu",
                                  "vtu_mixed_binary_uint64.vtu",
                                  "vtu_mixed_binary_zlib.vtu",
                                  "vtu_mixed_appended_raw.vtu",
                                  "vtu_mixed_appended_base64.vtu",
                                  "vtu_mixed_appended_raw_zlib_uint64.vtu",
                                  "vtu_mixed_big_endian_zlib.vtu",
                                  "vtu_mixed_appended_raw_big_endian.vtu"};

TEST(VtuReader, FilesWrittenByVtkReadAlike) {
    for (const char* name : kVtkWrittenFiles) {
        SCOPED_TRACE(name);
        const std::string bytes = test::readGridData(name);
        ASSERT_FALSE(bytes.empty());
        const Result<RawGrid> grid = readVtu(bytes);
        ASSERT_TRUE(grid) << grid.error;
        test::expectMixedGrid(*grid.value);
        // PointData's Scalars attribute names the active scalars.
        EXPECT_EQ(grid.value->scalar_name, "temperature");
        ASSERT_EQ(grid.value->scalars.size(), 17u);
        for (std::size_t i = 0; i < 17; ++i)
            EXPECT_EQ(grid.value->scalars[i], 0.5 * double(i));

        const Result<RawGrid> velocity = readVtu(bytes, "velocity");
        ASSERT_TRUE(velocity) << velocity.error;
        ASSERT_EQ(velocity.value->scalars.size(), 17u);
        for (std::size_t i = 0; i < 17; ++i)
            EXPECT_EQ(velocity.value->scalars[i], -double(i));

        const Result<RawGrid> pressure = readVtu(bytes, "pressure");
        ASSERT_TRUE(pressure) << pressure.error;
        for (std::size_t i = 0; i < 17; ++i)
            EXPECT_EQ(pressure.value->scalars[i], 100.0 + i);
    }
}

TEST(VtuReader, ScalarChoice) {
    // No Scalars attribute: the first array of one component, although velocity comes first.
    const Result<RawGrid> grid = readVtu(hexTetTriangle({}));
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->scalar_name, "temperature");

    const Result<RawGrid> missing =
        readVtu(test::readGridData("vtu_mixed_binary_zlib.vtu"), "material");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error, "no point array named 'material': the file has 'temperature', "
                             "'velocity', 'pressure'");

    std::string bare = hexTetTriangle({});
    bare.erase(bare.find("<PointData>"), bare.find("<Points>") - bare.find("<PointData>"));
    const Result<RawGrid> none = readVtu(bare);
    ASSERT_TRUE(none) << none.error;
    EXPECT_TRUE(none.value->scalars.empty());
    EXPECT_EQ(readVtu(bare, "t").error, "no point array named 't': the file has none");
}

std::string twoPieces(bool second_has_scalars) {
    VtuWriter writer({"appended", true});
    std::string pieces;
    for (int piece = 0; piece < 2; ++piece) {
        pieces += "<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">\n<PointData>\n";
        if (piece == 0 || second_has_scalars)
            pieces += writer.array("Float32", "t", {10.0 * piece, 1, 2, 3});
        pieces += "</PointData>\n<Points>\n";
        pieces +=
            writer.array("Float64", "Points", {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.0 + piece}, 3);
        pieces += "</Points>\n<Cells>\n";
        pieces += writer.array("Int64", "connectivity", {3, 0, 1, 2, 3});
        pieces += writer.array("Int64", "offsets", {1, 5});
        pieces += writer.array("UInt8", "types", {1, 10});
        pieces += "</Cells>\n</Piece>\n";
    }
    return writer.file(pieces);
}

TEST(VtuReader, SeveralPiecesAreConcatenated) {
    const Result<RawGrid> grid = readVtu(twoPieces(true));
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->points.size(), 8u);
    EXPECT_EQ(grid.value->points[7], (Vec3{0, 0, 2}));
    EXPECT_EQ(grid.value->cell_types,
              (std::vector<CellType>{CellType::tetrahedron, CellType::tetrahedron}));
    EXPECT_EQ(grid.value->cell_points, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(grid.value->skipped_cells, 2u);
    EXPECT_EQ(grid.value->scalars, (std::vector<double>{0, 1, 2, 3, 10, 1, 2, 3}));

    EXPECT_EQ(readVtu(twoPieces(false)).error, "piece 1: no point array named 't'");
}

std::string vtuError(const std::string& bytes, const std::string& scalar_name = {}) {
    const Result<RawGrid> grid = readVtu(bytes, scalar_name);
    EXPECT_FALSE(grid);
    return grid.error;
}

/// text with its first `from` replaced by `to`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

/// Where the appended data of the array named name start in file.
std::size_t appendedStart(const std::string& file, const std::string& name) {
    const std::size_t array = file.find("Name=\"" + name + "\"");
    const std::size_t offset = file.find("offset=\"", array) + 8;
    return file.find('_', file.find("<AppendedData")) + 1 +
           std::stoull(file.substr(offset, file.find('"', offset) - offset));
}

TEST(VtuReader, RefusesOtherFiles) {
    const std::string ascii = hexTetTriangle({});
    EXPECT_EQ(vtuError(edited(ascii, "UnstructuredGrid\" version", "PolyData\" version")),
              "VTKFile type 'PolyData': vissort reads UnstructuredGrid");
    EXPECT_EQ(vtuError("<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>"),
              "not valid XML: Start-end tags mismatch at byte 50");
    EXPECT_EQ(vtuError("<?xml version=\"1.0\"?>\n<Mesh/>"),
              "not a VTK XML file: it has no VTKFile element");
    EXPECT_EQ(vtuError(edited(ascii, "LittleEndian", "MiddleEndian")),
              "unknown byte_order 'MiddleEndian'");
    EXPECT_EQ(vtuError(edited(ascii, "UInt32", "UInt16")),
              "unknown header_type 'UInt16': UInt32 or UInt64 expected");
    EXPECT_EQ(vtuError(edited(edited(ascii, "<Piece", "<Bit"), "</Piece", "</Bit")),
              "UnstructuredGrid has no Piece");
}

TEST(VtuReader, MessagesQuoteTheFileShortAndOnOneLine) {
    const std::string ascii = hexTetTriangle({});
    EXPECT_EQ(vtuError(edited(ascii, "Name=\"temperature\"", "Name=\"temp&#10;erature\""), "t"),
              "no point array named 't': the file has 'velocity', 'temp?erature'");
    EXPECT_EQ(vtuError(edited(ascii, "Float32\" Name=\"Points",
                              std::string(60, 'F') + "\" Name=\"Points")),
              "Points has the unknown type '" + std::string(40, 'F') +
                  "...': vissort reads Int8 to Int64, UInt8 to UInt64, Float32 and Float64");
}

TEST(VtuReader, RefusesCellsItDoesNotRead) {
    const std::string ascii = hexTetTriangle({});
    EXPECT_EQ(vtuError(edited(ascii, "12 10 5", "12 24 5")),
              "cell 1 has VTK type 24 (quadratic tetrahedron), which vissort does not read: only "
              "linear tetrahedra, hexahedra, wedges, pyramids and voxels");
    EXPECT_EQ(vtuError(edited(ascii, "12 10 5", "12 14 5")),
              "cell 1 (VTK type 14, pyramid) has 4 corners instead of 5");
    EXPECT_EQ(vtuError(edited(ascii, "4 5 6 8", "4 5 6 9")),
              "cell 1 refers to point 9, but the points are numbered 0 to 8");
    EXPECT_EQ(vtuError(edited(ascii, "4 5 6 8", "4 5 6 -2")),
              "cell 1 refers to point -2, but the points are numbered 0 to 8");
    EXPECT_EQ(vtuError(edited(ascii, "8 12 15", "8 7 15")),
              "Cells offsets decrease at cell 1 (7 after 8)");
    EXPECT_EQ(vtuError(edited(ascii, "8 12 15", "8 12 16")),
              "Cells connectivity has 15 values instead of 16");
}

TEST(VtuReader, RefusesNonFiniteValues) {
    const std::string ascii = hexTetTriangle({});
    EXPECT_EQ(vtuError(edited(ascii, "1 1 0 0 1 0", "1 1 0 0 nan 0")),
              "point 3 has a coordinate that is not finite");
    EXPECT_EQ(vtuError(edited(ascii, "3.5 4", "3.5 -inf")),
              "the scalar 'temperature' of point 8 is not finite");
}

TEST(VtuReader, RefusesBadArrays) {
    const std::string ascii = hexTetTriangle({});
    EXPECT_EQ(vtuError(edited(ascii, "Float32\" Name=\"Points", "String\" Name=\"Points")),
              "Points has the unknown type 'String': vissort reads Int8 to Int64, UInt8 to "
              "UInt64, Float32 and Float64");
    EXPECT_EQ(
        vtuError(edited(ascii, "Int64\" Name=\"connectivity", "Float32\" Name=\"connectivity")),
        "Cells connectivity has type Float32: an integer type is needed");
    EXPECT_EQ(vtuError(edited(ascii, "Name=\"connectivity", "Name=\"connections")),
              "Cells has no DataArray named 'connectivity'");
    EXPECT_EQ(vtuError(edited(ascii, "Points\" NumberOfComponents=\"3",
                              "Points\" NumberOfComponents=\"2")),
              "Points DataArray has 2 components instead of 3");
    // Counts are read whole: pugixml's own reading takes "3x" for 3.
    EXPECT_EQ(vtuError(edited(ascii, "Points\" NumberOfComponents=\"3",
                              "Points\" NumberOfComponents=\"3x")),
              "Points DataArray has '3x' components instead of 3");
    EXPECT_EQ(vtuError(edited(ascii, "0.5 0.5 2", "0.5 0.5")),
              "Points has 26 values instead of 27");
    EXPECT_EQ(vtuError(edited(ascii, "0.5 0.5 2", "0.5 0.5 2 7")),
              "Points has more values than the 27 expected");
    EXPECT_EQ(vtuError(edited(ascii, "0.5 0.5 2", "0.5 0.5 two")),
              "Points value 'two' is not a number");
    EXPECT_EQ(vtuError(edited(ascii, "12 10 5", "12 10 5.5")),
              "Cells types value '5.5' is not an integer");
    EXPECT_EQ(vtuError(edited(ascii, "Points\" NumberOfComponents=\"3\" format=\"ascii",
                              "Points\" NumberOfComponents=\"3\" format=\"hex")),
              "Points has the unknown format 'hex'");
    EXPECT_EQ(vtuError(edited(ascii, "NumberOfCells=\"3", "NumberOfCells=\"three")),
              "Piece NumberOfCells 'three' is not a count");
    const std::string binary = hexTetTriangle({"binary", false, 16});
    EXPECT_EQ(vtuError(edited(binary, "vtkZLibDataCompressor", "vtkLZ4DataCompressor")),
              "compressor vtkLZ4DataCompressor is not supported: vissort reads "
              "vtkZLibDataCompressor");
    const std::string appended = hexTetTriangle({"appended"});
    EXPECT_EQ(vtuError(edited(edited(appended, "<AppendedData", "<Appendix"), "</AppendedData",
                              "</Appendix")),
              "Points is appended, but the file has no AppendedData");
}

TEST(VtuReader, RefusesHugeCountsBeforeAllocating) {
    // Small files declaring billions of values fail on the count, allocating nothing.
    const std::string ascii = hexTetTriangle({});
    EXPECT_EQ(vtuError(edited(ascii, "NumberOfPoints=\"9", "NumberOfPoints=\"4000000000")),
              "Piece NumberOfPoints 4000000000 makes more points than vissort's limit of "
              "67108864");
    EXPECT_EQ(vtuError(edited(ascii, "NumberOfCells=\"3", "NumberOfCells=\"4000000000")),
              "Piece NumberOfCells 4000000000 makes more cells than vissort's limit of 67108864");
    EXPECT_EQ(vtuError(edited(ascii, "NumberOfPoints=\"9", "NumberOfPoints=\"50000000")),
              "Points declares 150000000 values, more than its text can hold");
    EXPECT_EQ(vtuError(edited(ascii, "8 12 15", "8 12 4000000000000")),
              "Cells connectivity declares 4000000000000 values, more than its text can hold");

    // Binary data whose header disagrees with the count.
    const std::string binary = hexTetTriangle({"binary"});
    EXPECT_EQ(vtuError(edited(binary, "NumberOfPoints=\"9", "NumberOfPoints=\"50000000")),
              "Points holds 108 bytes instead of the 600000000 its values need");

    // A zlib header that adds up, but whose blocks could never inflate that far.
    VtuWriter writer({"appended", true, 16});
    std::string bomb = hexTetTriangle({"appended", true, 16});
    const std::string header =
        writer.word(1, 4) + writer.word(600000000, 4) + writer.word(0, 4) + writer.word(20, 4);
    bomb = edited(bomb, "NumberOfPoints=\"9", "NumberOfPoints=\"50000000");
    bomb.replace(appendedStart(bomb, "Points"), header.size(), header);
    EXPECT_EQ(vtuError(bomb), "Points: compressed block 0 of 20 bytes cannot hold 600000000");
    // Or that declares more blocks than the file has bytes.
    std::string blocks = hexTetTriangle({"appended", true, 16});
    const std::string many = writer.word(4000000000u, 4);
    blocks.replace(appendedStart(blocks, "Points"), many.size(), many);
    EXPECT_EQ(vtuError(blocks),
              "Points declares 4000000000 compressed blocks, more than its data can hold");
}

TEST(VtuReader, RefusesCorruptEncodedData) {
    const std::string binary = hexTetTriangle({"binary"});
    const std::size_t data = binary.find(">\n", binary.find("Name=\"Points")) + 2;
    std::string bad = binary;
    bad[data + 5] = '*';
    EXPECT_EQ(vtuError(bad), "Points has invalid base64 data");
    bad = binary;
    bad.insert(data + 8, "QUJD");
    EXPECT_EQ(vtuError(bad), "Points has data beyond its 108 bytes");

    // The header is fine, the compressed bytes are not: temperature has 5 blocks.
    std::string zipped = hexTetTriangle({"appended", true, 16});
    const std::size_t block = appendedStart(zipped, "temperature") + 4 * (3 + 5);
    zipped[block + 2] = char(zipped[block + 2] ^ 0x55);
    EXPECT_EQ(vtuError(zipped), "PointData array 'temperature': compressed block 0 does not "
                                "decompress: zlib data error");

    // Raw appended data cut short.
    const std::string raw = hexTetTriangle({"appended", true});
    EXPECT_EQ(vtuError(raw.substr(0, raw.size() - 40)),
              "Cells offsets is cut short: it needs 16 bytes, but 11 are left");
    EXPECT_EQ(vtuError(raw.substr(0, appendedStart(raw, "Points") + 50)),
              "Points is cut short: it needs 112 bytes, but 50 are left");
    // A header that disagrees with the array's count.
    std::string sized = raw;
    const std::string wrong = VtuWriter({"appended", true}).word(100, 4);
    sized.replace(appendedStart(sized, "Points"), wrong.size(), wrong);
    EXPECT_EQ(vtuError(sized), "Points holds 100 bytes instead of the 108 its values need");
}

} // namespace
} // namespace vissort::detail
