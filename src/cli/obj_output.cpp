#include "cli/obj_output.h"

#include <ostream>

#include "cli/output_paths.h"

namespace vissort::cli {

bool writePrimitivesObj(const std::string& path, const std::string& comment,
                        PositionsView positions, std::span<const PrimitiveRange> primitives) {
    return bool(writeTextFile(path, [&](std::ostream& out) {
        out << "# " << comment << '\n';
        std::size_t next_vertex = 1;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            out << "o prim_" << p << '\n';
            const std::size_t first = std::size_t(primitives[p].first_triangle) * 3;
            const std::size_t count = std::size_t(primitives[p].triangle_count) * 3;
            for (std::size_t c = first; c < first + count; ++c)
                out << "v " << positions.x[c] << ' ' << positions.y[c] << ' ' << positions.z[c]
                    << '\n';
            for (std::size_t t = 0; t < count / 3; ++t, next_vertex += 3)
                out << "f " << next_vertex << ' ' << next_vertex + 1 << ' ' << next_vertex + 2
                    << '\n';
        }
    }));
}

} // namespace vissort::cli
