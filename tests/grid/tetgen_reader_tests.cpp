// Tests of src/grid/tetgen_reader.cpp: hand-written .node/.ele pairs checked value by value
// (numbered from 0 and from 1, attributes, markers, comments, 10-node tetrahedra), a real tetgen
// output checked against the cube it fills, and every class of broken or hostile file.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "grid/raw_grid.h"
#include "grid/token_scanner.h"
#include "reader_test_support.h"

namespace vissort::detail {
namespace {

// The error of reading the pair, which must fail.
std::string errorOf(const std::string& node, const std::string& ele) {
    const Result<RawGrid> grid = readTetgen(node, ele);
    EXPECT_FALSE(grid) << "read although broken:\n" << node << "\n--\n" << ele;
    EXPECT_EQ(grid.error.find('\n'), std::string::npos) << grid.error;
    return grid.error;
}

const std::string kNode = "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";
const std::string kEle = "1 4 0\n0 0 1 2 3\n";

TEST(TetgenReader, ReadsPointsNumberedFromZeroWithAttributesMarkersAndComments) {
    const Result<RawGrid> grid = readTetgen(test::readGridData("tetgen_two_tets.node"),
                                            test::readGridData("tetgen_two_tets.ele"));
    ASSERT_TRUE(grid) << grid.error;
    const std::vector<Vec3> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    ASSERT_EQ(grid.value->points.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        EXPECT_EQ(grid.value->points[i], points[i]);
    // The first of the two attributes; 1.45e1 as written.
    EXPECT_EQ(grid.value->scalars, (std::vector<double>{10.5, 11.5, 12.5, 13.5, 14.5}));
    EXPECT_EQ(grid.value->scalar_name, "attribute 0");
    EXPECT_EQ(grid.value->cell_types,
              (std::vector<CellType>{CellType::tetrahedron, CellType::tetrahedron}));
    EXPECT_EQ(grid.value->cell_offsets, (std::vector<uint64_t>{0, 4, 8}));
    EXPECT_EQ(test::cornersOf(*grid.value, 0), (std::vector<uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(test::cornersOf(*grid.value, 1), (std::vector<uint32_t>{1, 2, 3, 4}));
    EXPECT_EQ(grid.value->skipped_cells, 0u);
}

TEST(TetgenReader, ReadsPointsNumberedFromOneAndQuadraticTetrahedraByTheirCorners) {
    const Result<RawGrid> grid = readTetgen(test::readGridData("tetgen_quadratic.node"),
                                            test::readGridData("tetgen_quadratic.ele"));
    ASSERT_TRUE(grid) << grid.error;
    ASSERT_EQ(grid.value->points.size(), 10u);
    EXPECT_EQ(grid.value->points[1], (Vec3{2, 0, 0}));
    EXPECT_EQ(grid.value->points[9], (Vec3{0, 1, 1}));
    EXPECT_TRUE(grid.value->scalars.empty()); // no attribute: no scalar, not an error
    EXPECT_TRUE(grid.value->scalar_name.empty());
    ASSERT_EQ(grid.value->cell_types.size(), 1u);
    EXPECT_EQ(test::cornersOf(*grid.value, 0), (std::vector<uint32_t>{0, 1, 2, 3}));
}

TEST(TetgenReader, NumbersFromOneGiveTheSameGridAsFromZero) {
    const Result<RawGrid> zero = readTetgen(kNode, kEle);
    const Result<RawGrid> one =
        readTetgen("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "1 4 0\n1 1 2 3 4\n");
    ASSERT_TRUE(zero) << zero.error;
    ASSERT_TRUE(one) << one.error;
    EXPECT_EQ(zero.value->cell_points, (std::vector<uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(one.value->cell_points, zero.value->cell_points);
    EXPECT_EQ(one.value->points[3], (Vec3{0, 0, 1}));
}

TEST(TetgenReader, AcceptsCommentsBlankLinesAndCarriageReturnsAnywhere) {
    const Result<RawGrid> grid =
        readTetgen("# points\r\n\r\n4 3 1 0 # header\r\n0 0 0 0 5#c\r\n1 1 0 0 6\r\n"
                   "# between\r\n2 0 1 0 7\r\n3 0 0 1 8\r\n# end\r\n",
                   "\n1 4 0 #\n0 0 1 2 3 # tet\n");
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->scalars, (std::vector<double>{5, 6, 7, 8}));
}

// tetgen 1.5's own output (tests/data/grids/README.md says the command): the tetrahedra fill the
// unit cube exactly, and the attribute is kept at the 8 input corners (x + 2y + 3z there) while
// tetgen gives the points it adds attribute 0.
TEST(TetgenReader, ReadsTetgenOutputThatFillsTheUnitCube) {
    const Result<RawGrid> grid = readTetgen(test::readGridData("tetgen_cube.1.node"),
                                            test::readGridData("tetgen_cube.1.ele"));
    ASSERT_TRUE(grid) << grid.error;
    const RawGrid& cube = *grid.value;
    ASSERT_EQ(cube.points.size(), 65u);
    ASSERT_EQ(cube.cell_types.size(), 130u);
    ASSERT_EQ(cube.scalars.size(), 65u);
    for (std::size_t i = 0; i < cube.points.size(); ++i) {
        const Vec3& p = cube.points[i];
        for (const double c : {p.x, p.y, p.z}) {
            EXPECT_GE(c, 0.0);
            EXPECT_LE(c, 1.0);
        }
        EXPECT_EQ(cube.scalars[i], i < 8 ? p.x + 2 * p.y + 3 * p.z : 0.0) << "point " << i;
    }
    double volume = 0;
    int positive = 0;
    for (std::size_t t = 0; t < cube.cell_types.size(); ++t) {
        const std::vector<uint32_t> c = test::cornersOf(cube, t);
        const Vec3 a = cube.points[c[0]];
        const double six_volume =
            dot(cross(cube.points[c[1]] - a, cube.points[c[2]] - a), cube.points[c[3]] - a);
        EXPECT_NE(six_volume, 0.0) << "tetrahedron " << t;
        positive += six_volume > 0;
        volume += std::abs(six_volume) / 6;
    }
    EXPECT_NEAR(volume, 1.0, 1e-12);
    // tetgen lists every tetrahedron positively oriented as vissort::Tet is: p3 on the side of
    // (p0, p1, p2) where (p1 - p0) x (p2 - p0) points.
    EXPECT_EQ(positive, 130);
}

TEST(TetgenReader, RefusesBrokenNodeHeaders) {
    EXPECT_EQ(errorOf("", kEle), ".node is empty");
    EXPECT_EQ(errorOf("# only a comment\n\n", kEle), ".node is empty");
    EXPECT_EQ(errorOf("4\n", kEle), ".node line 1: the header has 1 value, expected <#points> "
                                    "<dimension> [<#attributes> [<boundary markers>]]");
    EXPECT_NE(errorOf("4 3 0 0 9\n", kEle).find("the header has 5 values"), std::string::npos);
    EXPECT_NE(errorOf("-4 3 0 0\n", kEle).find("header value '-4' is not a count"),
              std::string::npos);
    EXPECT_EQ(errorOf("4 2 0 0\n0 0 0\n", kEle),
              ".node line 1: dimension 2, only 3D points are read");
    EXPECT_EQ(errorOf("4 3 0 2\n", kEle), ".node line 1: boundary markers 2, expected 0 or 1");
}

TEST(TetgenReader, RefusesPointRecordsWithMissingOrExtraValues) {
    EXPECT_EQ(errorOf("2 3 0 0\n0 0 0\n1 1 0 0\n", kEle),
              ".node line 2: point 0 has 3 values, expected 4 (index, x, y, z, 0 attributes)");
    EXPECT_EQ(errorOf("2 3 1 1\n0 0 0 0 1 1\n1 1 0 0 1\n", kEle),
              ".node line 3: point 1 has 5 values, expected 6 (index, x, y, z, 1 attribute, "
              "marker)");
    EXPECT_EQ(errorOf("2 3 0 0\n0 0 0 0 7\n1 1 0 0\n", kEle),
              ".node line 2: point 0 has 5 values, expected 4 (index, x, y, z, 0 attributes)");
    // A record split over two lines is two broken records, not one.
    EXPECT_NE(errorOf("1 3 0 0\n0 0 0\n0\n", kEle).find(".node line 2: point 0 has 3 values"),
              std::string::npos);
}

TEST(TetgenReader, RefusesBadPointNumbering) {
    EXPECT_EQ(errorOf("2 3 0 0\n2 0 0 0\n3 1 0 0\n", kEle),
              ".node line 2: the first point is numbered 2 (tetgen numbers from 0 or 1)");
    EXPECT_EQ(errorOf("3 3 0 0\n1 0 0 0\n2 1 0 0\n4 0 1 0\n", kEle),
              ".node line 4: point 4 follows point 2 (the numbering must be consecutive)");
    EXPECT_EQ(errorOf("2 3 0 0\n0 0 0 0\nx 1 0 0\n", kEle),
              ".node line 3: point index 'x' is not an integer");
}

TEST(TetgenReader, RefusesNonFiniteOrNonNumericValues) {
    EXPECT_EQ(errorOf("2 3 0 0\n0 0 0 0\n1 nan 0 0\n", kEle),
              ".node line 3: point 1: coordinate 'nan' is not finite");
    EXPECT_EQ(errorOf("2 3 0 0\n0 0 0 0\n1 0 -inf 0\n", kEle),
              ".node line 3: point 1: coordinate '-inf' is not finite");
    EXPECT_EQ(errorOf("2 3 0 0\n0 0 0 0\n1 0 0 1e999\n", kEle),
              ".node line 3: point 1: coordinate '1e999' is out of range");
    EXPECT_EQ(errorOf("2 3 0 0\n0 0 0 0\n1 0 0 1,5\n", kEle),
              ".node line 3: point 1: coordinate '1,5' is not a number");
    EXPECT_EQ(errorOf("1 3 1 0\n0 0 0 0 inf\n", kEle),
              ".node line 2: point 0: attribute 'inf' is not finite");
    EXPECT_EQ(errorOf("1 3 0 1\n0 0 0 0 1.5\n", kEle),
              ".node line 2: point 0: boundary marker '1.5' is not an integer");
    EXPECT_EQ(errorOf(kNode, "1 4 1\n0 0 1 2 3 nan\n"),
              ".ele line 2: tetrahedron 0: attribute 'nan' is not finite");
}

// The first n lines of a text.
std::string firstLines(const std::string& text, int n) {
    std::size_t end = 0;
    for (int i = 0; i < n; ++i)
        end = text.find('\n', end) + 1;
    return text.substr(0, end);
}

TEST(TetgenReader, RefusesTruncatedFilesAndTrailingGarbage) {
    // The real output cut after 40 of its 65 points, then in the middle of a tetrahedron's line
    // (a short file is refused earlier, by its count: RefusesHostileCountsBeforeAllocating).
    const std::string node = test::readGridData("tetgen_cube.1.node");
    const std::string ele = test::readGridData("tetgen_cube.1.ele");
    EXPECT_EQ(errorOf(firstLines(node, 41), ele),
              ".node line 42: the file ends after 40 of 65 points declared");
    const std::string cut_ele = firstLines(ele, 101) + "  101      12    24";
    EXPECT_EQ(errorOf(node, cut_ele),
              ".ele line 102: tetrahedron 101 has 3 values, expected 5 (index, 4 nodes, 0 "
              "attributes)");
    EXPECT_EQ(errorOf(node, firstLines(ele, 101)),
              ".ele line 102: the file ends after 100 of 130 tetrahedra declared");
    EXPECT_EQ(errorOf(kNode + "4 1 1 1\n", kEle),
              ".node line 6: unexpected '4' after the 4 points");
    EXPECT_EQ(errorOf(kNode, kEle + "end\n"),
              ".ele line 3: unexpected 'end' after the 1 tetrahedron");
    EXPECT_EQ(errorOf(kNode, ""), ".ele is empty");
}

TEST(TetgenReader, RefusesBadTetrahedra) {
    EXPECT_EQ(errorOf(kNode, "1 6 0\n0 0 1 2 3 0 1\n"),
              ".ele line 1: 6 nodes per tetrahedron, expected 4 or 10");
    EXPECT_EQ(errorOf(kNode, "1 4 0\n0 0 1 2 4\n"),
              ".ele line 2: tetrahedron 0: node 4 is not one of the 4 points numbered from 0");
    EXPECT_EQ(errorOf(kNode, "1 4 0\n0 0 1 2 -1\n"),
              ".ele line 2: tetrahedron 0: node -1 is not one of the 4 points numbered from 0");
    EXPECT_EQ(errorOf("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "1 4 0\n1 0 1 2 3\n"),
              ".ele line 2: tetrahedron 1: node 0 is not one of the 4 points numbered from 1");
    EXPECT_EQ(errorOf(kNode, "1 4 0\n0 0 1 2\n"),
              ".ele line 2: tetrahedron 0 has 4 values, expected 5 (index, 4 nodes, 0 attributes)");
    EXPECT_EQ(errorOf(kNode, "1 4 0\n0 0 1 2 3 1\n"),
              ".ele line 2: tetrahedron 0 has 6 values, expected 5 (index, 4 nodes, 0 attributes)");
    EXPECT_EQ(errorOf(kNode, "2 4 0\n0 0 1 2 3\n2 0 1 2 3\n"),
              ".ele line 3: tetrahedron 2 follows tetrahedron 0 (the numbering must be "
              "consecutive)");
    EXPECT_EQ(errorOf(kNode, "1 4 0\n0 0 1 2 3.0\n"),
              ".ele line 2: tetrahedron 0: node '3.0' is not an integer");
    // The quadratic nodes are checked as the corners are.
    EXPECT_NE(errorOf(kNode, "1 10 0\n0 0 1 2 3 0 1 2 3 0 9\n").find("node 9 is not one of"),
              std::string::npos);
}

// Bounded memory: a count is refused before anything is reserved for it, whether beyond the
// grid limit or beyond what the bytes can hold.
TEST(TetgenReader, RefusesHostileCountsBeforeAllocating) {
    EXPECT_EQ(errorOf("4000000000 3 0 0\n0 0 0 0\n", kEle),
              ".node line 1: 4000000000 points declared, beyond the limit of 67108864");
    EXPECT_EQ(errorOf("1000 3 0 0\n0 0 0 0\n", kEle),
              ".node line 1: 1000 points of 4 values declared, more than the rest of the file "
              "holds");
    // 2^62 attributes of each of 4 points overflow 64 bits if multiplied.
    EXPECT_NE(errorOf("4 3 4611686018427387904 0\n0 0 0 0\n", kEle)
                  .find("4 points of 4611686018427387908 values declared"),
              std::string::npos);
    EXPECT_EQ(errorOf(kNode, "9223372036854775807 4 0\n0 0 1 2 3\n"),
              ".ele line 1: 9223372036854775807 tetrahedra declared, beyond the limit of 67108864");
    EXPECT_EQ(errorOf(kNode, "500 4 0\n0 0 1 2 3\n"),
              ".ele line 1: 500 tetrahedra of 5 values declared, more than the rest of the file "
              "holds");
    EXPECT_NE(errorOf("99999999999999999999 3 0 0\n", kEle).find("is not a count"),
              std::string::npos);
}

TEST(TetgenReader, MessagesShowAtMost32CharactersOfAToken) {
    const std::string error = errorOf("1 3 0 0\n0 0 0 " + std::string(1000, 'z') + "\n", kEle);
    EXPECT_EQ(error, ".node line 2: point 0: coordinate '" + std::string(32, 'z') +
                         "...' is not a number");
}

} // namespace
// A '+' is read before digits, never before another sign: "+-5" is not -5.
TEST(TokenScanner, APlusSignOnlyBeforeDigits) {
    EXPECT_EQ(TokenScanner::parseInteger("+5"), 5);
    EXPECT_EQ(TokenScanner::parseDouble("+2.5"), 2.5);
    EXPECT_FALSE(TokenScanner::parseInteger("+-5"));
    EXPECT_FALSE(TokenScanner::parseDouble("+-1.5"));
    EXPECT_FALSE(TokenScanner::parseInteger("++5"));
    EXPECT_FALSE(TokenScanner::parseInteger("+"));
}

} // namespace vissort::detail
