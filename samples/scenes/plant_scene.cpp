// The `plant` scene: rows of process-plant equipment (a pipe rack, a tank, a pump and the steel
// that carries them) stacked one behind another on a concrete floor, after the power plant model
// of Govindaraju et al., "Interactive visibility ordering and transparency computations among
// geometric primitives in complex environments" (I3D 2005). Pipes and tanks are transparent,
// steel and concrete opaque; every part is a closed mesh kept clear of every other part.
//
// The depth complexity is controlled by the layout. Seen from the front (along z) the parts of a
// row never overlap: pipe levels are nested, each wider than the one below and carried by columns
// outside the spans of the lower levels, and the tank stands beside the rack. A ray running along
// the rows therefore crosses about one part per row. Every row's top pipe (the header) is a plain
// cylinder with its axis at the camera's height, spanning x = 0, so the camera's horizontal ray
// through x = 0 crosses every header: the maximum depth complexity is about 2 * layers.

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/builtin_scenes.h"
#include "scenes/scene_parameters.h"
#include "scenes/solid_shapes.h"

namespace vissort::detail {
namespace {

using glm::dvec3;

// Units are metres; y is up, the floor's top is y = 0 and rows stack along -z, away from the
// default camera. Row k is centred on z = ((layers - 1) / 2 - k) * kRowSpacing.
constexpr uint32_t kMaxLayers = 1000;
constexpr double kRowSpacing = 4.0;  // a row is at most 2 * 1.45 deep: 1.1 or more between rows
constexpr double kMaxRowShift = 1.0; // each row moves sideways by up to this, so rows differ

// Gaps between a part and what it rests on. Besides keeping parts apart (0.05 is 1% of a 5 m
// tank, 20% of a 0.24 m column), they stop a ray of the default view from passing from a pipe
// into its beam, or from a beam into its column, which would add two surfaces in one row: that
// takes a slope of gap / depth crossed (0.06 / 0.2, 0.1 / 0.32), while the default view's rays
// descend by at most 0.2 where they reach a beam (the eye is 22.8 away at 1 layer, farther with
// more, 5.4 high; the lowest beam top is at 1.08).
constexpr double kFloorGap = 0.05; // columns, pump and tank above the floor
constexpr double kShoeGap = 0.06;  // a pipe above its beam
constexpr double kCapGap = 0.1;    // a beam above its column
// Between parts side by side seen from the front, so that a ray along the rows that passes one
// part's edge does not also clip its neighbour in the same row.
constexpr double kClearance = 0.3;

// Pipe levels: axis heights of the three lower levels (each jittered) and of the header.
constexpr double kLevelHeights[3] = {1.5, 2.7, 3.9};
constexpr double kLevelJitter = 0.08;
constexpr double kHeaderHeight = 5.4; // also the camera's height
constexpr double kMinPipeRadius = 0.14, kMaxPipeRadius = 0.28;
constexpr double kMinHeaderRadius = 0.32, kMaxHeaderRadius = 0.45;
// A flange (solid_shapes.h) is a collar on a lower level's pipe (the header has none: a collar
// makes a pipe non-convex, and a ray grazing one crosses the pipe's surface four times). Even the
// largest collars leave 0.27 between one level's band and the next: 1.58 + 1.3 * 0.28 + 0.02 = 1.96
// < 2.62 - 0.38 = 2.24; 4.36 < 5.4 - 0.45.
constexpr int kFlangesPerPipe = 2;
constexpr double kOverhang = 0.45;      // a pipe runs on this far past its outer supports
constexpr double kSupportKeepOut = 0.3; // no flange this close to a support's beam

// T-supports: a square column and, on top of it, a beam running along z under the pipe, as wide
// as the column so that no ray reaches the column's top past the beam's side.
constexpr double kColumnHalf = 0.12;
constexpr double kBeamHalfWidth = 0.13, kBeamHalfDepth = 0.2, kBeamHeight = 0.18;

// Level 0 ends in an elbow of bend radius 2 r turning towards the camera (+z), then a short
// stub. A pump stands under the middle of level 0, far enough below it (0.5 or more) that no ray
// passes from the pipe into the pump.
constexpr double kStubLength = 0.5;
constexpr double kPumpHalfWidth = 0.35, kPumpHalfDepth = 0.4, kPumpHeight = 0.5;

// The tank: a vertical cylinder standing on the floor, with a dome or a cone on top.
constexpr double kMinTankRadius = 1.1, kMaxTankRadius = 1.45;
constexpr double kMinTankHeight = 3.6, kMaxTankHeight = 5.6;
constexpr double kDomeHeight = 0.45, kConeHeight = 0.35; // times the tank's radius

constexpr double kFloorThickness = 0.3, kFloorMargin = 1.0;

// Tessellation.
constexpr int kPipeSegments = 24, kTankSegments = 32, kBendSteps = 8, kDomeRings = 6;

// Upper bound of a row's triangles: a tube of R rings has 2 n (R - 1) + 2 n triangles. A lower
// pipe has 2 + 4 f rings (4 per flange), level 0 kBendSteps + 1 more for its elbow and stub, the
// header 2; the domed tank kDomeRings + 1; then 17 boxes.
constexpr std::size_t tubeTriangles(int rings, int segments) {
    return std::size_t(2) * segments * rings;
}
constexpr std::size_t kMaxRowTriangles =
    tubeTriangles(2, kPipeSegments) + 2 * tubeTriangles(2 + 4 * kFlangesPerPipe, kPipeSegments) +
    tubeTriangles(2 + 4 * kFlangesPerPipe + kBendSteps + 1, kPipeSegments) +
    tubeTriangles(kDomeRings + 1, kTankSegments) + 17 * 12;
static_assert(kMaxLayers * kMaxRowTriangles + 12 <= kMaxBuiltinTriangles,
              "the largest plant must stay under the built-in scenes' triangle limit");

// The tanks take the first three vessel colours (solid_shapes.h).
constexpr uint32_t kTankColourCount = 3;

/// A horizontal pipe run along x with its flanges, on a T-support near each end.
struct PipeRun {
    double height = 0, radius = 0;
    double start = 0, end = 0;                  // x of the pipe's ends (level 0: of the elbow)
    double support_left = 0, support_right = 0; // x of the supports' axes
};

/// Rings of a straight run along +x from `start` to `end`, with `flanges` collars placed at random
/// between the supports. The last ring is at `end`.
void straightRings(std::vector<Ring>& rings, const PipeRun& run, int flanges, SceneRandom& random) {
    const dvec3 normal{0, 1, 0}, binormal{0, 0, 1}; // y x z = x, the direction of the run
    const auto ring = [&](double x, double radius) {
        rings.push_back({{x, run.height, 0}, normal, binormal, radius});
    };
    ring(run.start, run.radius);
    // Evenly spaced between the supports' keep-outs, each moved by up to a quarter of the spacing:
    // collars stay at least half a spacing apart and never reach a beam.
    const double low = run.support_left + kBeamHalfWidth + kSupportKeepOut;
    const double high = run.support_right - kBeamHalfWidth - kSupportKeepOut;
    const double spacing = (high - low) / (flanges + 1);
    for (int f = 0; f < flanges; ++f) {
        const double x = low + (f + 1) * spacing + random.uniform(-0.25, 0.25) * spacing;
        for (const auto& [at, radius] : flangeRings(x, run.radius))
            ring(at, radius);
    }
    ring(run.end, run.radius);
}

/// A column and the beam on top of it carrying a pipe of `run` at x = `x`.
void addSupport(std::vector<SolidPart>& parts, const PipeRun& run, double x, int index,
                const std::string& prefix) {
    const double beam_top = run.height - run.radius - kShoeGap;
    const double beam_bottom = beam_top - kBeamHeight;
    const double column_top = beam_bottom - kCapGap;
    SolidPart column{prefix + "column_" + std::to_string(index), kColumnColour, false, {}};
    addBox(column.triangles, {x - kColumnHalf, kFloorGap, -kColumnHalf},
           {x + kColumnHalf, column_top, kColumnHalf});
    parts.push_back(std::move(column));
    SolidPart beam{prefix + "beam_" + std::to_string(index), kGirderColour, false, {}};
    addBox(beam.triangles, {x - kBeamHalfWidth, beam_bottom, -kBeamHalfDepth},
           {x + kBeamHalfWidth, beam_top, kBeamHalfDepth});
    parts.push_back(std::move(beam));
}

/// The parts of one row in its own frame, left to right seen from the front: the nested pipe
/// levels (level 0 innermost, with the pump under it and an elbow at its end), then the tank.
std::vector<SolidPart> makeRow(uint32_t row, SceneRandom& random) {
    const std::string prefix = "row" + std::to_string(row) + "_";
    std::vector<SolidPart> parts;
    const auto pipeColour = [&random] {
        const uint32_t colour = random.index(static_cast<uint32_t>(std::size(kPipeColours)));
        return pick(kPipeColours[colour], static_cast<float>(random.uniform(0.35, 0.6)));
    };

    PipeRun runs[4];
    for (int level = 0; level < 4; ++level) {
        PipeRun& run = runs[level];
        if (level < 3) {
            run.height = kLevelHeights[level] + random.uniform(-kLevelJitter, kLevelJitter);
            run.radius = random.uniform(kMinPipeRadius, kMaxPipeRadius);
        } else {
            run.height = kHeaderHeight;
            run.radius = random.uniform(kMinHeaderRadius, kMaxHeaderRadius);
        }
    }

    // Level 0: its elbow bends about (end, height, 2 r) into a stub along +z whose axis is at
    // x = end + 2 r, so the stub's side reaches x = end + 3 r.
    PipeRun& low = runs[0];
    low.start = -random.uniform(3.4, 4.2);
    low.end = random.uniform(0.4, 1.2);
    low.support_left = low.start + kOverhang;
    low.support_right = low.end - kOverhang;
    const double bend_radius = 2 * low.radius;
    double left_edge = low.start;
    double right_edge = low.end + bend_radius + low.radius;

    // Each upper level's supports stand kClearance outside everything below it, so seen from
    // the front a column never crosses a lower pipe; the run overhangs its supports.
    for (int level = 1; level < 4; ++level) {
        PipeRun& run = runs[level];
        run.support_left = left_edge - kClearance - kColumnHalf;
        run.support_right = right_edge + kClearance + kColumnHalf;
        run.start = run.support_left - kOverhang;
        run.end = run.support_right + kOverhang;
        left_edge = run.start;
        right_edge = run.end;
    }

    int support = 0;
    for (int level = 0; level < 4; ++level) {
        const PipeRun& run = runs[level];
        std::vector<Ring> rings;
        straightRings(rings, run, level == 3 ? 0 : kFlangesPerPipe, random);
        if (level == 0) {
            // The elbow: the run's direction turns from +x to +z about the bend centre; the
            // normal stays +y and the binormal turns with the run, so the rings never twist.
            const dvec3 bend_centre{run.end, run.height, bend_radius};
            const dvec3 up{0, 1, 0};
            dvec3 binormal{0, 0, 1};
            for (int step = 1; step <= kBendSteps; ++step) {
                const double turn = std::numbers::pi / 2 * step / kBendSteps;
                binormal = {-std::sin(turn), 0, std::cos(turn)};
                rings.push_back({bend_centre - bend_radius * binormal, up, binormal, run.radius});
            }
            rings.push_back(
                {rings.back().centre + dvec3(0, 0, kStubLength), up, binormal, run.radius});
        }
        SolidPart pipe{prefix + "pipe_" + std::to_string(level), pipeColour(), true, {}};
        addTube(pipe.triangles, rings, kPipeSegments, rings.front().centre, rings.back().centre);
        parts.push_back(std::move(pipe));
        addSupport(parts, run, run.support_left, support++, prefix);
        addSupport(parts, run, run.support_right, support++, prefix);
    }

    // Level 0's supports are at least 2.9 apart: the pump keeps kClearance from both columns.
    const double pump_x = (low.support_left + low.support_right) / 2;
    SolidPart pump{prefix + "pump", kEquipmentColour, false, {}};
    addBox(pump.triangles, {pump_x - kPumpHalfWidth, kFloorGap, -kPumpHalfDepth},
           {pump_x + kPumpHalfWidth, kFloorGap + kPumpHeight, kPumpHalfDepth});
    parts.push_back(std::move(pump));

    // The tank, kClearance to the right of the header's end.
    const double radius = random.uniform(kMinTankRadius, kMaxTankRadius);
    const double height = random.uniform(kMinTankHeight, kMaxTankHeight);
    const bool domed = random.uniform() < 0.5;
    const double tank_x = right_edge + kClearance + radius;
    const dvec3 normal{0, 0, 1}, binormal{1, 0, 0}; // z x x = y: the tank runs upwards
    std::vector<Ring> rings;
    rings.push_back({{tank_x, kFloorGap, 0}, normal, binormal, radius});
    rings.push_back({{tank_x, kFloorGap + height, 0}, normal, binormal, radius});
    dvec3 top{tank_x, kFloorGap + height + kConeHeight * radius, 0};
    if (domed) {
        // An ellipsoidal head: latitude rings up to the pole.
        const double dome = kDomeHeight * radius;
        for (int k = 1; k < kDomeRings; ++k) {
            const double latitude = std::numbers::pi / 2 * k / kDomeRings;
            rings.push_back({{tank_x, kFloorGap + height + dome * std::sin(latitude), 0},
                             normal,
                             binormal,
                             radius * std::cos(latitude)});
        }
        top.y = kFloorGap + height + dome;
    }
    const uint32_t colour = random.index(kTankColourCount);
    SolidPart tank{prefix + "tank",
                   pick(kVesselColours[colour], static_cast<float>(random.uniform(0.3, 0.45))),
                   true,
                   {}};
    addTube(tank.triangles, rings, kTankSegments, rings.front().centre, top);
    parts.push_back(std::move(tank));
    return parts;
}

/// Appends a part as one object, moved to the row's place: x -> (mirrored ? -x : x) + shift,
/// z -> z + row's z. A mirrored part has its triangles' corners swapped to still face outwards.
void addObject(Scene& scene, SolidPart&& part, double shift, double z, bool mirrored) {
    SceneObject object;
    object.name = std::move(part.name);
    object.colour = part.colour;
    object.transparent = part.transparent;
    object.first_triangle = static_cast<uint32_t>(scene.positions.x.size() / 3);
    object.triangle_count = static_cast<uint32_t>(part.triangles.size());
    TrianglePositions& out = scene.positions;
    for (SolidTriangle& triangle : part.triangles) {
        if (mirrored)
            std::swap(triangle[1], triangle[2]);
        for (const dvec3& p : triangle) {
            out.x.push_back(static_cast<float>((mirrored ? -p.x : p.x) + shift));
            out.y.push_back(static_cast<float>(p.y));
            out.z.push_back(static_cast<float>(p.z + z));
        }
    }
    scene.objects.push_back(std::move(object));
}

/// From the front at the headers' height, looking at the floor-level middle of the plant from
/// the nearest distance (in 2% steps) that keeps every corner of the bounds inside 95% of a
/// square 45-degree view.
CameraSpec framePlant(const Bounds& bounds) {
    CameraSpec camera;
    camera.fov_degrees = 45.0;
    camera.up = {0, 1, 0};
    camera.target = {0, 0.4 * kHeaderHeight, bounds.centre().z};
    const double reach = 0.95 * std::tan(camera.fov_degrees / 2 * std::numbers::pi / 180);
    const dvec3 target{camera.target.x, camera.target.y, camera.target.z};
    for (double distance = 1.0;; distance *= 1.02) {
        const dvec3 eye{0, kHeaderHeight, bounds.max.z + distance};
        const dvec3 forward = glm::normalize(target - eye);
        const dvec3 right = glm::normalize(glm::cross(forward, dvec3(0, 1, 0)));
        const dvec3 up = glm::cross(right, forward);
        bool inside = true;
        for (int i = 0; i < 8 && inside; ++i) {
            const dvec3 corner{i & 1 ? bounds.max.x : bounds.min.x,
                               i & 2 ? bounds.max.y : bounds.min.y,
                               i & 4 ? bounds.max.z : bounds.min.z};
            const dvec3 d = corner - eye;
            const double depth = glm::dot(d, forward);
            inside = depth > 0 && std::abs(glm::dot(d, right)) <= depth * reach &&
                     std::abs(glm::dot(d, up)) <= depth * reach;
        }
        if (inside) {
            camera.eye = {eye.x, eye.y, eye.z};
            return camera;
        }
    }
}

} // namespace

Result<Scene> makePlantScene(const SceneParameters& parameters) {
    ParameterReader reader("builtin:plant", parameters);
    const auto layers = static_cast<uint32_t>(reader.integer("layers", 8, 1, kMaxLayers));
    const uint64_t seed = reader.seed("seed", 1);
    if (std::string error = reader.error(); !error.empty())
        return Result<Scene>::failure(error);

    SceneRandom random(seed);
    Scene scene;
    scene.name = "builtin:plant";
    scene.positions.x.reserve(std::size_t{layers} * kMaxRowTriangles * 3);
    scene.positions.y.reserve(std::size_t{layers} * kMaxRowTriangles * 3);
    scene.positions.z.reserve(std::size_t{layers} * kMaxRowTriangles * 3);

    // The floor comes first; its size is known once the rows are placed, so it is written last
    // into the 12 triangles kept for it here.
    scene.objects.push_back({"floor", kConcreteColour, false, 0, 12});
    scene.positions.resize(12);
    double min_x = 0, max_x = 0;
    for (uint32_t row = 0; row < layers; ++row) {
        const double z = ((layers - 1) / 2.0 - row) * kRowSpacing;
        // The header spans at least x = -6 to 3.4 in the row's frame, so mirrored or not and
        // shifted by up to 1 it still covers x = -2.4 to 2.4: the camera's axis.
        const bool mirrored = random.uniform() < 0.5;
        const double shift = random.uniform(-kMaxRowShift, kMaxRowShift);
        std::vector<SolidPart> parts = makeRow(row, random);
        std::size_t row_triangles = 0;
        for (SolidPart& part : parts) {
            for (const SolidTriangle& triangle : part.triangles)
                for (const dvec3& p : triangle) {
                    min_x = std::min(min_x, (mirrored ? -p.x : p.x) + shift);
                    max_x = std::max(max_x, (mirrored ? -p.x : p.x) + shift);
                }
            row_triangles += part.triangles.size();
            addObject(scene, std::move(part), shift, z, mirrored);
        }
        assert(row_triangles <= kMaxRowTriangles);
        (void)row_triangles;
    }

    // Under every row, reaching 2.5 beyond the first and last rows' centres (a row reaches at
    // most 1.45 either side of its centre: the largest tank's radius).
    const double front = (layers - 1) / 2.0 * kRowSpacing + kRowSpacing / 2 + 0.5;
    std::vector<SolidTriangle> floor;
    addBox(floor, {min_x - kFloorMargin, -kFloorThickness, -front},
           {max_x + kFloorMargin, 0, front});
    for (std::size_t t = 0; t < floor.size(); ++t)
        for (int corner = 0; corner < 3; ++corner) {
            scene.positions.x[3 * t + corner] = static_cast<float>(floor[t][corner].x);
            scene.positions.y[3 * t + corner] = static_cast<float>(floor[t][corner].y);
            scene.positions.z[3 * t + corner] = static_cast<float>(floor[t][corner].z);
        }

    scene.camera = framePlant(scene.positions.bounds());
    return Result<Scene>{std::move(scene), {}};
}

} // namespace vissort::detail
