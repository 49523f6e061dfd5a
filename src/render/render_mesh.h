#pragma once
// The vertex stream the renderer draws: every triangle corner with its position, a smooth
// normal, its object and its drawn part, built from a scene's unindexed corners.

#include <cstdint>
#include <vector>

#include "vissort/scene.h"

namespace vissort::detail {

/// Corners sharing a position within one drawn part (SceneObject::drawnParts: the object, or a
/// mesh of it) are one vertex for normals: its normal is the area-weighted sum of its triangles'
/// normals (scene files' own normals are not kept by the loader, so they are always computed;
/// parts stay faceted against each other, so grouping meshes into objects leaves the picture
/// as it was).
class RenderMesh {
public:
    explicit RenderMesh(const Scene& scene);

    /// Fills `vertices` with 6 floats per corner (position, unit normal) for `positions`, which
    /// has the scene's corner count (a frame of a dynamic scene moves them: normals follow).
    void update(PositionsView positions, std::vector<float>& vertices);

    /// The object of each corner (constant over frames).
    const std::vector<uint32_t>& cornerObjects() const { return corner_object_; }
    /// The drawn part of each corner: parts numbered over the objects in order.
    const std::vector<uint32_t>& cornerParts() const { return corner_part_; }

private:
    std::vector<uint32_t> corner_vertex_; // corner -> welded vertex
    std::vector<uint32_t> corner_object_;
    std::vector<uint32_t> corner_part_;
    std::vector<float> vertex_normals_; // 3 per welded vertex, reused per frame
    std::vector<float> face_normals_;   // 3 per triangle, reused per frame
};

} // namespace vissort::detail
