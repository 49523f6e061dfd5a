// The `slabs` scene: a stack of large, slightly tilted quads along z. A controlled case for
// depth complexity: seen from +z, a pixel near the middle is covered by every layer.

#include <cmath>
#include <numbers>
#include <string>

#include "scenes/builtin_scenes.h"
#include "scenes/scene_parameters.h"

namespace vissort::detail {
namespace {

constexpr double kSpacing = 0.25; // distance along z between consecutive layer centres
constexpr double kHalfSize = 2.0; // each quad is 4 x 4 before tilting
// A tilt of a about x and b about y lifts a corner by at most kHalfSize * (sin a + sin b):
// 2 * 2 * sin(1.5 deg) = 0.105 < kSpacing / 2, so the slab of layer k stays strictly inside
// z_k +- kSpacing / 2. Planes between layers then separate every pair of quads, which makes the
// quads disjoint and their visibility order acyclic from any viewpoint.
constexpr double kMaxTiltDegrees = 1.5;
constexpr float kAlpha = 0.4f;

} // namespace

Result<Scene> makeSlabsScene(const SceneParameters& parameters) {
    ParameterReader reader("builtin:slabs", parameters);
    const auto layers = static_cast<uint32_t>(reader.integer("layers", 8, 1, 100'000));
    const uint64_t seed = reader.seed("seed", 1);
    if (std::string error = reader.error(); !error.empty())
        return Result<Scene>::failure(error);

    SceneRandom random(seed);
    Scene scene;
    scene.name = "builtin:slabs";
    scene.positions.resize(std::size_t{layers} * 2);
    scene.objects.reserve(layers);

    const double max_tilt = kMaxTiltDegrees * std::numbers::pi / 180;
    const double corners[4][2] = {{-kHalfSize, -kHalfSize},
                                  {kHalfSize, -kHalfSize},
                                  {kHalfSize, kHalfSize},
                                  {-kHalfSize, kHalfSize}};
    constexpr int kQuadCorners[6] = {0, 1, 2, 0, 2, 3};
    TrianglePositions& out = scene.positions;
    for (uint32_t layer = 0; layer < layers; ++layer) {
        // Layers are centred on the origin, layer 0 at the bottom (most negative z).
        const double centre_z = (layer - (layers - 1) / 2.0) * kSpacing;
        const double tilt_x = random.uniform(-max_tilt, max_tilt);
        const double tilt_y = random.uniform(-max_tilt, max_tilt);
        const double cx = std::cos(tilt_x), sx = std::sin(tilt_x);
        const double cy = std::cos(tilt_y), sy = std::sin(tilt_y);
        for (int i = 0; i < 6; ++i) {
            const double px = corners[kQuadCorners[i]][0], py = corners[kQuadCorners[i]][1];
            // Rotate (px, py, 0) by Rx(tilt_x), then by Ry(tilt_y).
            const double ry = py * cx, rz = py * sx;
            const std::size_t index = std::size_t{layer} * 6 + i;
            out.x[index] = static_cast<float>(px * cy + rz * sy);
            out.y[index] = static_cast<float>(ry);
            out.z[index] = static_cast<float>(centre_z - px * sy + rz * cy);
        }
        SceneObject object;
        object.name = "slab_" + std::to_string(layer);
        object.colour = random.colour(kAlpha);
        object.transparent = true;
        object.first_triangle = layer * 2;
        object.triangle_count = 2;
        scene.objects.push_back(std::move(object));
    }

    // Straight down the stack from above, far enough that the top quad fills most of a 45 degree
    // view without leaving it; the lower quads project inside it.
    const double top = (layers - 1) / 2.0 * kSpacing + kSpacing / 2;
    CameraSpec camera;
    camera.fov_degrees = 45.0;
    camera.eye = {
        0, 0, top + 1.1 * kHalfSize / std::tan(camera.fov_degrees / 2 * std::numbers::pi / 180)};
    camera.target = {0, 0, 0};
    camera.up = {0, 1, 0};
    scene.camera = camera;
    return Result<Scene>{std::move(scene), {}};
}

} // namespace vissort::detail
