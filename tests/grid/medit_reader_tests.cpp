// Tests of src/grid/medit_reader.cpp: a .mesh with every cell kind and skipped sections, checked
// value by value and for the corner orders VTK's cells have (by the corners' known coordinates),
// a .sol's scalar, and every class of broken or hostile file.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "grid/raw_grid.h"
#include "reader_test_support.h"

namespace vissort::detail {
namespace {

// The error of reading the mesh (and .sol), which must fail.
std::string errorOf(const std::string& mesh, const std::string* sol = nullptr) {
    const Result<RawGrid> grid = readMedit(mesh, sol);
    EXPECT_FALSE(grid) << "read although broken:\n" << mesh;
    EXPECT_EQ(grid.error.find('\n'), std::string::npos) << grid.error;
    return grid.error;
}
std::string solErrorOf(const std::string& mesh, const std::string& sol) {
    return errorOf(mesh, &sol);
}

const std::string kHead = "MeshVersionFormatted 2\nDimension 3\n";
const std::string kTet = kHead + "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                                 "Tetrahedra\n1\n1 2 3 4 0\nEnd\n";

TEST(MeditReader, ReadsEveryCellKindAndSkipsTheBoundarySections) {
    const Result<RawGrid> grid = readMedit(test::readGridData("medit_all_cells.mesh"));
    ASSERT_TRUE(grid) << grid.error;
    const RawGrid& mesh = *grid.value;
    ASSERT_EQ(mesh.points.size(), 12u);
    EXPECT_EQ(mesh.points[0], (Vec3{0, 0, 0}));
    EXPECT_EQ(mesh.points[6], (Vec3{1, 1, 1}));
    EXPECT_EQ(mesh.points[11], (Vec3{1.3, 0.3, 1.5}));
    EXPECT_EQ(mesh.cell_types, (std::vector<CellType>{CellType::hexahedron, CellType::wedge,
                                                      CellType::pyramid, CellType::tetrahedron}));
    EXPECT_EQ(mesh.cell_offsets, (std::vector<uint64_t>{0, 8, 14, 19, 23}));
    EXPECT_EQ(test::cornersOf(mesh, 0), (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(test::cornersOf(mesh, 1), (std::vector<uint32_t>{1, 8, 2, 5, 9, 6}));
    EXPECT_EQ(test::cornersOf(mesh, 2), (std::vector<uint32_t>{4, 5, 6, 7, 10}));
    EXPECT_EQ(test::cornersOf(mesh, 3), (std::vector<uint32_t>{5, 9, 6, 11}));
    // 2 triangles, 1 quadrilateral and 3 edges; Corners, Normals and the rest are not cells.
    EXPECT_EQ(mesh.skipped_cells, 6u);
    EXPECT_TRUE(mesh.scalars.empty());
    EXPECT_TRUE(mesh.scalar_name.empty());
}

bool joinedAlongZ(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z != b.z;
}
// Corners of a face are joined by an edge of the cell: here, each along one axis.
bool adjacent(const Vec3& a, const Vec3& b) {
    return (a.x != b.x) + (a.y != b.y) + (a.z != b.z) == 1;
}

// VTK's orders, raw_grid.h: the hexahedron's corner i + 4 joined to i, its faces 0-3 and 4-7
// quadrilaterals going round; the wedge's corner i + 3 joined to i; the pyramid's base a
// quadrilateral going round, then the apex. The test cells' faces lie in the planes z = 0 and
// z = 1, their joining edges along z.
TEST(MeditReader, GivesTheCornersInVtkOrder) {
    const Result<RawGrid> grid = readMedit(test::readGridData("medit_all_cells.mesh"));
    ASSERT_TRUE(grid) << grid.error;
    const std::vector<Vec3>& p = grid.value->points;
    const std::vector<uint32_t> hexahedron = test::cornersOf(*grid.value, 0);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(p[hexahedron[i]].z, 0.0) << i;
        EXPECT_EQ(p[hexahedron[i + 4]].z, 1.0) << i;
        EXPECT_TRUE(joinedAlongZ(p[hexahedron[i]], p[hexahedron[i + 4]])) << i;
        EXPECT_TRUE(adjacent(p[hexahedron[i]], p[hexahedron[(i + 1) % 4]])) << i;
        EXPECT_TRUE(adjacent(p[hexahedron[i + 4]], p[hexahedron[(i + 1) % 4 + 4]])) << i;
    }
    const std::vector<uint32_t> wedge = test::cornersOf(*grid.value, 1);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(p[wedge[i]].z, 0.0) << i;
        EXPECT_TRUE(joinedAlongZ(p[wedge[i]], p[wedge[i + 3]])) << i;
    }
    const std::vector<uint32_t> pyramid = test::cornersOf(*grid.value, 2);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(p[pyramid[i]].z, 1.0) << i;
        EXPECT_TRUE(adjacent(p[pyramid[i]], p[pyramid[(i + 1) % 4]])) << i;
    }
    EXPECT_EQ(p[pyramid[4]], (Vec3{0.5, 0.5, 1.5}));
}

TEST(MeditReader, ReadsTheFirstScalarFieldOfASol) {
    const std::string sol = test::readGridData("medit_all_cells.sol");
    const Result<RawGrid> grid = readMedit(test::readGridData("medit_all_cells.mesh"), &sol);
    ASSERT_TRUE(grid) << grid.error;
    ASSERT_EQ(grid.value->scalars.size(), 12u);
    EXPECT_EQ(grid.value->scalar_name, "SolAtVertices");
    // The scalar after the vector field, x + 2y + 3z + 0.5 at each vertex.
    for (std::size_t i = 0; i < 12; ++i) {
        const Vec3& p = grid.value->points[i];
        EXPECT_NEAR(grid.value->scalars[i], p.x + 2 * p.y + 3 * p.z + 0.5, 1e-12) << i;
    }
}

TEST(MeditReader, AcceptsAnyCaseCommentsAMissingEndAndCellsBeforeVertices) {
    const Result<RawGrid> grid =
        readMedit("# a comment\nmeshversionformatted 1\r\nDIMENSION\r\n3\r\n"
                  "TETRAHEDRA 1 # cells before the vertices\n1 2 3 4 7\n"
                  "hexaedra 0\n" // Medit's old spelling
                  "vertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1.5e0 0 # last\n");
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->points[3], (Vec3{0, 0, 1.5}));
    EXPECT_EQ(grid.value->cell_points, (std::vector<uint32_t>{0, 1, 2, 3}));
    const Result<RawGrid> version_4 = readMedit("MeshVersionFormatted 4\n" + kTet.substr(23));
    EXPECT_TRUE(version_4) << version_4.error;
}

TEST(MeditReader, RefusesBinaryFiles) {
    EXPECT_EQ(errorOf(std::string("\1\0\0\0\2\0\0\0", 8)),
              "binary .meshb is not read: write ASCII .mesh");
    EXPECT_EQ(errorOf(std::string("\0\0\0\1\0\0\0\2", 8)),
              "binary .meshb is not read: write ASCII .mesh");
    EXPECT_EQ(solErrorOf(kTet, std::string("\1\0\0\0\2\0\0\0", 8)),
              "binary .solb is not read: write ASCII .sol");
}

TEST(MeditReader, RefusesBrokenHeaders) {
    EXPECT_EQ(errorOf(""), "no Vertices section");
    EXPECT_EQ(errorOf("Dimension 3\n"),
              "line 1: 'Dimension' where MeshVersionFormatted should start a Medit .mesh");
    EXPECT_EQ(errorOf("MeshVersionFormatted 5\n"),
              "line 1 (MeshVersionFormatted): version '5', expected 1, 2, 3 or 4");
    EXPECT_EQ(errorOf("MeshVersionFormatted 2\nDimension 2\n"),
              "line 2 (Dimension): dimension '2', only 3D meshes are read");
    EXPECT_EQ(errorOf("MeshVersionFormatted 2\nDimension\n\n"),
              "line 4 (Dimension): the file ends before the dimension");
    EXPECT_EQ(errorOf("MeshVersionFormatted"),
              "line 1 (MeshVersionFormatted): the file ends before the version");
    EXPECT_EQ(errorOf("MeshVersionFormatted 2\nVertices 0\n"),
              "line 2 (Vertices): the section comes before Dimension");
    EXPECT_EQ(errorOf(kHead + "Dimension 3\n"), "line 3 (Dimension): a second Dimension");
}

TEST(MeditReader, RefusesUnknownAndHighOrderKeywordsNamingThem) {
    EXPECT_EQ(errorOf(kHead + "Vertices 0\n\nPolyhedra 0\n"),
              "line 5: unknown keyword 'Polyhedra'");
    EXPECT_EQ(errorOf(kHead + "Vertices 0\nTetrahedraP2 0\n"),
              "line 4: 'TetrahedraP2': high-order cells are not read");
    // A section with more records than its count leaves a number where a keyword should be.
    EXPECT_EQ(errorOf(kHead + "Vertices 1\n0 0 0 0\n1 1 1 0\n"),
              "line 5: number '1' where a keyword is expected (more records than a section's "
              "count?)");
    EXPECT_EQ(errorOf(kHead + "Vertices 0\nVertices 0\n"),
              "line 4 (Vertices): a second Vertices section");
}

TEST(MeditReader, RefusesBadVertices) {
    EXPECT_EQ(errorOf(kHead + "Vertices 2\n0 0 0 0\n0 nan 0 0\n"),
              "line 5 (Vertices): vertex 2: coordinate 'nan' is not finite");
    EXPECT_EQ(errorOf(kHead + "Vertices 2\n0 0 0 0\n0 0 inf 0\n"),
              "line 5 (Vertices): vertex 2: coordinate 'inf' is not finite");
    EXPECT_EQ(errorOf(kHead + "Vertices 1\n0 0 x 0\n"),
              "line 4 (Vertices): vertex 1: coordinate 'x' is not a number");
    EXPECT_EQ(errorOf(kHead + "Vertices 1\n0 0 0 0.5\n"),
              "line 4 (Vertices): vertex 1: reference '0.5' is not an integer");
    EXPECT_EQ(errorOf(kHead + "Vertices -1\n"),
              "line 3 (Vertices): the count '-1' is not a non-negative integer");
}

TEST(MeditReader, RefusesCellsWithBadVertexIndices) {
    const std::string vertices = kHead + "Vertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
    EXPECT_EQ(errorOf(vertices + "Tetrahedra 1\n1 2 3 0 0\n"),
              "line 9 (Tetrahedra): tetrahedron 1: vertex index 0 is not one of the 4 vertices "
              "(numbered from 1)");
    EXPECT_EQ(errorOf(vertices + "Pyramids 1\n1 2 3 4 5 0\n"),
              "line 9 (Pyramids): pyramid 1: vertex index 5 is not one of the 4 vertices "
              "(numbered from 1)");
    EXPECT_EQ(errorOf(vertices + "Prisms 1\n1 2 3 4 -1 2 0\n"),
              "line 9 (Prisms): prism 1: vertex index -1 is not one of the 4 vertices (numbered "
              "from 1)");
    EXPECT_EQ(errorOf(vertices + "Hexahedra 1\n1 2 3 4 1 2 3 4.0 0\n"),
              "line 9 (Hexahedra): hexahedron 1: vertex index '4.0' is not an integer");
    EXPECT_EQ(errorOf(vertices + "Tetrahedra 1\n1 2 3 4 r\n"),
              "line 9 (Tetrahedra): tetrahedron 1: reference 'r' is not an integer");
    // Checked once the vertices are read when the cells come first.
    EXPECT_EQ(errorOf(kHead + "Tetrahedra 1\n1 2 3 9 0\nVertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
                              "0 0 1 0\n"),
              "a cell refers to vertex 9, beyond the 4 vertices");
    EXPECT_EQ(errorOf(vertices + "Triangles 1\n1 2 x 0\n"),
              "line 9 (Triangles): triangle 1: 'x' is not a number");
}

TEST(MeditReader, RefusesTruncatedFiles) {
    // Numbers written long, as writers do, so that the count fits the bytes left (a short file is
    // refused earlier, by its count: RefusesHostileCountsBeforeAllocating).
    const std::string zero = "0.0000000000000000e+00 ";
    const std::string vertex = zero + zero + zero + "1\n";
    EXPECT_EQ(errorOf(kHead + "Vertices 4\n" + vertex + vertex + vertex),
              "line 7 (Vertices): the file ends in vertex 4 of 4");
    EXPECT_EQ(errorOf(kHead + "Vertices 4\n" + vertex + vertex + vertex + zero + zero),
              "line 7 (Vertices): the file ends in vertex 4 of 4");
    EXPECT_EQ(errorOf(kHead + "Vertices 4\n" + vertex + vertex + vertex + vertex +
                      "Tetrahedra 2\n1 2 3 4 0 # the second tetrahedron is missing\n"),
              "line 10 (Tetrahedra): the file ends in tetrahedron 2 of 2");
    EXPECT_EQ(errorOf(kHead + "Vertices"), "line 3 (Vertices): the file ends before the count");
    EXPECT_EQ(errorOf(kHead + "Vertices 0\nCorners 2\n1 "),
              "line 5 (Corners): the file ends in record 2 of 2");
}

// Bounded memory: a count is refused before anything is reserved for it, whether beyond the
// grid limit or beyond what the bytes can hold.
TEST(MeditReader, RefusesHostileCountsBeforeAllocating) {
    EXPECT_EQ(errorOf(kHead + "Vertices\n4000000000\n0 0 0 0\n"),
              "line 4 (Vertices): 4000000000 vertices declared, beyond the limit of 67108864 "
              "vertices in a grid");
    const std::string error = errorOf(kHead + "Vertices\n1000\n0 0 0 0\n");
    EXPECT_EQ(error.find("line 4 (Vertices): 1000 vertices declared, more than the rest of the "
                         "file can hold"),
              0u)
        << error;
    EXPECT_NE(errorOf(kHead + "Vertices 0\nTetrahedra 67108865\n")
                  .find("67108865 cells declared, "
                        "beyond the limit"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "Vertices 0\nTriangles 9223372036854775807\n")
                  .find("9223372036854775807 records declared, more than the rest"),
              std::string::npos);
    EXPECT_NE(errorOf(kHead + "Vertices 0\nEdges 99999999999999999999\n")
                  .find("the count '99999999999999999999' is not a non-negative integer"),
              std::string::npos);
}

TEST(MeditReader, RefusesBrokenSols) {
    const std::string sol_head = "MeshVersionFormatted 2\nDimension 3\n";
    EXPECT_EQ(solErrorOf(kTet, sol_head + "SolAtVertices 3\n1 1\n0 1 2\n"),
              ".sol line 3 (SolAtVertices): 3 values for the mesh's 4 vertices");
    EXPECT_EQ(solErrorOf(kTet, sol_head + "SolAtVertices 4\n1 2\n0 0 0 1 1 1 2 2 2 3 3 3\n"),
              ".sol line 3 (SolAtVertices): no scalar field (type 1) among the 1 fields");
    EXPECT_EQ(solErrorOf(kTet, sol_head + "SolAtVertices 4\n1 7\n0 1 2 3\n"),
              ".sol line 4 (SolAtVertices): field type '7', expected 1 (scalar), 2 (vector), 3 "
              "or 4 (matrix)");
    EXPECT_EQ(solErrorOf(kTet, sol_head + "SolAtVertices 4\n1 1\n0 1 nan 3\n"),
              ".sol line 5 (SolAtVertices): record 3: 'nan' is not finite");
    EXPECT_EQ(solErrorOf(kTet, sol_head + "SolAtVertices 4\n1 1\n0 1 2\n"),
              ".sol line 6 (SolAtVertices): the file ends in record 4 of 4");
    EXPECT_EQ(solErrorOf(kTet, sol_head + "End\n"), ".sol has no SolAtVertices section");
    EXPECT_EQ(solErrorOf(kTet, "SolAtVertices 4\n1 1\n0 1 2 3\n"),
              ".sol line 1: 'SolAtVertices' where MeshVersionFormatted and Dimension should start "
              "a Medit .sol");
    EXPECT_EQ(solErrorOf(kTet, "MeshVersionFormatted 2\nDimension 2\n"),
              ".sol line 2 (Dimension): dimension '2', only 3D solutions are read");
    EXPECT_EQ(solErrorOf(kTet, sol_head + "SolAtVertices 4000000000\n1 1\n0\n"),
              ".sol line 3 (SolAtVertices): 4000000000 records declared, more than the 2 values "
              "the rest of the file can hold");
    EXPECT_EQ(solErrorOf(kTet, sol_head + "Solution 4\n"),
              ".sol line 3: unknown keyword 'Solution'");
    // Other sections and Time are skipped; the scalar is the first of type 1.
    const std::string sol = sol_head +
                            "Time 0.5\nSolAtTetrahedra 1\n1 2\n7 7 7\n"
                            "SolAtVertices 4\n3 3 1 1\n" +
                            "0 0 0 0 0 0 10 20\n0 0 0 0 0 0 11 21\n0 0 0 0 0 0 12 22\n"
                            "0 0 0 0 0 0 13 23\nEnd\n";
    const Result<RawGrid> grid = readMedit(kTet, &sol);
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->scalars, (std::vector<double>{10, 11, 12, 13}));
}

TEST(MeditReader, MessagesShowAtMost32CharactersOfAToken) {
    EXPECT_EQ(errorOf(kHead + std::string(100, 'K') + "\n"),
              "line 3: unknown keyword '" + std::string(32, 'K') + "...'");
    EXPECT_EQ(errorOf(kHead + "V\x01rtices 0\n"), "line 3: unknown keyword 'V?rtices'");
}

} // namespace
} // namespace vissort::detail
