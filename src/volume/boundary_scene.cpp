// boundaryScene: a grid's boundary faces as one object, so that a grid's cameras are chosen and
// framed by the same policy as a scene's (chooseView).
#include "vissort/volume.h"

namespace vissort {

Scene boundaryScene(const TetGrid& grid) {
    Scene scene;
    scene.name = grid.name;
    Result<std::vector<TetNeighbours>> neighbours = faceNeighbours(grid);
    std::size_t count = 0;
    const auto each_face = [&](auto&& visit) {
        for (uint32_t t = 0; t < grid.tets.size(); ++t)
            for (int f = 0; f < 4; ++f)
                if (!neighbours || (*neighbours.value)[t][f] == kNoNeighbour)
                    visit(t, f);
    };
    each_face([&](uint32_t, int) { ++count; });
    scene.positions.resize(count);
    std::size_t corner = 0;
    each_face([&](uint32_t t, int f) {
        for (int k = 0; k < 3; ++k, ++corner) {
            const Vec3& p = grid.points[grid.tets[t][kTetFaceCorners[f][k]]];
            scene.positions.x[corner] = float(p.x);
            scene.positions.y[corner] = float(p.y);
            scene.positions.z[corner] = float(p.z);
        }
    });
    SceneObject boundary;
    boundary.name = "boundary";
    boundary.triangle_count = uint32_t(count);
    scene.objects.push_back(boundary);
    return scene;
}

} // namespace vissort
