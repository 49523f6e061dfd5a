// gatherPositions (vertex_positions.h): vertex buffers to the corners' structure of arrays.

#include "vissort/vertex_positions.h"

#include <cmath>
#include <string>

namespace vissort {
namespace {

// Corner ids are 32-bit throughout the library.
constexpr std::size_t kMaxTriangles = (std::size_t(1) << 32) / 3 - 1;
constexpr std::size_t kMaxStride = 1024;

std::string problemOf(const VertexPositionsView& v) {
    if (v.stride < 3 * sizeof(float) || v.stride % sizeof(float) != 0 || v.stride > kMaxStride)
        return "vertex stride " + std::to_string(v.stride) +
               " bytes: expected a multiple of 4 from 12 to " + std::to_string(kMaxStride);
    if (v.count > 0 && v.data == nullptr)
        return "vertex data is null with " + std::to_string(v.count) + " vertices";
    if (!v.indices.empty() && v.indices.size() % 3 != 0)
        return std::to_string(v.indices.size()) + " indices: expected three per triangle";
    if (v.indices.empty() && v.count % 3 != 0)
        return std::to_string(v.count) + " vertices without indices: expected three per triangle";
    if (v.triangleCount() == 0)
        return "no triangles";
    if (v.triangleCount() > kMaxTriangles)
        return std::to_string(v.triangleCount()) + " triangles, more than the " +
               std::to_string(kMaxTriangles) + " that 32-bit corner ids address";
    return {};
}

} // namespace

Status gatherPositions(const VertexPositionsView& vertices, TrianglePositions& out) {
    if (std::string problem = problemOf(vertices); !problem.empty())
        return Status::failure(std::move(problem));
    const std::size_t corners = 3 * vertices.triangleCount();
    const std::size_t step = vertices.stride / sizeof(float);
    out.resize(corners / 3);
    for (std::size_t c = 0; c < corners; ++c) {
        const std::size_t v = vertices.indices.empty() ? c : vertices.indices[c];
        if (v >= vertices.count)
            return Status::failure("triangle " + std::to_string(c / 3) + " names vertex " +
                                   std::to_string(v) + ", outside 0.." +
                                   std::to_string(vertices.count - 1));
        const float* p = vertices.data + v * step;
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            return Status::failure("triangle " + std::to_string(c / 3) + ", corner " +
                                   std::to_string(c % 3) + " is not finite (vertex " +
                                   std::to_string(v) + ")");
        out.x[c] = p[0];
        out.y[c] = p[1];
        out.z[c] = p[2];
    }
    return Status::ok();
}

} // namespace vissort
