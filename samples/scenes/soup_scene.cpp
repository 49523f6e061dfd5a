// The `soup` scene: random triangles that never intersect, one per cell of a jittered grid (as in
// jittered sampling: a random point per stratum), so that every ordering difficulty comes from
// occlusion alone, not from intersections.

#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scenes/builtin_scenes.h"
#include "scenes/scene_parameters.h"

namespace vissort::detail {
namespace {

// Cells are unit cubes. A triangle lies on a sphere of radius r around its centre, kept
// kCellMargin away from its cell's walls, so triangles of different cells are at least
// 2 * kCellMargin apart: far above float rounding for grids up to 216 cells a side.
constexpr double kCellMargin = 0.025;
constexpr double kMinRadius = 0.2;
constexpr double kMaxRadius = 0.45;
constexpr float kAlpha = 0.5f;

} // namespace

Result<Scene> makeSoupScene(const SceneParameters& parameters) {
    ParameterReader reader("builtin:soup", parameters);
    const auto count = static_cast<uint32_t>(reader.integer("n", 1000, 1, kMaxBuiltinTriangles));
    const uint64_t seed = reader.seed("seed", 1);
    if (std::string error = reader.error(); !error.empty())
        return Result<Scene>::failure(error);

    uint32_t side = 1; // the smallest grid with at least `count` cells
    while (std::size_t{side} * side * side < count)
        ++side;
    const uint32_t cell_count = side * side * side;

    SceneRandom random(seed);
    // A partial Fisher-Yates shuffle picks `count` distinct cells in random order, so triangle ids
    // say nothing about position and a grid that is not full leaves random holes.
    std::vector<uint32_t> cells(cell_count);
    std::iota(cells.begin(), cells.end(), 0u);
    for (uint32_t i = 0; i < count; ++i)
        std::swap(cells[i], cells[i + random.index(cell_count - i)]);

    Scene scene;
    scene.name = "builtin:soup";
    scene.positions.resize(count);
    scene.objects.resize(count);
    TrianglePositions& out = scene.positions;
    const double origin = -(side / 2.0); // the cube is centred on the origin
    constexpr double kThird = 2 * std::numbers::pi / 3;
    for (uint32_t t = 0; t < count; ++t) {
        const uint32_t cell = cells[t];
        const double cell_min[3] = {origin + cell % side, origin + cell / side % side,
                                    origin + cell / (side * side)};
        const double radius = random.uniform(kMinRadius, kMaxRadius);
        double centre[3];
        for (int axis = 0; axis < 3; ++axis) {
            const double low = cell_min[axis] + kCellMargin + radius;
            centre[axis] = random.uniform(low, cell_min[axis] + 1 - kCellMargin - radius);
        }
        const std::array<double, 4> q = random.rotation();
        const glm::dmat3 orientation = glm::mat3_cast(glm::dquat(q[0], q[1], q[2], q[3]));
        // Corners roughly a third of a turn apart (never closer than 60 degrees) at 60..100% of
        // the radius: varied shapes, none degenerate.
        for (int corner = 0; corner < 3; ++corner) {
            const double angle = corner * kThird + (corner ? random.uniform(-0.5, 0.5) : 0.0);
            const double reach = radius * random.uniform(0.6, 1.0);
            const glm::dvec3 p =
                orientation * glm::dvec3(reach * std::cos(angle), reach * std::sin(angle), 0);
            const std::size_t index = std::size_t{t} * 3 + corner;
            out.x[index] = static_cast<float>(centre[0] + p.x);
            out.y[index] = static_cast<float>(centre[1] + p.y);
            out.z[index] = static_cast<float>(centre[2] + p.z);
        }
        SceneObject& object = scene.objects[t];
        object.name = "tri_" + std::to_string(t); // short enough to stay in the string's buffer
        object.colour = random.colour(kAlpha);
        object.transparent = true;
        object.first_triangle = t;
        object.triangle_count = 1;
    }
    Bounds cube;
    cube.add({origin, origin, origin});
    cube.add({-origin, -origin, -origin});
    scene.camera = defaultCamera(cube);
    return Result<Scene>{std::move(scene), {}};
}

} // namespace vissort::detail
