#pragma once
// Triangle corners the way vertex buffers and mesh libraries hold them (meshoptimizer's
// convention): vertices of three floats at a stride, in an interleaved buffer or a packed one,
// and optionally three 32-bit indices per triangle. The orderer and the collision detector take
// them directly and gather the corners once into the structure of arrays every oracle reads
// (PositionsView), reusing its memory from frame to frame.
//
// Layer: vissort::geometry (the package's `order` component; docs/architecture.md).

#include <cstddef>
#include <cstdint>
#include <span>

#include "vissort/geometry.h"
#include "vissort/result.h"

namespace vissort {

struct VertexPositionsView {
    /// Vertex v's x, y and z are data[v * stride / 4 + 0, 1, 2] (stride in bytes).
    const float* data = nullptr;
    /// The vertices at data.
    std::size_t count = 0;
    /// Bytes from one vertex to the next: 12 when packed, the vertex's size when interleaved
    /// (positions first, then normals, ...). At least 12, a multiple of 4, at most 1024.
    std::size_t stride = 3 * sizeof(float);
    /// Three vertex indices per triangle; empty: vertices 3t, 3t+1, 3t+2 are triangle t.
    std::span<const uint32_t> indices;

    /// The triangles the view describes (indices / 3, else count / 3).
    std::size_t triangleCount() const { return indices.empty() ? count / 3 : indices.size() / 3; }
};

/// The view's triangles as corners, into out (resized; its memory reused). A one-line error,
/// out unspecified, when: data is null with vertices, the stride is out of range or not a
/// multiple of 4, the indices are not three per triangle or name a vertex outside 0..count-1,
/// there are no triangles, or more than 32-bit corner ids address, or a coordinate used is not
/// finite (naming the triangle and corner).
Status gatherPositions(const VertexPositionsView& vertices, TrianglePositions& out);

} // namespace vissort
