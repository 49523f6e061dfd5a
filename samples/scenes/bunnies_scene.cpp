// The `bunnies` scene: the dynamic scene of Govindaraju, Henson, Lin and Manocha, "Interactive
// Visibility Ordering and Transparency Computations among Geometric Primitives in Complex
// Environments", I3D 2005 (Vis-sort): deforming Stanford bunnies moving in a box, colliding.
//
// Every frame is a pure function of t: positions bounce off the walls by folding the straight
// line into the allowed interval (a triangle wave), rotations turn at a constant rate, and the
// deformation is a travelling sine wave along the vertex normals. No state is stepped, so any
// frame can be asked for in any order and the result is the same.

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scenes/builtin_scenes.h"
#include "scenes/embedded_meshes.h"
#include "scenes/scene_parameters.h"

namespace vissort::detail {
namespace {

constexpr double kMinSpeed = 0.5, kMaxSpeed = 1.5;           // units per second
constexpr double kMinSpinDegrees = 20, kMaxSpinDegrees = 90; // degrees per second
constexpr double kWaveSpatialFrequency = 3;                  // radians per model unit of y
constexpr double kWaveTemporalFrequency = 2;                 // radians per second
constexpr float kAlpha = 0.5f;
constexpr double kGoldenFraction = 0.6180339887498949; // spreads successive hues evenly

glm::dvec3 toGlm(const Vec3& v) {
    return {v.x, v.y, v.z};
}

/// Folds x into [-half_range, half_range] as a point moving on a line would be by perfectly
/// elastic walls at +-half_range: a triangle wave of period 4 * half_range.
double foldIntoRange(double x, double half_range) {
    if (half_range <= 0)
        return 0;
    const double period = 4 * half_range;
    double u = std::fmod(x + half_range, period);
    if (u < 0)
        u += period;
    return u <= 2 * half_range ? u - half_range : 3 * half_range - u;
}

/// One welded vertex of the rest mesh, in the unit-sphere model space, with what the wave needs.
struct RestVertex {
    glm::dvec3 position;
    glm::dvec3 normal; // unit, or zero where the faces around the vertex cancel out
    // sin and cos of kWaveSpatialFrequency * y: the wave sin(3y + 2t + phase) is then
    // sin_y * cos(2t + phase) + cos_y * sin(2t + phase), with no sine per vertex per frame.
    double sin_y, cos_y;
};

struct BunnyMotion {
    glm::dvec3 start; // centre at t = 0
    glm::dvec3 velocity;
    glm::dquat orientation; // at t = 0
    glm::dvec3 spin_axis;   // unit, world space
    double spin_rate;       // radians per second
    double phase;           // of the deformation wave, radians
};

class BunniesAnimation final : public Animation {
public:
    BunniesAnimation(std::vector<RestVertex> vertices, std::vector<uint32_t> corner_vertex,
                     std::vector<BunnyMotion> bunnies, double half_range)
        : vertices_(std::move(vertices)), corner_vertex_(std::move(corner_vertex)),
          bunnies_(std::move(bunnies)), half_range_(half_range) {}

    std::size_t bunnyCount() const { return bunnies_.size(); }

    glm::dvec3 centreAt(std::size_t bunny, double t) const {
        const BunnyMotion& motion = bunnies_[bunny];
        const glm::dvec3 line = motion.start + motion.velocity * t;
        return {foldIntoRange(line.x, half_range_), foldIntoRange(line.y, half_range_),
                foldIntoRange(line.z, half_range_)};
    }

    void positionsAt(double t, TrianglePositions& out) const override {
        const std::size_t corners_per_bunny = corner_vertex_.size();
        out.resize(corners_per_bunny / 3 * bunnies_.size());
        for (std::size_t bunny = 0; bunny < bunnies_.size(); ++bunny) {
            const BunnyMotion& motion = bunnies_[bunny];
            // Constant angular velocity in world space: the spin is applied after the start pose.
            const glm::dquat spin = glm::angleAxis(motion.spin_rate * t, motion.spin_axis);
            const glm::dmat3 rotation = glm::mat3_cast(spin * motion.orientation);
            const glm::dvec3 centre = centreAt(bunny, t);
            const double wave_angle = kWaveTemporalFrequency * t + motion.phase;
            const double wave_cos = kBunnyWobble * std::cos(wave_angle);
            const double wave_sin = kBunnyWobble * std::sin(wave_angle);
            const std::size_t first = bunny * corners_per_bunny;
            for (std::size_t corner = 0; corner < corners_per_bunny; ++corner) {
                const RestVertex& vertex = vertices_[corner_vertex_[corner]];
                const double offset = vertex.sin_y * wave_cos + vertex.cos_y * wave_sin;
                const glm::dvec3 world =
                    rotation * (vertex.position + offset * vertex.normal) + centre;
                out.x[first + corner] = static_cast<float>(world.x);
                out.y[first + corner] = static_cast<float>(world.y);
                out.z[first + corner] = static_cast<float>(world.z);
            }
        }
    }

private:
    std::vector<RestVertex> vertices_;
    std::vector<uint32_t> corner_vertex_; // corner 3t+k of the rest mesh -> welded vertex
    std::vector<BunnyMotion> bunnies_;
    double half_range_; // the centres stay in [-half_range_, half_range_]^3
};

/// The embedded bunny scaled into the unit sphere around its bounding box centre, with corners
/// welded by identical position and area-weighted vertex normals.
struct RestMesh {
    std::vector<RestVertex> vertices;
    std::vector<uint32_t> corner_vertex;
};

Result<RestMesh> loadRestBunny() {
    Result<Scene> loaded = loadMeshFromMemory(kBunnyLowresObj, kBunnyLowresObjSize, "obj",
                                              "built-in mesh bunny-lowres.obj");
    if (!loaded)
        return Result<RestMesh>::failure(loaded.error);
    const TrianglePositions& positions = loaded.value->positions;
    const Bounds bounds = positions.bounds();
    if (positions.triangleCount() == 0 || !(bounds.radius() > 0))
        return Result<RestMesh>::failure("built-in mesh bunny-lowres.obj has no extent");
    const glm::dvec3 centre = toGlm(bounds.centre());
    const double scale = 1 / bounds.radius();

    RestMesh mesh;
    const std::size_t corner_count = positions.x.size();
    mesh.corner_vertex.resize(corner_count);
    std::map<std::array<float, 3>, uint32_t> vertex_of_position;
    for (std::size_t corner = 0; corner < corner_count; ++corner) {
        const std::array<float, 3> key = {positions.x[corner], positions.y[corner],
                                          positions.z[corner]};
        const auto [it, inserted] =
            vertex_of_position.emplace(key, static_cast<uint32_t>(mesh.vertices.size()));
        if (inserted) {
            const glm::dvec3 p = (glm::dvec3(key[0], key[1], key[2]) - centre) * scale;
            mesh.vertices.push_back({p, glm::dvec3(0), 0, 0});
        }
        mesh.corner_vertex[corner] = it->second;
    }
    // The unnormalised cross product has length twice the face area: summing it weights by area.
    for (std::size_t corner = 0; corner < corner_count; corner += 3) {
        RestVertex* v[3] = {&mesh.vertices[mesh.corner_vertex[corner]],
                            &mesh.vertices[mesh.corner_vertex[corner + 1]],
                            &mesh.vertices[mesh.corner_vertex[corner + 2]]};
        const glm::dvec3 face =
            glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
        for (RestVertex* vertex : v)
            vertex->normal += face;
    }
    for (RestVertex& vertex : mesh.vertices) {
        const double length = glm::length(vertex.normal);
        vertex.normal = length > 0 ? vertex.normal / length : glm::dvec3(0);
        vertex.sin_y = std::sin(kWaveSpatialFrequency * vertex.position.y);
        vertex.cos_y = std::cos(kWaveSpatialFrequency * vertex.position.y);
    }
    return Result<RestMesh>{std::move(mesh), {}};
}

glm::dvec3 randomUnitVector(SceneRandom& random) {
    return toGlm(random.unitVector());
}

} // namespace

Result<Scene> makeBunniesScene(const SceneParameters& parameters) {
    ParameterReader reader("builtin:bunnies", parameters);
    const auto count = static_cast<std::size_t>(reader.integer("n", 18, 1, 10'000));
    const uint64_t seed = reader.seed("seed", 1);
    if (std::string error = reader.error(); !error.empty())
        return Result<Scene>::failure(error);

    Result<RestMesh> rest = loadRestBunny();
    if (!rest)
        return Result<Scene>::failure("builtin:bunnies: " + rest.error);
    const std::size_t triangles_per_bunny = rest.value->corner_vertex.size() / 3;
    if (count * triangles_per_bunny > kMaxBuiltinTriangles)
        return Result<Scene>::failure("builtin:bunnies: parameter n=" + std::to_string(count) +
                                      " gives " + std::to_string(count * triangles_per_bunny) +
                                      " triangles, more than the limit of " +
                                      std::to_string(kMaxBuiltinTriangles));

    // The paper's density: 18 bunnies in a cube of side 6, the side growing with cbrt(n) so that
    // the density, and so the rate of contacts, stays the same for any n.
    const double cube_side = 6 * std::cbrt(count / 18.0);
    const double half_range = cube_side / 2 - 1; // where a unit bounding sphere's centre may go

    SceneRandom random(seed);
    const double first_hue = random.uniform();
    Scene scene;
    scene.name = "builtin:bunnies";
    std::vector<BunnyMotion> bunnies(count);
    for (std::size_t i = 0; i < count; ++i) {
        BunnyMotion& motion = bunnies[i];
        for (int axis = 0; axis < 3; ++axis)
            motion.start[axis] = random.uniform(-half_range, half_range);
        const std::array<double, 4> q = random.rotation();
        motion.orientation = glm::dquat(q[0], q[1], q[2], q[3]);
        motion.velocity = randomUnitVector(random) * random.uniform(kMinSpeed, kMaxSpeed);
        motion.spin_axis = randomUnitVector(random);
        motion.spin_rate = glm::radians(random.uniform(kMinSpinDegrees, kMaxSpinDegrees));
        motion.phase = random.uniform(0, 2 * std::numbers::pi);

        SceneObject object;
        object.name = "bunny_" + std::to_string(i);
        object.colour = SceneRandom::hueColour(first_hue + kGoldenFraction * i, kAlpha);
        object.transparent = true;
        object.first_triangle = static_cast<uint32_t>(i * triangles_per_bunny);
        object.triangle_count = static_cast<uint32_t>(triangles_per_bunny);
        scene.objects.push_back(std::move(object));
    }

    auto animation = std::make_shared<BunniesAnimation>(std::move(rest.value->vertices),
                                                        std::move(rest.value->corner_vertex),
                                                        std::move(bunnies), half_range);
    animation->positionsAt(0, scene.positions);
    // Framed over the motion (the first 10 s), as tightly as the bunnies allow; the bounce keeps
    // them in the cube, which they fill by then. Framed from each bunny's bounding sphere
    // (radius 1 + the wobble about its centre) at sampled times, not from its vertices: the
    // cost stays small at any count. 26 points around each centre at 1.13 times the radius
    // enclose the sphere (their polytope's inradius is 0.887 of its circumradius).
    std::vector<Vec3> around;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z)
                if (x || y || z)
                    around.push_back(normalized(Vec3{double(x), double(y), double(z)}) *
                                     (1.13 * (1 + kBunnyWobble)));
    const std::size_t per_time = count * around.size();
    const int times = int(std::clamp<std::size_t>(65536 / per_time, 2, 32));
    std::vector<Vec3> points;
    points.reserve(per_time * std::size_t(times));
    for (int i = 0; i < times; ++i) {
        const double t = 299 * kFrameInterval * i / (times - 1);
        for (std::size_t bunny = 0; bunny < count; ++bunny) {
            const glm::dvec3 c = animation->centreAt(bunny, t);
            for (const Vec3& offset : around)
                points.push_back(Vec3{c.x, c.y, c.z} + offset);
        }
    }
    scene.camera = framingCamera(points);
    scene.animation = std::move(animation);
    return Result<Scene>{std::move(scene), {}};
}

bool bunnyCentreAt(const Animation& animation, std::size_t bunny, double t, Vec3& centre) {
    const auto* bunnies = dynamic_cast<const BunniesAnimation*>(&animation);
    if (!bunnies || bunny >= bunnies->bunnyCount())
        return false;
    const glm::dvec3 c = bunnies->centreAt(bunny, t);
    centre = {c.x, c.y, c.z};
    return true;
}

} // namespace vissort::detail
