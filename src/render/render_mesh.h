#pragma once
// The vertex stream the renderer draws: every triangle corner with its position, a smooth
// normal and its object, built from a scene's unindexed corners.

#include <cstdint>
#include <vector>

#include "vissort/scene.h"

namespace vissort::detail {

/// Corners sharing a position within one object are one vertex for normals: its normal is the
/// area-weighted sum of its triangles' normals (scene files' own normals are not kept by the
/// loader, so they are always computed; objects stay faceted against each other).
class RenderMesh {
public:
    explicit RenderMesh(const Scene& scene);

    /// Fills `vertices` with 6 floats per corner (position, unit normal) for `positions`, which
    /// has the scene's corner count (a frame of a dynamic scene moves them: normals follow).
    void update(PositionsView positions, std::vector<float>& vertices);

    /// The object of each corner (constant over frames).
    const std::vector<uint32_t>& cornerObjects() const { return corner_object_; }

private:
    std::vector<uint32_t> corner_vertex_; // corner -> welded vertex
    std::vector<uint32_t> corner_object_;
    std::vector<float> vertex_normals_; // 3 per welded vertex, reused per frame
    std::vector<float> face_normals_;   // 3 per triangle, reused per frame
};

} // namespace vissort::detail
