// Reads Medit's ASCII .mesh (the INRIA Gamma Mesh Format that mmg, Gmsh and Medit write; the
// keywords and their record lengths as libMeshb documents them: github.com/LoicMarechal/libMeshb,
// Documentation/libMeshb7.tex, "Keywords") and the scalar of an optional .sol beside it.
//
// A .mesh is `MeshVersionFormatted <1..4>`, `Dimension 3`, then sections: a keyword, a count and
// that many records of a known number of values, until `End` or the end of the text. The values
// are whitespace-separated, not line-based (libMeshb reads them with fscanf), so tokens are read
// across lines; '#' starts a comment. Keywords are matched in any case. Read: Vertices (x y z
// ref), Tetrahedra, Hexahedra, Prisms and Pyramids (1-based vertex indices then a ref). Counted
// in skipped_cells: Edges, Triangles, Quadrilaterals (and their quadratic kinds). Skipped: the
// other sections whose record length libMeshb gives (Corners, Ridges, Normals, ...). Refused
// with a message: an unknown keyword, high-order volume cells, Dimension 2, binary .meshb.
//
// Corner orders. Medit's hexahedron is 1-2-3-4 one quadrilateral face, 5-6-7-8 the opposite one,
// vertex i + 4 joined to i, as VTK_HEXAHEDRON: Frey's hexahexa_2x2x2.mesh (the sample of the
// Medit report, INRIA RT-0253, 2001; also in J. Burkardt's mesh data) lists its cube cells so.
// Prisms (triangles 1-2-3 and 4-5-6, i + 3 joined to i) and pyramids (quadrilateral 1-2-3-4,
// apex 5) are in VTK_WEDGE's and VTK_PYRAMID's orders too: meshio's Medit reader
// (src/meshio/medit/_medit.py) reads them into its VTK-ordered wedge and pyramid without a
// permutation. So corners are kept in the file's order, less 1; which way a cell's first face
// winds (its orientation) is the file's, left to tetrahedralize().
//
// A .sol is `MeshVersionFormatted`, `Dimension 3`, then `SolAtVertices <n>`, a line
// `<#fields> <type per field>` (1 scalar, 2 vector, 3 symmetric matrix, 4 matrix) and n records
// of the fields' values; the first scalar field is the grid's scalar. Other SolAt* sections,
// Time and Iterations are skipped.

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

// Whether the bytes start as libMeshb's binary files do: the int32 1 in either byte order.
bool isBinary(const std::string& bytes) {
    if (bytes.size() < 4)
        return false;
    const std::string_view head(bytes.data(), 4);
    return head == std::string_view("\1\0\0\0", 4) || head == std::string_view("\0\0\0\1", 4);
}

enum class SectionKind : uint8_t { vertices, cells, skipped_cells, skipped };

struct Section {
    const char* keyword; // lowercase
    SectionKind kind;
    uint32_t values;  // per record, in 3D
    CellType type;    // for cells
    const char* noun; // one record, in messages
};

// The sections known, with their record lengths in 3D (libMeshb7.tex, "Keywords"; the older
// Vertex/EdgeOnGeometric* names and SubDomainFromMesh as meshio's reader reads them).
constexpr Section kSections[] = {
    {"vertices", SectionKind::vertices, 4, CellType::tetrahedron, "vertex"},
    {"tetrahedra", SectionKind::cells, 5, CellType::tetrahedron, "tetrahedron"},
    {"hexahedra", SectionKind::cells, 9, CellType::hexahedron, "hexahedron"},
    {"hexaedra", SectionKind::cells, 9, CellType::hexahedron, "hexahedron"}, // Medit's old spelling
    {"prisms", SectionKind::cells, 7, CellType::wedge, "prism"},
    {"pyramids", SectionKind::cells, 6, CellType::pyramid, "pyramid"},
    {"edges", SectionKind::skipped_cells, 3, CellType::tetrahedron, "edge"},
    {"triangles", SectionKind::skipped_cells, 4, CellType::tetrahedron, "triangle"},
    {"quadrilaterals", SectionKind::skipped_cells, 5, CellType::tetrahedron, "quadrilateral"},
    {"edgesp2", SectionKind::skipped_cells, 4, CellType::tetrahedron, "edge"},
    {"trianglesp2", SectionKind::skipped_cells, 7, CellType::tetrahedron, "triangle"},
    {"quadrilateralsq2", SectionKind::skipped_cells, 10, CellType::tetrahedron, "quadrilateral"},
    {"corners", SectionKind::skipped, 1, CellType::tetrahedron, "record"},
    {"requiredvertices", SectionKind::skipped, 1, CellType::tetrahedron, "record"},
    {"ridges", SectionKind::skipped, 1, CellType::tetrahedron, "record"},
    {"requirededges", SectionKind::skipped, 1, CellType::tetrahedron, "record"},
    {"requiredtriangles", SectionKind::skipped, 1, CellType::tetrahedron, "record"},
    {"requiredquadrilaterals", SectionKind::skipped, 1, CellType::tetrahedron, "record"},
    {"requiredtetrahedra", SectionKind::skipped, 1, CellType::tetrahedron, "record"},
    {"normals", SectionKind::skipped, 3, CellType::tetrahedron, "record"},
    {"tangents", SectionKind::skipped, 3, CellType::tetrahedron, "record"},
    {"normalatvertices", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"normalattrianglevertices", SectionKind::skipped, 3, CellType::tetrahedron, "record"},
    {"normalatquadrilateralvertices", SectionKind::skipped, 4, CellType::tetrahedron, "record"},
    {"tangentatvertices", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"tangentatedgevertices", SectionKind::skipped, 3, CellType::tetrahedron, "record"},
    {"verticesongeometricvertices", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"verticesongeometricedges", SectionKind::skipped, 4, CellType::tetrahedron, "record"},
    {"verticesongeometrictriangles", SectionKind::skipped, 5, CellType::tetrahedron, "record"},
    {"verticesongeometricquadrilaterals", SectionKind::skipped, 5, CellType::tetrahedron, "record"},
    {"edgesongeometricedges", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"trianglesongeometrictriangles", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"trianglesongeometricquadrilaterals", SectionKind::skipped, 2, CellType::tetrahedron,
     "record"},
    {"quadrilateralsongeometrictriangles", SectionKind::skipped, 2, CellType::tetrahedron,
     "record"},
    {"quadrilateralsongeometricquadrilaterals", SectionKind::skipped, 2, CellType::tetrahedron,
     "record"},
    {"periodicvertices", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"periodicedges", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"periodictriangles", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"periodicquadrilaterals", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"vertexongeometricvertex", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"vertexongeometricedge", SectionKind::skipped, 3, CellType::tetrahedron, "record"},
    {"edgeongeometricedge", SectionKind::skipped, 2, CellType::tetrahedron, "record"},
    {"subdomainfrommesh", SectionKind::skipped, 4, CellType::tetrahedron, "record"},
};

const Section* findSection(const std::string& keyword) {
    for (const Section& section : kSections)
        if (keyword == section.keyword)
            return &section;
    return nullptr;
}

bool isHighOrderVolume(const std::string& keyword) {
    for (const char* prefix : {"tetrahedrap", "hexahedraq", "prismsp", "pyramidsp"})
        if (keyword.starts_with(prefix))
            return true;
    return false;
}

// Where a message points: "line 12 (Vertices): " with the keyword as the file spells it.
std::string at(std::string_view file, std::size_t line, std::string_view keyword) {
    std::string text = std::string(file) + "line " + std::to_string(line);
    if (!keyword.empty())
        text += " (" + std::string(keyword) + ")";
    return text + ": ";
}

// A section's count, after its keyword: a non-negative integer whose records, of `values`
// tokens each, fit in the bytes left (bounded memory on hostile headers), and at most `limit`
// (`limit_shown` in the message: the grid's limit, of which `limit` may be what is left).
Result<uint64_t> readCount(TokenScanner& scanner, std::string_view file, std::string_view keyword,
                           uint64_t values, const char* nouns, uint64_t limit = UINT64_MAX,
                           uint64_t limit_shown = 0) {
    const std::string_view token = scanner.next();
    const std::string where = at(file, scanner.line(), keyword);
    if (token.empty())
        return Result<uint64_t>::failure(where + "the file ends before the count");
    const std::optional<int64_t> count = TokenScanner::parseInteger(token);
    if (!count || *count < 0)
        return Result<uint64_t>::failure(where + "the count " + quoted(token, kQuoteChars) +
                                         " is not a non-negative integer");
    const uint64_t n = uint64_t(*count);
    if (n > limit)
        return Result<uint64_t>::failure(where + std::to_string(n) + " " + nouns +
                                         " declared, beyond the limit of " +
                                         std::to_string(limit_shown) + " " + nouns + " in a grid");
    if (values > 0 && n > scanner.maxTokensLeft() / values)
        return Result<uint64_t>::failure(where + std::to_string(n) + " " + nouns +
                                         " declared, more than the rest of the file can hold (" +
                                         std::to_string(scanner.maxTokensLeft()) + " values)");
    return Result<uint64_t>{n, {}};
}

// The value of a record, its keyword and index named when it is missing.
std::string missing(std::string_view file, const TokenScanner& scanner, std::string_view keyword,
                    const char* noun, uint64_t record, uint64_t count) {
    return at(file, scanner.line(), keyword) + "the file ends in " + noun + " " +
           std::to_string(record + 1) + " of " + std::to_string(count);
}

// Checks the value after MeshVersionFormatted (1 to 4: versions 3 and 4 change only a binary
// file's integer sizes) or Dimension (3), the keyword as the file spells it; `value_name` says
// what the file ends before, `contents` what only 3D of is read. The problem, or empty.
std::string readFormatValue(TokenScanner& scanner, std::string_view file, std::string_view keyword,
                            bool is_version, const char* value_name, const char* contents) {
    const std::string_view value = scanner.next();
    if (value.empty())
        return at(file, scanner.line(), keyword) + "the file ends before " + value_name;
    const std::optional<int64_t> number = TokenScanner::parseInteger(value);
    if (is_version && (!number || *number < 1 || *number > 4))
        return at(file, scanner.line(), keyword) + "version " + quoted(value, kQuoteChars) +
               ", expected 1, 2, 3 or 4";
    if (!is_version && (!number || *number != 3))
        return at(file, scanner.line(), keyword) + "dimension " + quoted(value, kQuoteChars) +
               ", only 3D " + contents + " are read";
    return {};
}

// Why a token that is no known keyword stands where a keyword should: a number, most likely
// a record beyond its section's count, or an unknown word.
std::string notAKeyword(std::string_view file, std::size_t line, std::string_view token) {
    if (TokenScanner::parseDouble(token))
        return at(file, line, "") + "number " + quoted(token, kQuoteChars) +
               " where a keyword is expected (more records than a section's count?)";
    return at(file, line, "") + "unknown keyword " + quoted(token, kQuoteChars);
}

class MeshReader {
public:
    explicit MeshReader(const std::string& bytes) : scanner_(bytes, '#') {}

    // The grid, or the one-line problem.
    std::string read(RawGrid& grid) {
        bool version_read = false;
        while (true) {
            const std::string_view token = scanner_.next();
            if (token.empty())
                break; // End is optional, as for libMeshb
            const std::size_t line = scanner_.line();
            const std::string keyword = lowerCase(token.substr(0, 64));
            if (keyword == "end")
                break;
            const bool is_version = keyword == "meshversionformatted";
            if (is_version && version_read)
                return at("", line, token) + "a second MeshVersionFormatted";
            if (!is_version && !version_read)
                return at("", line, "") + quoted(token, kQuoteChars) +
                       " where MeshVersionFormatted should start a Medit .mesh";
            if (keyword == "dimension" && dimension_read_)
                return at("", line, token) + "a second Dimension";
            if (is_version || keyword == "dimension") {
                if (std::string error =
                        readFormatValue(scanner_, "", token, is_version,
                                        is_version ? "the version" : "the dimension", "meshes");
                    !error.empty())
                    return error;
                (is_version ? version_read : dimension_read_) = true;
                continue;
            }
            if (std::string error = readSection(token, keyword, line, grid); !error.empty())
                return error;
        }
        if (!vertices_read_)
            return "no Vertices section";
        // Cells before Vertices could not be checked against the vertices when read.
        for (const uint32_t corner : grid.cell_points)
            if (corner >= grid.points.size())
                return "a cell refers to vertex " + std::to_string(uint64_t(corner) + 1) +
                       ", beyond the " + std::to_string(grid.points.size()) + " vertices";
        return {};
    }

private:
    std::string readSection(std::string_view token, const std::string& keyword, std::size_t line,
                            RawGrid& grid) {
        const Section* section = findSection(keyword);
        if (!section) {
            if (isHighOrderVolume(keyword))
                return at("", line, "") + quoted(token, kQuoteChars) +
                       ": high-order cells are not read";
            return notAKeyword("", line, token);
        }
        if (!dimension_read_)
            return at("", line, token) + "the section comes before Dimension";
        switch (section->kind) {
        case SectionKind::vertices:
            return readVertices(token, grid);
        case SectionKind::cells:
            return readCells(token, *section, grid);
        case SectionKind::skipped_cells:
        case SectionKind::skipped:
            return skipRecords(token, *section, grid);
        }
        return {};
    }

    std::string readVertices(std::string_view keyword, RawGrid& grid) {
        if (vertices_read_)
            return at("", scanner_.line(), keyword) + "a second Vertices section";
        const Result<uint64_t> count =
            readCount(scanner_, "", keyword, 4, "vertices", kMaxGridPoints, kMaxGridPoints);
        if (!count)
            return count.error;
        grid.points.reserve(*count.value);
        for (uint64_t i = 0; i < *count.value; ++i) {
            double xyz[3];
            for (double& coordinate : xyz) {
                const std::string_view token = scanner_.next();
                if (token.empty())
                    return missing("", scanner_, keyword, "vertex", i, *count.value);
                const std::optional<double> value = TokenScanner::parseDouble(token);
                if (!value)
                    return at("", scanner_.line(), keyword) + "vertex " + std::to_string(i + 1) +
                           ": coordinate " + badNumber(token, kQuoteChars);
                coordinate = *value;
            }
            const std::string_view ref = scanner_.next();
            if (ref.empty())
                return missing("", scanner_, keyword, "vertex", i, *count.value);
            if (!TokenScanner::parseInteger(ref))
                return at("", scanner_.line(), keyword) + "vertex " + std::to_string(i + 1) +
                       ": reference " + quoted(ref, kQuoteChars) + " is not an integer";
            grid.points.push_back({xyz[0], xyz[1], xyz[2]});
        }
        vertices_read_ = true;
        return {};
    }

    std::string readCells(std::string_view keyword, const Section& section, RawGrid& grid) {
        // Every cell makes at least one tetrahedron: more cells than kMaxGridTets make too many.
        const Result<uint64_t> count =
            readCount(scanner_, "", keyword, section.values, "cells",
                      kMaxGridTets - grid.cell_types.size(), kMaxGridTets);
        if (!count)
            return count.error;
        const uint32_t corners = cornerCount(section.type);
        grid.cell_types.reserve(grid.cell_types.size() + *count.value);
        grid.cell_offsets.reserve(grid.cell_offsets.size() + *count.value);
        grid.cell_points.reserve(grid.cell_points.size() + *count.value * corners);
        // Before Vertices, indices are checked at the end instead (read()).
        const uint64_t vertex_count = vertices_read_ ? grid.points.size() : kMaxGridPoints;
        for (uint64_t i = 0; i < *count.value; ++i) {
            uint32_t cell[8];
            for (uint32_t c = 0; c <= corners; ++c) {
                const std::string_view token = scanner_.next();
                if (token.empty())
                    return missing("", scanner_, keyword, section.noun, i, *count.value);
                const std::optional<int64_t> value = TokenScanner::parseInteger(token);
                const std::string where = at("", scanner_.line(), keyword) + section.noun + " " +
                                          std::to_string(i + 1) + ": ";
                if (c == corners) { // the reference
                    if (!value)
                        return where + "reference " + quoted(token, kQuoteChars) +
                               " is not an integer";
                    break;
                }
                if (!value)
                    return where + "vertex index " + quoted(token, kQuoteChars) +
                           " is not an integer";
                if (*value < 1 || uint64_t(*value) > vertex_count)
                    return where + "vertex index " + std::to_string(*value) +
                           " is not one of the " + std::to_string(vertex_count) +
                           " vertices (numbered from 1)";
                cell[c] = uint32_t(*value - 1);
            }
            grid.addCell(section.type, cell);
        }
        return {};
    }

    std::string skipRecords(std::string_view keyword, const Section& section, RawGrid& grid) {
        const Result<uint64_t> count = readCount(scanner_, "", keyword, section.values, "records");
        if (!count)
            return count.error;
        for (uint64_t i = 0; i < *count.value; ++i) {
            for (uint32_t v = 0; v < section.values; ++v) {
                const std::string_view token = scanner_.next();
                if (token.empty())
                    return missing("", scanner_, keyword, section.noun, i, *count.value);
                if (!TokenScanner::parseDouble(token))
                    return at("", scanner_.line(), keyword) + section.noun + " " +
                           std::to_string(i + 1) + ": " + badNumber(token, kQuoteChars);
            }
        }
        if (section.kind == SectionKind::skipped_cells)
            grid.skipped_cells += *count.value;
        return {};
    }

    TokenScanner scanner_;
    bool dimension_read_ = false;
    bool vertices_read_ = false;
};

// How many values a .sol field of this type has in 3D, or 0 for an unknown type.
uint64_t solutionSize(int64_t type) {
    switch (type) {
    case 1:
        return 1; // scalar
    case 2:
        return 3; // vector
    case 3:
        return 6; // symmetric matrix
    case 4:
        return 9; // matrix
    default:
        return 0;
    }
}

// Reads a .sol's first scalar field at the vertices into grid.scalars.
std::string readSol(const std::string& bytes, RawGrid& grid) {
    if (isBinary(bytes))
        return "binary .solb is not read: write ASCII .sol";
    TokenScanner scanner(bytes, '#');
    const std::string_view file = ".sol ";
    bool version_read = false, dimension_read = false, solution_read = false;
    while (true) {
        const std::string_view token = scanner.next();
        if (token.empty())
            break;
        const std::size_t line = scanner.line();
        const std::string keyword = lowerCase(token.substr(0, 64));
        if (keyword == "end")
            break;
        if (keyword == "meshversionformatted" || keyword == "dimension") {
            const bool is_version = keyword == "meshversionformatted";
            if (is_version ? version_read : dimension_read)
                return at(file, line, token) + "a second " + std::string(token);
            if (!is_version && !version_read)
                return at(file, line, "") + quoted(token, kQuoteChars) +
                       " where MeshVersionFormatted should start a Medit .sol";
            if (std::string error =
                    readFormatValue(scanner, file, token, is_version, "its value", "solutions");
                !error.empty())
                return error;
            (is_version ? version_read : dimension_read) = true;
            continue;
        }
        if (!version_read || !dimension_read)
            return at(file, line, "") + quoted(token, kQuoteChars) +
                   " where MeshVersionFormatted and Dimension should start a Medit .sol";
        if (keyword == "time" || keyword == "iterations") { // one value, no count
            const std::string_view value = scanner.next();
            if (value.empty())
                return at(file, scanner.line(), token) + "the file ends before its value";
            if (!TokenScanner::parseDouble(value))
                return at(file, scanner.line(), token) + badNumber(value, kQuoteChars);
            continue;
        }
        if (!keyword.starts_with("solat")) {
            return notAKeyword(file, line, token);
        }
        const bool at_vertices = keyword == "solatvertices";
        if (at_vertices && solution_read)
            return at(file, line, token) + "a second SolAtVertices section";
        // The count is checked against the bytes once the record length is known.
        const Result<uint64_t> count = readCount(scanner, file, token, 0, "records");
        if (!count)
            return count.error;
        const std::string_view fields_token = scanner.next();
        const std::optional<int64_t> fields = TokenScanner::parseInteger(fields_token);
        if (!fields || *fields < 1 || uint64_t(*fields) > scanner.maxTokensLeft())
            return at(file, scanner.line(), token) + "field count " +
                   quoted(fields_token, kQuoteChars) +
                   " is not a positive integer the file can hold";
        uint64_t record_size = 0, scalar_offset = UINT64_MAX;
        for (int64_t f = 0; f < *fields; ++f) {
            const std::string_view type_token = scanner.next();
            const std::optional<int64_t> type = TokenScanner::parseInteger(type_token);
            const uint64_t size = type ? solutionSize(*type) : 0;
            if (size == 0)
                return at(file, scanner.line(), token) + "field type " +
                       quoted(type_token, kQuoteChars) +
                       ", expected 1 (scalar), 2 (vector), 3 or 4 (matrix)";
            if (size == 1 && scalar_offset == UINT64_MAX)
                scalar_offset = record_size;
            record_size += size; // at most 9 per field: no overflow
        }
        if (*count.value > scanner.maxTokensLeft() / record_size)
            return at(file, line, token) + std::to_string(*count.value) +
                   " records declared, more than the " + std::to_string(scanner.maxTokensLeft()) +
                   " values the rest of the file can hold";
        if (at_vertices) {
            if (scalar_offset == UINT64_MAX)
                return at(file, line, token) + "no scalar field (type 1) among the " +
                       std::to_string(*fields) + " fields";
            if (*count.value != grid.points.size())
                return at(file, line, token) + std::to_string(*count.value) +
                       " values for the mesh's " + std::to_string(grid.points.size()) + " vertices";
            grid.scalars.reserve(*count.value);
            grid.scalar_name = "SolAtVertices";
        }
        for (uint64_t i = 0; i < *count.value; ++i) {
            for (uint64_t v = 0; v < record_size; ++v) {
                const std::string_view value = scanner.next();
                if (value.empty())
                    return missing(file, scanner, token, "record", i, *count.value);
                const std::optional<double> number = TokenScanner::parseDouble(value);
                if (!number)
                    return at(file, scanner.line(), token) + "record " + std::to_string(i + 1) +
                           ": " + badNumber(value, kQuoteChars);
                if (at_vertices && v == scalar_offset)
                    grid.scalars.push_back(*number);
            }
        }
        solution_read = solution_read || at_vertices;
    }
    if (!solution_read)
        return ".sol has no SolAtVertices section";
    return {};
}

} // namespace

Result<RawGrid> readMedit(const std::string& mesh_bytes, const std::string* sol_bytes) {
    if (isBinary(mesh_bytes))
        return Result<RawGrid>::failure("binary .meshb is not read: write ASCII .mesh");
    RawGrid grid;
    if (std::string error = MeshReader(mesh_bytes).read(grid); !error.empty())
        return Result<RawGrid>::failure(std::move(error));
    if (sol_bytes)
        if (std::string error = readSol(*sol_bytes, grid); !error.empty())
            return Result<RawGrid>::failure(std::move(error));
    return Result<RawGrid>{std::move(grid), {}};
}

} // namespace vissort::detail
