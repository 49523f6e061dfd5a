#include "render/render_mesh.h"

#include <cmath>
#include <cstring>
#include <unordered_map>

namespace vissort::detail {
namespace {

struct PositionKey {
    float x, y, z;
    uint32_t part;
    bool operator==(const PositionKey& o) const {
        return x == o.x && y == o.y && z == o.z && part == o.part;
    }
};

struct PositionHash {
    std::size_t operator()(const PositionKey& k) const {
        uint32_t bits[4];
        std::memcpy(bits, &k.x, 12);
        bits[3] = k.part;
        std::size_t h = 1469598103934665603ull;
        for (uint32_t b : bits)
            h = (h ^ b) * 1099511628211ull;
        return h;
    }
};

} // namespace

RenderMesh::RenderMesh(const Scene& scene) {
    PositionsView p = scene.positions;
    const std::size_t corners = p.x.size();
    corner_vertex_.resize(corners);
    corner_object_.resize(corners);
    corner_part_.resize(corners);
    std::unordered_map<PositionKey, uint32_t, PositionHash> vertex_of;
    vertex_of.reserve(corners);
    uint32_t part_index = 0;
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        for (const ObjectPart& part : scene.objects[o].drawnParts()) {
            const std::size_t first = std::size_t(part.first_triangle) * 3;
            for (std::size_t c = first; c < first + std::size_t(part.triangle_count) * 3; ++c) {
                // +0.0 so that -0.0 and 0.0 weld.
                const PositionKey key{p.x[c] + 0.0f, p.y[c] + 0.0f, p.z[c] + 0.0f, part_index};
                corner_vertex_[c] =
                    vertex_of.try_emplace(key, uint32_t(vertex_of.size())).first->second;
                corner_object_[c] = o;
                corner_part_[c] = part_index;
            }
            ++part_index;
        }
    }
    vertex_normals_.resize(vertex_of.size() * 3);
}

void RenderMesh::update(PositionsView positions, std::vector<float>& vertices) {
    const std::size_t corners = corner_vertex_.size();
    std::fill(vertex_normals_.begin(), vertex_normals_.end(), 0.0f);
    face_normals_.resize(corners); // 3 floats per triangle
    for (std::size_t t = 0; t < corners / 3; ++t) {
        const std::size_t c = t * 3;
        const Vec3 corner = positions.corner(c);
        // The cross product's length is twice the area: the sum weights faces by area.
        const Vec3 normal =
            cross(positions.corner(c + 1) - corner, positions.corner(c + 2) - corner);
        const float n[3] = {float(normal.x), float(normal.y), float(normal.z)};
        for (int i = 0; i < 3; ++i) {
            face_normals_[t * 3 + i] = n[i];
            for (int k = 0; k < 3; ++k)
                vertex_normals_[corner_vertex_[c + k] * 3 + i] += n[i];
        }
    }
    vertices.resize(corners * 6);
    for (std::size_t c = 0; c < corners; ++c) {
        const float* n = &vertex_normals_[corner_vertex_[c] * 3];
        double length = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
        const float* chosen = n;
        if (!(length > 0)) { // opposite faces cancelled: the corner's own face
            chosen = &face_normals_[c / 3 * 3];
            length = std::sqrt(double(chosen[0]) * chosen[0] + double(chosen[1]) * chosen[1] +
                               double(chosen[2]) * chosen[2]);
        }
        float* v = &vertices[c * 6];
        v[0] = positions.x[c];
        v[1] = positions.y[c];
        v[2] = positions.z[c];
        for (int i = 0; i < 3; ++i)
            v[3 + i] = length > 0 ? float(chosen[i] / length) : 0.0f;
    }
}

} // namespace vissort::detail
