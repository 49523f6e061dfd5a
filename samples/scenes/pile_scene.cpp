// The `pile` scene, for collision benchmarks: thousands of small bodies, rigid ellipsoids and
// capsules and deforming blobs, falling into a loose pile on a floor and settling there, so that
// early frames move a lot and later frames are nearly static (coherent) while the blobs keep
// deforming and the contacts between neighbours stay.
//
// Every frame is a pure function of t, as the bunnies' are: each body bounces on its rest
// position with a damped bounce, drop exp(-t / tau) |cos(omega t)|, and untumbles into its rest
// orientation by an angle decaying as exp(-t / tau). No state is stepped, so any frame can be
// asked for in any order and the result is the same.

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scenes/builtin_scenes.h"
#include "scenes/scene_parameters.h"
#include "scenes/solid_shapes.h"

namespace vissort::detail {
namespace {

// Every body is one tube from pole to pole (solid_shapes.h), so all share one topology: the
// same corner -> vertex table, whatever their shape.
constexpr int kSegments = 16;
constexpr int kRings = 8;
constexpr std::size_t kVerticesPerBody = kSegments * kRings + 2;  // the rings and two poles
constexpr std::size_t kTrianglesPerBody = 2 * kSegments * kRings; // two fans, kRings - 1 bands
constexpr std::size_t kCornersPerBody = 3 * kTrianglesPerBody;

constexpr double kMinRadius = 0.4, kMaxRadius = 0.6;           // of a body's bounding sphere, units
constexpr double kMinEllipsoidAxis = 0.6;                      // of the radius; the largest is 1
constexpr double kCapsuleCapRadius = 0.5;                      // of the radius
constexpr double kCapsuleHalfStraight = 1 - kCapsuleCapRadius; // so the length is 2 radii
constexpr double kBlobWave = 0.08;                             // of the radius, along the radius
constexpr double kWaveSpatialFrequency = 3;                    // radians per unit-sphere unit of y
constexpr double kWaveTemporalFrequency = 2;                   // radians per second
constexpr double kMaxReach = kMaxRadius * (1 + kBlobWave);     // the largest bounding sphere

// Less than a typical body's diameter (an ellipsoid's mean axis is 0.8 of a mean radius 0.5),
// so that resting neighbours overlap a little: 2 to 6 contacts a body once settled.
constexpr double kSpacing = 0.8;
constexpr double kJitter = 0.15 * kSpacing; // per axis, of the rest positions
constexpr double kColumnsPerCubeRoot = 1.4; // columns a side per cbrt(n): wider than high
constexpr double kSettleTime = 1.5;         // tau, seconds: e^-1 of the bounce and tumble
constexpr double kMinDrop = 1.5, kDropPerLayer = 0.5, kMaxExtraDrop = 1; // units above rest
constexpr double kMinBounceRate = 3, kMaxBounceRate = 5; // omega, radians per second
constexpr double kMinTumble = 0.5 * std::numbers::pi, kMaxTumble = std::numbers::pi; // radians
constexpr float kAlpha = 0.5f;
constexpr double kGoldenFraction = 0.6180339887498949; // spreads successive hues evenly

enum class BodyKind : uint8_t { ellipsoid, capsule, blob };

glm::dvec3 toGlm(const Vec3& v) {
    return {v.x, v.y, v.z};
}

/// One body: its shape (a unit shape scaled per axis) and its rest pose and settling motion.
struct PileBody {
    BodyKind kind;
    glm::dvec3 scale;            // of the unit shape, per local axis
    glm::dvec3 rest_centre;      // where it settles, y up
    glm::dquat rest_orientation; // the orientation it settles into
    glm::dvec3 tumble_axis;      // unit, world space
    double tumble_angle;         // at t = 0, radians, decaying to 0
    double drop;                 // height above the rest centre at t = 0
    double bounce_rate;          // omega, radians per second
    double wave_phase;           // of a blob's deformation wave, radians
};

/// The shapes every body is made from, as welded vertices of the shared tube topology.
struct UnitShapes {
    std::vector<uint32_t> corner_vertex;                      // corner 3t+k of a body -> its vertex
    std::array<glm::dvec3, kVerticesPerBody> sphere, capsule; // the radius 1
    // sin and cos of kWaveSpatialFrequency * y of each sphere vertex: a blob's wave
    // sin(3y + 2t + phase) is then sin_y cos(2t + phase) + cos_y sin(2t + phase), with no sine
    // per vertex per frame.
    std::array<double, kVerticesPerBody> sin_y, cos_y;
};

class PileAnimation final : public Animation {
public:
    PileAnimation(UnitShapes shapes, std::vector<PileBody> bodies)
        : shapes_(std::move(shapes)), bodies_(std::move(bodies)) {}

    glm::dvec3 centreAt(const PileBody& body, double t) const {
        const double decay = std::exp(-t / kSettleTime);
        // |cos| bounces: the body meets its rest height at every zero, each bounce lower.
        const double height = body.drop * decay * std::abs(std::cos(body.bounce_rate * t));
        return body.rest_centre + glm::dvec3(0, height, 0);
    }

    void positionsAt(double t, TrianglePositions& out) const override {
        out.resize(kTrianglesPerBody * bodies_.size());
        const double decay = std::exp(-t / kSettleTime);
        const double wave_angle_base = kWaveTemporalFrequency * t;
        // Per frame per body: its vertices moved once (here, on the stack), then scattered to
        // its corners; no allocation.
        std::array<glm::dvec3, kVerticesPerBody> world;
        for (std::size_t index = 0; index < bodies_.size(); ++index) {
            const PileBody& body = bodies_[index];
            const glm::dquat tumble = glm::angleAxis(body.tumble_angle * decay, body.tumble_axis);
            glm::dmat3 transform = glm::mat3_cast(tumble * body.rest_orientation);
            for (int axis = 0; axis < 3; ++axis)
                transform[axis] *= body.scale[axis]; // column axis: scale, then rotate
            const glm::dvec3 centre = centreAt(body, t);
            const auto& unit = body.kind == BodyKind::capsule ? shapes_.capsule : shapes_.sphere;
            if (body.kind == BodyKind::blob) {
                const double wave_cos = kBlobWave * std::cos(wave_angle_base + body.wave_phase);
                const double wave_sin = kBlobWave * std::sin(wave_angle_base + body.wave_phase);
                // Along the radius of the unit sphere: the blob stays star-shaped about its
                // centre, so closed and wound outwards.
                for (std::size_t v = 0; v < kVerticesPerBody; ++v) {
                    const double radial =
                        1 + shapes_.sin_y[v] * wave_cos + shapes_.cos_y[v] * wave_sin;
                    world[v] = transform * (unit[v] * radial) + centre;
                }
            } else {
                for (std::size_t v = 0; v < kVerticesPerBody; ++v)
                    world[v] = transform * unit[v] + centre;
            }
            const std::size_t first = index * kCornersPerBody;
            for (std::size_t corner = 0; corner < kCornersPerBody; ++corner) {
                const glm::dvec3& p = world[shapes_.corner_vertex[corner]];
                out.x[first + corner] = static_cast<float>(p.x);
                out.y[first + corner] = static_cast<float>(p.y);
                out.z[first + corner] = static_cast<float>(p.z);
            }
        }
    }

    /// The vertical segment the body's centre moves along (it starts at the top, rests at the
    /// bottom) and its bounding sphere's radius: what the camera must see.
    struct Sweep {
        glm::dvec3 top, bottom;
        double reach;
    };
    Sweep sweepOf(std::size_t index) const {
        const PileBody& body = bodies_[index];
        return {centreAt(body, 0), body.rest_centre, reachOf(body)};
    }

    /// The radius of the body's bounding sphere about its centre, deformation included.
    static double reachOf(const PileBody& body) {
        const double largest_axis = std::max({body.scale.x, body.scale.y, body.scale.z});
        return body.kind == BodyKind::blob ? largest_axis * (1 + kBlobWave) : largest_axis;
    }

private:
    UnitShapes shapes_;
    std::vector<PileBody> bodies_;
};

/// A pole-to-pole tube along +y: rings at (y, radius) from the south pole up to the north pole.
/// normal x binormal = z x x = +y, the way the tube runs, so it is wound outwards.
std::vector<SolidTriangle> poleToPoleTube(std::span<const std::array<double, 2>> rings,
                                          double south_pole, double north_pole) {
    std::vector<Ring> tube;
    for (const auto& [y, radius] : rings)
        tube.push_back({glm::dvec3(0, y, 0), glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), radius});
    std::vector<SolidTriangle> triangles;
    addTube(triangles, tube, kSegments, glm::dvec3(0, south_pole, 0), glm::dvec3(0, north_pole, 0));
    return triangles;
}

/// The unit sphere and the unit capsule (length 2, radius kCapsuleCapRadius), welded. Both
/// come from addTube with the same ring and segment counts, so corner k is the same vertex of
/// both: the sphere's distinct corners define the table, the capsule's fill its vertices.
UnitShapes makeUnitShapes() {
    std::array<std::array<double, 2>, kRings> sphere_rings, capsule_rings;
    for (int i = 0; i < kRings; ++i) {
        // Evenly in latitude from the south pole: no ring at either pole.
        const double polar = std::numbers::pi * (i + 1) / (kRings + 1);
        sphere_rings[i] = {-std::cos(polar), std::sin(polar)};
        // The capsule: kRings / 2 rings on each dome, the last of the lower and the first of
        // the upper on the equators at -+kCapsuleHalfStraight, the straight part between them.
        const bool lower = i < kRings / 2;
        const double dome_polar =
            std::numbers::pi / 2 *
            (lower ? double(i + 1) / (kRings / 2) : 1 + double(i - kRings / 2) / (kRings / 2));
        const double shift = lower ? -kCapsuleHalfStraight : kCapsuleHalfStraight;
        capsule_rings[i] = {shift - kCapsuleCapRadius * std::cos(dome_polar),
                            kCapsuleCapRadius * std::sin(dome_polar)};
    }
    const std::vector<SolidTriangle> sphere = poleToPoleTube(sphere_rings, -1, 1);
    const double capsule_end = kCapsuleHalfStraight + kCapsuleCapRadius;
    const std::vector<SolidTriangle> capsule =
        poleToPoleTube(capsule_rings, -capsule_end, capsule_end);

    UnitShapes shapes;
    shapes.corner_vertex.resize(kCornersPerBody);
    std::map<std::array<double, 3>, uint32_t> vertex_of_position;
    for (std::size_t corner = 0; corner < kCornersPerBody; ++corner) {
        const glm::dvec3& p = sphere[corner / 3][corner % 3];
        const auto [it, inserted] = vertex_of_position.emplace(
            std::array<double, 3>{p.x, p.y, p.z}, static_cast<uint32_t>(vertex_of_position.size()));
        assert(it->second < kVerticesPerBody);
        shapes.corner_vertex[corner] = it->second;
        shapes.sphere[it->second] = p;
        shapes.capsule[it->second] = capsule[corner / 3][corner % 3];
    }
    assert(vertex_of_position.size() == kVerticesPerBody);
    for (std::size_t v = 0; v < kVerticesPerBody; ++v) {
        shapes.sin_y[v] = std::sin(kWaveSpatialFrequency * shapes.sphere[v].y);
        shapes.cos_y[v] = std::cos(kWaveSpatialFrequency * shapes.sphere[v].y);
    }
    return shapes;
}

} // namespace

Result<Scene> makePileScene(const SceneParameters& parameters) {
    ParameterReader reader("builtin:pile", parameters);
    const auto count = static_cast<std::size_t>(reader.integer("n", 1000, 1, 100'000));
    const uint64_t seed = reader.seed("seed", 1);
    if (std::string error = reader.error(); !error.empty())
        return Result<Scene>::failure(error);
    if (count * kTrianglesPerBody > kMaxBuiltinTriangles)
        return Result<Scene>::failure("builtin:pile: parameter n=" + std::to_string(count) +
                                      " gives " + std::to_string(count * kTrianglesPerBody) +
                                      " triangles, more than the limit of " +
                                      std::to_string(kMaxBuiltinTriangles));

    UnitShapes shapes = makeUnitShapes();
    // A square footprint of columns, about twice as wide as the pile is high.
    const auto columns = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::lround(kColumnsPerCubeRoot * std::cbrt(double(count)))));
    const std::size_t per_layer = columns * columns;
    const double half_width = (double(columns) - 1) / 2 * kSpacing;

    SceneRandom random(seed);
    const double first_hue = random.uniform();
    Scene scene;
    scene.name = "builtin:pile";
    std::vector<PileBody> bodies(count);
    for (std::size_t i = 0; i < count; ++i) {
        PileBody& body = bodies[i];
        // Every value is drawn for every body, whatever its kind, so that one body's kind does
        // not shift the random numbers of the bodies after it.
        body.kind = static_cast<BodyKind>(random.index(3));
        const double radius = random.uniform(kMinRadius, kMaxRadius);
        glm::dvec3 axes;
        for (int axis = 0; axis < 3; ++axis)
            axes[axis] = random.uniform(kMinEllipsoidAxis, 1);
        body.scale = body.kind == BodyKind::ellipsoid ? radius * axes : glm::dvec3(radius);

        const std::size_t layer = i / per_layer, in_layer = i % per_layer;
        const glm::dvec3 grid((double(in_layer % columns)) * kSpacing - half_width,
                              kMaxReach + double(layer) * kSpacing,
                              (double(in_layer / columns)) * kSpacing - half_width);
        glm::dvec3 jitter;
        for (int axis = 0; axis < 3; ++axis)
            jitter[axis] = random.uniform(-kJitter, kJitter);
        body.rest_centre = grid + jitter;
        // On the floor (y = 0), not through it: the bounding sphere stays above it.
        body.rest_centre.y = std::max(body.rest_centre.y, PileAnimation::reachOf(body));

        const std::array<double, 4> q = random.rotation();
        body.rest_orientation = glm::dquat(q[0], q[1], q[2], q[3]);
        body.tumble_axis = toGlm(random.unitVector());
        body.tumble_angle = random.uniform(kMinTumble, kMaxTumble);
        // Higher layers start higher, so the pile falls in order and rises at the start.
        body.drop = kMinDrop + kDropPerLayer * double(layer) + random.uniform(0, kMaxExtraDrop);
        body.bounce_rate = random.uniform(kMinBounceRate, kMaxBounceRate);
        body.wave_phase = random.uniform(0, 2 * std::numbers::pi);

        SceneObject object;
        object.name = "body_" + std::to_string(i);
        object.colour = SceneRandom::hueColour(first_hue + kGoldenFraction * double(i), kAlpha);
        object.transparent = true;
        object.first_triangle = static_cast<uint32_t>(i * kTrianglesPerBody);
        object.triangle_count = static_cast<uint32_t>(kTrianglesPerBody);
        scene.objects.push_back(std::move(object));
    }

    auto animation = std::make_shared<PileAnimation>(std::move(shapes), std::move(bodies));
    animation->positionsAt(0, scene.positions);
    // Framed over the whole fall: each body's centre only moves down the segment from its start
    // to its rest position, so the cubes around its bounding sphere at both ends hold every
    // frame of it (a view's frustum is convex). 16 points a body: the cost stays small.
    std::vector<Vec3> points;
    points.reserve(16 * count);
    for (std::size_t i = 0; i < count; ++i) {
        const PileAnimation::Sweep sweep = animation->sweepOf(i);
        for (const glm::dvec3& end : {sweep.top, sweep.bottom})
            for (int corner = 0; corner < 8; ++corner)
                points.push_back(Vec3{end.x + (corner & 1 ? sweep.reach : -sweep.reach),
                                      end.y + (corner & 2 ? sweep.reach : -sweep.reach),
                                      end.z + (corner & 4 ? sweep.reach : -sweep.reach)});
    }
    scene.camera = framingCamera(points);
    scene.animation = std::move(animation);
    return Result<Scene>{std::move(scene), {}};
}

} // namespace vissort::detail
