// Tests of src/grid/vtk_legacy_reader.cpp: hand-written ASCII files and BINARY ones built here
// byte by byte (big-endian), checked value by value; the files VTK 9.1 itself wrote
// (tests/data/grids/vtk_mixed_*.vtk, versions 4.2 and 5.1); and every class of problem.

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "grid/raw_grid.h"
#include "reader_test_support.h"

namespace vissort::detail {
namespace {

/// A legacy BINARY file: text lines and big-endian numbers.
struct BinaryFile {
    std::string bytes;

    BinaryFile& line(const std::string& text) {
        bytes += text + "\n";
        return *this;
    }
    template <class T> BinaryFile& values(std::initializer_list<T> list) {
        for (T value : list) {
            unsigned char raw[sizeof(T)];
            std::memcpy(raw, &value, sizeof(T));
            for (std::size_t i = sizeof(T); i-- > 0;)
                bytes.push_back(char(raw[i]));
        }
        bytes += "\n"; // as vtkDataWriter ends binary data
        return *this;
    }
};
static_assert(std::endian::native == std::endian::little, "the byte swapping above assumes it");

const char* kHexTetTriangle = R"(# vtk DataFile Version 3.0
a hexahedron, a tetrahedron and a triangle
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 9 float
0 0 0  1 0 0  1 1 0  0 1 0
0 0 1  1 0 1  1 1 1  0 1 1
0.5 0.5 2
CELLS 3 18
8 0 1 2 3 4 5 6 7
4 4 5 6 8
3 0 1 2
CELL_TYPES 3
12
10
5
POINT_DATA 9
SCALARS temperature float 1
LOOKUP_TABLE default
0 0.5 1 1.5 2 2.5 3 3.5 4
)";

void expectHexTetTriangle(const RawGrid& grid) {
    const std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},    {0, 0, 1},
                                      {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0.5, 0.5, 2}};
    ASSERT_EQ(grid.points.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        EXPECT_EQ(grid.points[i], points[i]) << i;
    EXPECT_EQ(grid.cell_types,
              (std::vector<CellType>{CellType::hexahedron, CellType::tetrahedron}));
    EXPECT_EQ(grid.cell_offsets, (std::vector<uint64_t>{0, 8, 12}));
    EXPECT_EQ(grid.cell_points, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 8}));
    EXPECT_EQ(grid.skipped_cells, 1u);
    EXPECT_EQ(grid.scalar_name, "temperature");
    EXPECT_EQ(grid.scalars, (std::vector<double>{0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4}));
}

BinaryFile hexTetTriangleBinary() {
    BinaryFile file;
    file.line("# vtk DataFile Version 3.0").line("binary twin").line("BINARY");
    file.line("DATASET UNSTRUCTURED_GRID").line("POINTS 9 float");
    file.values<float>(
        {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5f, 0.5f, 2});
    file.line("CELLS 3 18");
    file.values<int32_t>({8, 0, 1, 2, 3, 4, 5, 6, 7, 4, 4, 5, 6, 8, 3, 0, 1, 2});
    file.line("CELL_TYPES 3").values<int32_t>({12, 10, 5});
    return file;
}

TEST(VtkLegacyReader, HandWrittenAsciiHexTetTriangleAndScalars) {
    const Result<RawGrid> grid = readVtkLegacy(kHexTetTriangle);
    ASSERT_TRUE(grid) << grid.error;
    expectHexTetTriangle(*grid.value);
}

TEST(VtkLegacyReader, BinaryTwinReadsTheSame) {
    BinaryFile file = hexTetTriangleBinary();
    file.line("POINT_DATA 9").line("SCALARS temperature double 1").line("LOOKUP_TABLE default");
    file.values<double>({0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4});
    const Result<RawGrid> grid = readVtkLegacy(file.bytes);
    ASSERT_TRUE(grid) << grid.error;
    expectHexTetTriangle(*grid.value);
}

TEST(VtkLegacyReader, Version51OffsetsAndConnectivityWithMetadata) {
    const Result<RawGrid> grid = readVtkLegacy(R"(# vtk DataFile Version 5.1
vtk output
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 9 double
0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1 0.5 0.5 2
METADATA
INFORMATION 2
NAME L2_NORM_RANGE LOCATION vtkDataArray
DATA 2 0 2.12132

NAME L2_NORM_FINITE_RANGE LOCATION vtkDataArray
DATA 2 0 2.12132

CELLS 4 15
OFFSETS vtktypeint64
0 8 12 15
CONNECTIVITY int
0 1 2 3 4 5 6 7 4 5 6 8 0 1 2
CELL_TYPES 3
12 10 5

POINT_DATA 9
SCALARS temperature float
LOOKUP_TABLE default
0 0.5 1 1.5 2 2.5 3 3.5 4
)");
    ASSERT_TRUE(grid) << grid.error;
    expectHexTetTriangle(*grid.value);
}

TEST(VtkLegacyReader, Version51BinaryWithInt32Offsets) {
    BinaryFile file;
    file.line("# vtk DataFile Version 5.1").line("vtk output").line("BINARY");
    file.line("DATASET UNSTRUCTURED_GRID").line("POINTS 9 double");
    file.values<double>(
        {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0.5, 2});
    file.line("CELLS 4 15").line("OFFSETS vtktypeint32").values<int32_t>({0, 8, 12, 15});
    file.line("CONNECTIVITY vtktypeint64");
    file.values<int64_t>({0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 8, 0, 1, 2});
    file.line("CELL_TYPES 3").values<int32_t>({12, 10, 5});
    file.line("POINT_DATA 9").line("SCALARS temperature float").line("LOOKUP_TABLE default");
    file.values<float>({0, 0.5f, 1, 1.5f, 2, 2.5f, 3, 3.5f, 4});
    const Result<RawGrid> grid = readVtkLegacy(file.bytes);
    ASSERT_TRUE(grid) << grid.error;
    expectHexTetTriangle(*grid.value);
}

TEST(VtkLegacyReader, FilesWrittenByVtkReadAlike) {
    for (const char* name : {"vtk_mixed_42_ascii.vtk", "vtk_mixed_42_binary.vtk",
                             "vtk_mixed_51_ascii.vtk", "vtk_mixed_51_binary.vtk"}) {
        SCOPED_TRACE(name);
        const std::string bytes = test::readGridData(name);
        ASSERT_FALSE(bytes.empty());
        const Result<RawGrid> grid = readVtkLegacy(bytes);
        ASSERT_TRUE(grid) << grid.error;
        test::expectMixedGrid(*grid.value);
        EXPECT_EQ(grid.value->scalar_name, "temperature");
    }
}

TEST(VtkLegacyReader, NamedScalarAndTheNamesWhenAbsent) {
    for (const char* name : {"vtk_mixed_42_binary.vtk", "vtk_mixed_51_ascii.vtk"}) {
        SCOPED_TRACE(name);
        const std::string bytes = test::readGridData(name);
        const Result<RawGrid> pressure = readVtkLegacy(bytes, "pressure");
        ASSERT_TRUE(pressure) << pressure.error;
        EXPECT_EQ(pressure.value->scalar_name, "pressure");
        ASSERT_EQ(pressure.value->scalars.size(), 17u);
        for (std::size_t i = 0; i < 17; ++i)
            EXPECT_EQ(pressure.value->scalars[i], 100.0 + i);

        // Vectors are not scalars; cell arrays are not point arrays.
        const Result<RawGrid> missing = readVtkLegacy(bytes, "material");
        ASSERT_FALSE(missing);
        EXPECT_EQ(missing.error,
                  "no point array named 'material': the file has 'temperature', 'pressure'");
    }
}

const char* kFieldOnly = R"(# vtk DataFile Version 2.0
FIELD arrays as point data
ASCII
DATASET UNSTRUCTURED_GRID
FIELD FieldData 2
TIME 1 1 double
12.5
CYCLE 1 1 int
3
POINTS 4 float
0 0 0 1 0 0 0 1 0 0 0 1
CELLS 1 5
4 0 1 2 3
CELL_TYPES 1
10
POINT_DATA 4
FIELD FieldData 3
velocity 3 4 float
1 2 3 4 5 6 7 8 9 10 11 12
names 1 4 string
first
second%20one
third
fourth
pressure 1 4 double
10 20 30 40
)";

TEST(VtkLegacyReader, FieldArraysAreScalarCandidates) {
    // One component preferred: pressure, although velocity comes first.
    const Result<RawGrid> grid = readVtkLegacy(kFieldOnly);
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->scalar_name, "pressure");
    EXPECT_EQ(grid.value->scalars, (std::vector<double>{10, 20, 30, 40}));
    EXPECT_EQ(grid.value->cell_types, std::vector<CellType>{CellType::tetrahedron});

    // A named array of several components gives its first.
    const Result<RawGrid> velocity = readVtkLegacy(kFieldOnly, "velocity");
    ASSERT_TRUE(velocity) << velocity.error;
    EXPECT_EQ(velocity.value->scalars, (std::vector<double>{1, 4, 7, 10}));

    const Result<RawGrid> missing = readVtkLegacy(kFieldOnly, "TIME");
    EXPECT_EQ(missing.error, "no point array named 'TIME': the file has 'velocity', 'pressure'");
}

TEST(VtkLegacyReader, NoScalarsIsNotAnError) {
    const std::string text = kHexTetTriangle;
    const Result<RawGrid> grid = readVtkLegacy(text.substr(0, text.find("POINT_DATA")));
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_TRUE(grid.value->scalars.empty());
    EXPECT_EQ(grid.value->scalar_name, "");
    EXPECT_EQ(grid.value->cell_types.size(), 2u);

    const Result<RawGrid> named = readVtkLegacy(text.substr(0, text.find("POINT_DATA")), "t");
    EXPECT_EQ(named.error, "no point array named 't': the file has none");
}

TEST(VtkLegacyReader, SkipsEveryOtherAttributeInBinary) {
    BinaryFile file = hexTetTriangleBinary();
    file.line("CELL_DATA 3").line("SCALARS material int 2").line("LOOKUP_TABLE default");
    file.values<int32_t>({1, 2, 3, 4, 5, 6});
    file.line("VECTORS flow float").values<float>({1, 2, 3, 4, 5, 6, 7, 8, 9});
    file.line("FIELD FieldData 2").line("labels 1 3 string");
    // Strings with 1-byte length headers (top bits 11): "ab", "", "xyz".
    file.bytes += "\xC2"
                  "ab\xC0\xC3xyz\n";
    file.line("flags 1 3 bit").values<uint8_t>({0xA0});
    file.line("POINT_DATA 9").line("NORMALS n float");
    file.values<float>(
        {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    file.line("TEXTURE_COORDINATES uv 2 double");
    file.values<double>({0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5});
    file.line("TENSORS6 stress float");
    file.values<float>({1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6,
                        1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6,
                        1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6});
    file.line("COLOR_SCALARS rgb 3");
    file.values<uint8_t>(
        {1, 2, 3, 4, 5, 6, 7, 8, 9, 1, 2, 3, 4, 5, 6, 7, 8, 9, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    file.line("LOOKUP_TABLE colours 2").values<uint8_t>({255, 0, 0, 255, 0, 255, 0, 255});
    file.line("GLOBAL_IDS ids vtkIdType").values<int32_t>({0, 1, 2, 3, 4, 5, 6, 7, 8});
    file.line("METADATA").line("INFORMATION 0").line("");
    file.line("SCALARS temperature double").line("LOOKUP_TABLE default");
    file.values<double>({0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4});
    const Result<RawGrid> grid = readVtkLegacy(file.bytes);
    ASSERT_TRUE(grid) << grid.error;
    expectHexTetTriangle(*grid.value);
}

TEST(VtkLegacyReader, SkipsEveryOtherAttributeInAscii) {
    std::string text = kHexTetTriangle;
    text.insert(text.find("POINT_DATA"), R"(CELL_DATA 3
COLOR_SCALARS rgba 4
1 0 0 1  0 1 0 1  0 0 1 1
LOOKUP_TABLE table 1
0.5 0.5 0.5 1
TENSORS t double
1 0 0 0 1 0 0 0 1  1 0 0 0 1 0 0 0 1  1 0 0 0 1 0 0 0 1
PEDIGREE_IDS p vtkIdType
7 8 9
)");
    text += "VECTORS v float\n";
    for (int i = 0; i < 9; ++i)
        text += "nan inf -inf\n"; // not finite, but skipped
    text += "METADATA\nCOMPONENT_NAMES\n\nvy\nvz\n\nEDGE_FLAGS e unsigned_char\n";
    text += "1 1 1 1 1 1 1 1 1\n";
    const Result<RawGrid> grid = readVtkLegacy(text);
    ASSERT_TRUE(grid) << grid.error;
    expectHexTetTriangle(*grid.value);
}

TEST(VtkLegacyReader, VoxelBecomesHexahedron) {
    const Result<RawGrid> grid = readVtkLegacy(R"(# vtk DataFile Version 4.2
voxel
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 8 float
0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1
CELLS 1 9
8 0 1 2 3 4 5 6 7
CELL_TYPES 1
11
)");
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->cell_types, std::vector<CellType>{CellType::hexahedron});
    EXPECT_EQ(grid.value->cell_points, (std::vector<uint32_t>{0, 1, 3, 2, 4, 5, 7, 6}));
}

/// kHexTetTriangle with its text from `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
    std::string text = kHexTetTriangle;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

std::string legacyError(const std::string& bytes, const std::string& scalar_name = {}) {
    const Result<RawGrid> grid = readVtkLegacy(bytes, scalar_name);
    EXPECT_FALSE(grid);
    return grid.error;
}

TEST(VtkLegacyReader, RefusesOtherFilesAndDatasets) {
    EXPECT_EQ(legacyError(edited("UNSTRUCTURED_GRID", "POLYDATA")),
              "line 4: DATASET POLYDATA: vissort reads UNSTRUCTURED_GRID");
    EXPECT_EQ(legacyError("ply\nformat ascii 1.0\n"),
              "line 1: not a legacy VTK file: it should start with '# vtk DataFile Version'");
    EXPECT_EQ(legacyError(""),
              "line 1: not a legacy VTK file: it should start with '# vtk DataFile Version'");
    EXPECT_EQ(legacyError(edited("ASCII", "TEXT")),
              "line 3: expected ASCII or BINARY, found 'TEXT'");
    EXPECT_EQ(legacyError(edited("CELL_TYPES 3", "CELL_KINDS 3")),
              "line 13: unknown section 'CELL_KINDS'");
    EXPECT_EQ(legacyError(edited("SCALARS", "SCALARZ")),
              "line 18: unknown section 'SCALARZ' in POINT_DATA");
}

TEST(VtkLegacyReader, MessagesQuoteTheFileShortAndOnOneLine) {
    EXPECT_EQ(legacyError(edited("CELL_TYPES 3", std::string(50, 'Z') + "\x01 3")),
              "line 13: unknown section '" + std::string(40, 'Z') + "...'");
    // A name's %0A is a line break.
    EXPECT_EQ(legacyError(edited("SCALARS temperature", "SCALARS temp%0Aerature"), "t"),
              "no point array named 't': the file has 'temp?erature'");
}

TEST(VtkLegacyReader, RefusesCellsItDoesNotRead) {
    EXPECT_EQ(legacyError(edited("10\n5", "24\n5")),
              "cell 1 has VTK type 24 (quadratic tetrahedron), which vissort does not read: only "
              "linear tetrahedra, hexahedra, wedges, pyramids and voxels");
    EXPECT_EQ(legacyError(edited("12\n10", "42\n10")),
              "cell 0 has VTK type 42 (polyhedron), which vissort does not read: only linear "
              "tetrahedra, hexahedra, wedges, pyramids and voxels");
    EXPECT_EQ(legacyError(edited("12\n10", "15\n10")).substr(0, 38),
              "cell 0 has VTK type 15 (pentagonal pri");
    EXPECT_EQ(legacyError(edited("12\n10", "13\n10")),
              "cell 0 (VTK type 13, wedge) has 8 corners instead of 6");
}

TEST(VtkLegacyReader, RefusesIndicesOutOfRange) {
    EXPECT_EQ(legacyError(edited("4 4 5 6 8", "4 4 5 6 9")),
              "cell 1 refers to point 9, but the points are numbered 0 to 8");
    EXPECT_EQ(legacyError(edited("3 0 1 2", "3 0 -1 2")),
              "cell 2 refers to point -1, but the points are numbered 0 to 8");
}

TEST(VtkLegacyReader, RefusesNonFiniteValues) {
    EXPECT_EQ(legacyError(edited("1 1 0  0 1 0", "1 1 0  0 nan 0")),
              "point 3 has a coordinate that is not finite");
    EXPECT_EQ(legacyError(edited("1 1 0  0 1 0", "1 1 0  0 1e999 0")),
              "point 3 has a coordinate that is not finite");
    EXPECT_EQ(legacyError(edited("3.5 4", "inf 4")),
              "the scalar 'temperature' of point 7 is not finite");
}

TEST(VtkLegacyReader, RefusesWrongCounts) {
    EXPECT_EQ(legacyError(edited("POINT_DATA 9", "POINT_DATA 8")),
              "line 17: POINT_DATA has 8 values, but POINTS has 9");
    EXPECT_EQ(legacyError(edited("CELL_TYPES 3\n12\n10\n5", "CELL_TYPES 2\n12\n10")),
              "CELL_TYPES has 2 cells, but CELLS has 3");
    EXPECT_EQ(legacyError(edited("CELLS 3 18", "CELLS 2 18")),
              "line 9: CELLS declares 18 numbers, but its 2 cells use 14");
    EXPECT_EQ(legacyError(edited("3 0 1 2", "5 0 1 2")),
              "line 9: CELLS: cell 2 has 5 corners, more than the numbers left");
    // A count too large takes the next section's keyword for a number.
    EXPECT_EQ(legacyError(edited("CELLS 3 18", "CELLS 3 19")),
              "line 13: CELLS value 'CELL_TYPES' is not an integer");
    EXPECT_EQ(legacyError(edited("POINTS 9", "POINTS -9")), "line 5: POINTS: '-9' is not a count");
    EXPECT_EQ(legacyError(edited("0.5 0.5 2\n", "0.5 0.5\n")),
              "line 9: POINTS value 'CELLS' is not a number");
    EXPECT_EQ(legacyError(edited("3.5 4\n", "3.5\n")),
              "line 21: SCALARS 'temperature': the file ends after 8 of 9 values");
    EXPECT_EQ(legacyError(edited("POINTS 9 float", "POINTS 9 quad")),
              "line 5: POINTS has the unknown data type 'quad'");
    EXPECT_EQ(legacyError(edited("CELLS 3 18\n8 0", "CELLS 3 18\n8 zero")),
              "line 10: CELLS value 'zero' is not an integer");
    std::string text = kHexTetTriangle;
    EXPECT_EQ(legacyError(text.substr(0, text.find("CELLS"))), "the file has no CELLS");
    EXPECT_EQ(legacyError(text.substr(0, text.find("CELL_TYPES"))), "the file has no CELL_TYPES");
}

TEST(VtkLegacyReader, RefusesInconsistentOffsets) {
    const std::string header = "# vtk DataFile Version 5.1\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                               "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n";
    EXPECT_EQ(legacyError(header + "CELLS 2 4\nOFFSETS vtktypeint64\n0 5\n"
                                   "CONNECTIVITY vtktypeint64\n0 1 2 3\nCELL_TYPES 1\n10\n"),
              "line 8: OFFSETS end at 5, but CELLS declares 4 CONNECTIVITY values");
    EXPECT_EQ(legacyError(header + "CELLS 3 4\nOFFSETS vtktypeint64\n0 4 2\n"
                                   "CONNECTIVITY vtktypeint64\n0 1 2 3\nCELL_TYPES 2\n10 10\n"),
              "line 8: OFFSETS decrease at cell 1");
    EXPECT_EQ(legacyError(header + "CELLS 2 4\nOFFSETS float\n0 4\n"),
              "line 8: OFFSETS need an integer data type");
}

TEST(VtkLegacyReader, RefusesHugeCountsBeforeAllocating) {
    // A 200-byte file declaring billions of values fails on the count, allocating nothing.
    EXPECT_EQ(legacyError(edited("POINTS 9 float", "POINTS 4000000000 float")),
              "line 5: POINTS declares 4000000000 points, more than vissort's limit of 67108864");
    EXPECT_EQ(legacyError(edited("POINTS 9 float", "POINTS 60000000 float")),
              "line 5: POINTS declares 180000000 values, more than the 221 bytes left can hold");
    EXPECT_EQ(legacyError(edited("CELLS 3 18", "CELLS 3 9000000000000000000")),
              "line 9: CELLS declares 9000000000000000000 values, more than the 146 bytes left "
              "can hold");
    EXPECT_EQ(legacyError(edited("CELL_TYPES 3", "CELL_TYPES 50000000")),
              "line 13: CELL_TYPES declares 50000000 values, more than the 97 bytes left can "
              "hold");
    EXPECT_EQ(legacyError(edited("SCALARS temperature float 1",
                                 "SCALARS temperature float 4611686018427387904")),
              "line 18: SCALARS 'temperature' declares 9 tuples of 4611686018427387904 "
              "components, more than any file holds");

    BinaryFile file;
    file.line("# vtk DataFile Version 3.0").line("x").line("BINARY");
    file.line("DATASET UNSTRUCTURED_GRID").line("POINTS 50000000 double").values<double>({0, 1});
    EXPECT_EQ(legacyError(file.bytes),
              "byte 62: POINTS declares 150000000 values, more than the 17 bytes left can hold");
    BinaryFile strings = hexTetTriangleBinary();
    strings.line("CELL_DATA 3").line("FIELD f 1").line("s 1 4000000000 string");
    strings.bytes += "\xC0"; // an empty string, then the end
    EXPECT_EQ(legacyError(strings.bytes),
              "byte " + std::to_string(strings.bytes.find("s 1 4000000000")) +
                  ": FIELD array 's': the file ends after 1 of 4000000000 strings");
}

TEST(VtkLegacyReader, RefusesTruncatedBinary) {
    BinaryFile file = hexTetTriangleBinary();
    const std::size_t cells = file.bytes.find("CELLS");
    // Cut inside the points: 9 * 3 floats need 108 bytes.
    EXPECT_EQ(legacyError(file.bytes.substr(0, cells - 50)),
              "byte 72: POINTS declares 27 values, more than the 59 bytes left can hold");
    // Cut inside the cell types.
    EXPECT_EQ(legacyError(file.bytes.substr(0, file.bytes.size() - 3)),
              "byte " + std::to_string(file.bytes.find("CELL_TYPES")) +
                  ": CELL_TYPES declares 3 values, more than the 10 bytes left can hold");
}

} // namespace
} // namespace vissort::detail
