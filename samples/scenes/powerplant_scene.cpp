// The `powerplant` scene: a compact multi-storey process plant with the proportions of the power
// plant benchmark of Govindaraju et al., "Interactive visibility ordering and transparency
// computations among geometric primitives in complex environments" (I3D 2005), section 5.4:
// about 730K opaque and 90K transparent triangles, depth complexity 5 to 12 from inside, and a
// walkthrough along its aisles and up a stair (the scene's own camera path, `--path scene`).
//
// The layout is a grid of 8 m bays, three storeys of 6 m. Rows of bays along x alternate between
// equipment rows (tanks, boilers, heat exchangers, pump skids on the floor, risers through the
// gratings) and aisle rows (a walkway, and the stairs). Overhead, every storey carries the same
// bands, bottom to top: pipe runs along z, rack beams carrying pipe runs along x, the runs along
// x, girders along z, girders along x, then the grating of the storey above. Each kind of part
// keeps to its band and to its lanes inside a bay, so no two parts meet: every gap is at least
// kGap (tests/scene_library/powerplant_scene_tests.cpp checks it triangle by triangle). Columns
// stand at the bays' corners, walls with windows close the outside, a slab lies under it all and
// a roof over it. Pipe runs have flanges in every bay and end in elbows (down for runs along x,
// up for runs along z); risers climb from one storey through the grating into the next and turn
// along x there.

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/builtin_scenes.h"
#include "scenes/scene_parameters.h"
#include "scenes/solid_shapes.h"

namespace vissort::detail {
namespace {

using glm::dvec3;

// Metres; y is up, the ground slab's top is y = 0. Bay (i, j) covers x in [8i, 8i + 8] and
// z in [8j, 8j + 8]; u and v are offsets inside a bay along x and z.
constexpr int kStoreys = 3;
constexpr double kBay = 8.0, kStoreyHeight = 6.0;
// The default plant: 8 x 6 bays. scale=s multiplies the bays (and so the triangles) by about s.
constexpr double kDefaultBaysX = 8, kDefaultBaysZ = 6;
constexpr double kMinScale = 0.05, kMaxScale = 10;
// Between every two parts, also those that rest on each other.
constexpr double kGap = 0.01;

// The bands of a storey, as heights above its floor (a grating's top, or the slab's).
constexpr double kEquipmentTop = 3.05;
constexpr double kZRunAxis = 3.6; // pipe runs along z: 3.32 to 3.88 with their flanges
constexpr double kRackBottom = 3.97, kRackTop = 4.15, kRackHalf = 0.09;
constexpr double kXRunLowBottom = 4.2; // a low lane's pipe rests 0.05 above the rack beam
constexpr double kXRunHighAxis = 4.8;  // a high lane's axis: 5.08 at most with its flanges
constexpr double kZGirderBottom = 5.1, kZGirderTop = 5.46;
constexpr double kXGirderBottom = 5.5, kXGirderTop = 5.92;
constexpr double kGratingThickness = 0.06; // the grating of the storey above: 5.94 to 6
constexpr double kGirderHalf = 0.15, kColumnHalf = 0.15, kGirderEnd = 0.2;
constexpr double kRodHalf = 0.025;

// Lanes inside a bay. Runs along x lie at these v (aisle rows only the first two, away from
// the stair), runs along z at these u; both keep clear of the rack beam at u = 4 and of the
// riser's corner at (0.9, 0.9).
constexpr double kXRunLanes[4] = {2.0, 2.8, 5.2, 6.0};
constexpr double kZRunLanes[4] = {1.6, 2.4, 5.6, 6.4};
constexpr double kRackU = 4.0;
constexpr double kMinPipeRadius = 0.1, kMaxPipeRadius = 0.2;
constexpr double kFlangeOffsets[2] = {2.0, 6.0}; // in every bay, each moved by up to 0.3
constexpr double kRunStart = 0.5, kRunEndMargin = 0.9, kRunTurnLength = 0.8;
// Risers: at (u, v) = (0.9, 0.9) of an equipment bay, through a hole of the grating above that
// leaves [kGratingInset, kRiserHole) free on both axes.
constexpr double kRiserUV = 0.9, kRiserHole = 1.6, kMaxRiserRadius = 0.18;
constexpr double kRiserTurnHeight = 1.4, kRiserStubLength = 1.0;

// Gratings: bearing bars along x under cross bars along z, kBarPitch apart, kept kGratingInset
// from the column lines.
constexpr double kGratingInset = 0.25, kBarPitch = 0.4, kBarHalf = 0.02;

// Equipment stays inside [kEquipmentLow, kEquipmentHigh] on both axes of its bay.
constexpr double kEquipmentLow = 1.6, kEquipmentHigh = 6.9;
constexpr double kEquipmentCentre = (kEquipmentLow + kEquipmentHigh) / 2;

// Stairs: a straight flight along +x in an aisle bay, kSteps treads of kRise by kGoing from
// u = kStairStart, between v = kStairLow and kStairHigh; the grating above is open over
// v in (kStairHoleLow, kStairHoleHigh).
constexpr int kSteps = 30;
constexpr double kRise = kStoreyHeight / kSteps, kGoing = 0.24, kStairStart = 0.4;
constexpr double kStairLow = 5.05, kStairHigh = 6.35, kTreadThickness = 0.04;
constexpr double kStairHoleLow = 4.8, kStairHoleHigh = 6.6;
constexpr double kStringerDepth = 0.25, kStringerWidth = 0.06, kRailHeight = 0.9;

// Walls: panels kWallInner to kWallOuter outside the column lines, a window in each.
constexpr double kWallInner = 0.25, kWallOuter = 0.45;
constexpr double kWindowLow = 1.2, kWindowHigh = 4.2, kWindowStart = 2.0, kWindowEnd = 6.0;
constexpr double kSlabThickness = 0.3, kSlabMargin = 0.6;

// The walkthrough: eye height, the aisle's and the stair's v, walking and turning speeds.
constexpr double kEyeHeight = 1.7, kAisleV = 4.2, kStairV = 5.7;
constexpr double kWalkSpeed = 1.5, kTurnSpeed = 50; // m/s, degrees/s
constexpr int kAisleRow = 1;

// Tessellation.
constexpr int kPipeSegments = 28, kVesselSegments = 96, kSmallSegments = 32;
constexpr int kBendSteps = 8, kHeadRings = 8;

// Besides the shared palette (solid_shapes.h):
constexpr Rgba kRackColour{0.80f, 0.55f, 0.10f, 1.0f};
constexpr Rgba kRodColour{0.50f, 0.50f, 0.52f, 1.0f};
constexpr Rgba kGratingColour{0.30f, 0.34f, 0.32f, 1.0f};
constexpr Rgba kStairColour{0.75f, 0.60f, 0.10f, 1.0f};
constexpr Rgba kWallColour{0.70f, 0.69f, 0.66f, 1.0f};
constexpr Rgba kGlassColour{0.55f, 0.75f, 0.90f, 0.3f};
constexpr Rgba kMotorColour{0.25f, 0.50f, 0.30f, 1.0f};

// Every kTransparentPipeEvery-th pipe and every kTransparentVesselEvery-th vessel is transparent
// (counted in the order they are built, not drawn at random: the share then hardly depends on the
// seed), so that about 11% of the triangles are transparent, as in the paper's model (91K of
// 823K).
constexpr int kTransparentPipeEvery = 10, kTransparentVesselEvery = 4;

struct Layout {
    int bays_x = 0, bays_z = 0;
    double width() const { return kBay * bays_x; }
    double depth() const { return kBay * bays_z; }
    static bool isAisleRow(int j) { return j % 2 == 1; }
    /// The bay (along x) of storey s's stair, in aisle row kAisleRow: alternating between the
    /// middle bay and the one before it, so that no stair starts under another's opening.
    int stairBay(int storey) const { return bays_x / 2 - (storey % 2); }
    bool hasStair(int storey, int i, int j) const {
        return storey < kStoreys - 1 && j == kAisleRow && i == stairBay(storey);
    }
    /// Risers climb from storey s in every other equipment bay, never into a bay whose own
    /// riser would start where this one ends.
    static bool hasRiser(int storey, int i, int j) {
        return storey < kStoreys - 1 && !isAisleRow(j) && (i + j / 2 + storey) % 2 == 0;
    }
};

double floorOf(int storey) {
    return kStoreyHeight * storey;
}

/// Builds the parts of the plant in order and appends each as an object.
class PlantBuilder {
public:
    PlantBuilder(Scene& scene, const Layout& layout, SceneRandom& random)
        : scene_(scene), layout_(layout), random_(random) {}

    void build() {
        addSlabs();
        for (int storey = 0; storey < kStoreys; ++storey) {
            addSteel(storey);
            if (storey > 0)
                addGratings(storey);
            addWalls(storey);
            addPipeRunsAlongX(storey);
            addPipeRunsAlongZ(storey);
            for (int j = 0; j < layout_.bays_z; ++j)
                for (int i = 0; i < layout_.bays_x; ++i) {
                    if (!Layout::isAisleRow(j))
                        addEquipment(storey, i, j);
                    if (Layout::hasRiser(storey, i, j))
                        addRiser(storey, i, j);
                    if (layout_.hasStair(storey, i, j))
                        addStair(storey, i, j);
                }
        }
    }

private:
    void emit(const SolidPart& part) { appendPart(scene_, part); }
    /// One box as a part of its own.
    void emitBox(std::string name, Rgba colour, const dvec3& low, const dvec3& high,
                 bool transparent = false) {
        SolidPart box = part(std::move(name), colour, transparent);
        addBox(box.triangles, low, high);
        emit(box);
    }
    static SolidPart part(std::string name, Rgba colour, bool transparent = false) {
        return {std::move(name), colour, transparent, {}};
    }
    std::string label(const char* kind, int storey, int i, int j) const {
        return std::string(kind) + "_s" + std::to_string(storey) + "_" + std::to_string(i) + "_" +
               std::to_string(j);
    }
    bool nextPipeIsTransparent() { return pipes_++ % kTransparentPipeEvery == 0; }
    bool nextVesselIsTransparent() { return vessels_++ % kTransparentVesselEvery == 0; }
    Rgba pipeColour(bool transparent) {
        const uint32_t k = random_.index(static_cast<uint32_t>(std::size(kPipeColours)));
        return pick(kPipeColours[k],
                    transparent ? static_cast<float>(random_.uniform(0.35, 0.6)) : 1.0f);
    }
    Rgba vesselColour(bool transparent) {
        const uint32_t k = random_.index(static_cast<uint32_t>(std::size(kVesselColours)));
        return pick(kVesselColours[k],
                    transparent ? static_cast<float>(random_.uniform(0.3, 0.45)) : 1.0f);
    }

    void addSlabs() {
        const double top = kStoreyHeight * kStoreys;
        emitBox("ground_slab", kConcreteColour, {-kSlabMargin, -kSlabThickness, -kSlabMargin},
                {layout_.width() + kSlabMargin, 0, layout_.depth() + kSlabMargin});
        emitBox(
            "roof", kConcreteColour, {-kSlabMargin, top, -kSlabMargin},
            {layout_.width() + kSlabMargin, top + kSlabThickness, layout_.depth() + kSlabMargin});
    }

    /// Columns at every bay corner, girders along x and z between them, and in every bay a rack
    /// beam along z hung on rods from the girders above.
    void addSteel(int storey) {
        const double y = floorOf(storey);
        for (int j = 0; j <= layout_.bays_z; ++j)
            for (int i = 0; i <= layout_.bays_x; ++i) {
                emitBox(label("column", storey, i, j), kColumnColour,
                        {kBay * i - kColumnHalf, y + kGap, kBay * j - kColumnHalf},
                        {kBay * i + kColumnHalf, y + kStoreyHeight - kGap, kBay * j + kColumnHalf});
            }
        for (int j = 0; j <= layout_.bays_z; ++j)
            for (int i = 0; i < layout_.bays_x; ++i) {
                emitBox(label("girder_x", storey, i, j), kGirderColour,
                        {kBay * i + kGirderEnd, y + kXGirderBottom, kBay * j - kGirderHalf},
                        {kBay * (i + 1) - kGirderEnd, y + kXGirderTop, kBay * j + kGirderHalf});
            }
        for (int i = 0; i <= layout_.bays_x; ++i)
            for (int j = 0; j < layout_.bays_z; ++j) {
                emitBox(label("girder_z", storey, i, j), kGirderColour,
                        {kBay * i - kGirderHalf, y + kZGirderBottom, kBay * j + kGirderEnd},
                        {kBay * i + kGirderHalf, y + kZGirderTop, kBay * (j + 1) - kGirderEnd});
            }
        for (int j = 0; j < layout_.bays_z; ++j)
            for (int i = 0; i < layout_.bays_x; ++i) {
                // In aisle rows the rack stops short of the stair and the walkway.
                const bool aisle = Layout::isAisleRow(j);
                const double x = kBay * i + kRackU, z0 = kBay * j + 0.05;
                const double z1 = kBay * j + (aisle ? 3.6 : kBay - 0.05);
                emitBox(label("rack", storey, i, j), kRackColour,
                        {x - kRackHalf, y + kRackBottom, z0}, {x + kRackHalf, y + kRackTop, z1});
                // Rods under the girders along x (v = 0.1 and 7.9), or under the grating.
                const double rod_zs[2] = {kBay * j + 0.1, aisle ? z1 - 0.1 : kBay * (j + 1) - 0.1};
                for (int r = 0; r < 2; ++r) {
                    const bool under_girder = !aisle || r == 0;
                    const double top =
                        under_girder ? kXGirderBottom : kStoreyHeight - kGratingThickness;
                    emitBox(label(r == 0 ? "rod_a" : "rod_b", storey, i, j), kRodColour,
                            {x - kRodHalf, y + kRackTop + kGap, rod_zs[r] - kRodHalf},
                            {x + kRodHalf, y + top - kGap, rod_zs[r] + kRodHalf});
                }
            }
    }

    /// A grating over [x0, x1] x [z0, z1] with its top at y: bearing bars along x under cross
    /// bars along z. Bars never end on another bar's side, so the bars' corners never coincide.
    void addGrating(std::string name, double x0, double x1, double z0, double z1, double y) {
        SolidPart grating = part(std::move(name), kGratingColour);
        const double middle = y - kGratingThickness / 2, bottom = y - kGratingThickness;
        for (double z = z0 + kBarPitch / 2; z + kBarHalf < z1; z += kBarPitch)
            addBox(grating.triangles, {x0, bottom, z - kBarHalf}, {x1, middle, z + kBarHalf});
        for (double x = x0 + kBarPitch / 2; x + kBarHalf < x1; x += kBarPitch)
            addBox(grating.triangles, {x - kBarHalf, middle, z0}, {x + kBarHalf, y, z1});
        emit(grating);
    }

    /// The floor of a storey above the ground: a grating in every bay, open over a stair that
    /// arrives from below and around a riser that climbs through it.
    void addGratings(int storey) {
        const double y = floorOf(storey);
        const double inner = kGratingInset, outer = kBay - kGratingInset;
        for (int j = 0; j < layout_.bays_z; ++j)
            for (int i = 0; i < layout_.bays_x; ++i) {
                const double x = kBay * i, z = kBay * j;
                const std::string name = label("grating", storey, i, j);
                if (layout_.hasStair(storey - 1, i, j)) {
                    addGrating(name + "_a", x + inner, x + outer, z + inner, z + kStairHoleLow, y);
                    addGrating(name + "_b", x + inner, x + outer, z + kStairHoleHigh, z + outer, y);
                } else if (Layout::hasRiser(storey - 1, i, j)) {
                    addGrating(name + "_a", x + kRiserHole, x + outer, z + inner, z + outer, y);
                    addGrating(name + "_b", x + inner, x + kRiserHole - 0.05, z + kRiserHole,
                               z + outer, y);
                } else {
                    addGrating(name, x + inner, x + outer, z + inner, z + outer, y);
                }
            }
    }

    /// A wall panel with a window in every bay of the four sides, and the window's glass.
    void addWalls(int storey) {
        const double y = floorOf(storey) + kGap;
        const double middle = (kWallInner + kWallOuter) / 2, thickness = kWallOuter - kWallInner;
        struct Side {
            const char* name;
            dvec3 origin, along;
            int bays;
        };
        const Side sides[4] = {
            {"wall_south", {0, y, -middle}, {1, 0, 0}, layout_.bays_x},
            {"wall_north", {0, y, layout_.depth() + middle}, {1, 0, 0}, layout_.bays_x},
            {"wall_west", {-middle, y, 0}, {0, 0, 1}, layout_.bays_z},
            {"wall_east", {layout_.width() + middle, y, 0}, {0, 0, 1}, layout_.bays_z},
        };
        for (const Side& side : sides)
            for (int k = 0; k < side.bays; ++k) {
                FrameShape frame;
                frame.origin = side.origin + side.along * (kBay * k + kGap);
                frame.a = side.along;
                frame.b = {0, 1, 0};
                frame.a_length = kBay - 2 * kGap;
                frame.b_length = kStoreyHeight - 2 * kGap;
                frame.hole_a0 = kWindowStart, frame.hole_a1 = kWindowEnd;
                frame.hole_b0 = kWindowLow, frame.hole_b1 = kWindowHigh;
                frame.thickness = thickness;
                const std::string name = std::string(side.name) + "_s" + std::to_string(storey) +
                                         "_" + std::to_string(k);
                SolidPart wall = part(name, kWallColour);
                addFrame(wall.triangles, frame);
                emit(wall);
                // The glass: the window's opening less kGap all round, 2 cm thick.
                const dvec3 normal = glm::cross(frame.a, frame.b) * 0.01;
                const dvec3 low = frame.origin + frame.a * (kWindowStart + kGap) +
                                  frame.b * (kWindowLow + kGap) - normal;
                const dvec3 high = frame.origin + frame.a * (kWindowEnd - kGap) +
                                   frame.b * (kWindowHigh - kGap) + normal;
                emitBox(name + "_glass", kGlassColour, glm::min(low, high), glm::max(low, high),
                        true);
            }
    }

    /// Rings of a straight run from `start` along `direction` (x or z) to `end`, with two
    /// flanges in every bay it crosses, each moved by up to 0.3 from kFlangeOffsets.
    /// The rings' normal is `normal`, their binormal direction x normal (so that normal x
    /// binormal = direction).
    void straightRun(std::vector<Ring>& rings, const dvec3& axis_point, const dvec3& direction,
                     double start, double end, double radius, const dvec3& normal) {
        const dvec3 binormal = glm::cross(direction, normal);
        const auto ring = [&](double s, double r) {
            rings.push_back({axis_point + direction * s, normal, binormal, r});
        };
        ring(start, radius);
        for (int bay = 0; kBay * bay < end; ++bay)
            for (const double offset : kFlangeOffsets) {
                const double s = kBay * bay + offset + random_.uniform(-0.3, 0.3);
                if (s - kFlangeWidth < start || s + kFlangeWidth > end)
                    continue;
                for (const auto& [at, r] : flangeRings(s, radius))
                    ring(at, r);
            }
        ring(end, radius);
    }

    /// A quarter bend of radius 2 r from the last ring's direction `from` to `to` (both unit, at
    /// right angles), then a straight piece of `length` along `to`. The rings' frame turns with
    /// the run about from x to, so the tube never twists.
    static void bend(std::vector<Ring>& rings, const dvec3& from, const dvec3& to, double radius,
                     double length) {
        const Ring last = rings.back();
        const double bend_radius = 2 * radius;
        const dvec3 centre = last.centre + to * bend_radius;
        const dvec3 axis = glm::cross(from, to);
        // The rotation by `turn` about `axis`: from -> cos from + sin to, to -> cos to - sin from.
        const auto rotate = [&](const dvec3& v, double turn) {
            const double c = std::cos(turn), s = std::sin(turn);
            return glm::dot(v, axis) * axis + glm::dot(v, from) * (c * from + s * to) +
                   glm::dot(v, to) * (c * to - s * from);
        };
        for (int step = 1; step <= kBendSteps; ++step) {
            const double turn = std::numbers::pi / 2 * step / kBendSteps;
            const dvec3 offset = -std::cos(turn) * to + std::sin(turn) * from;
            rings.push_back({centre + offset * bend_radius, rotate(last.normal, turn),
                             rotate(last.binormal, turn), radius});
        }
        const Ring end = rings.back();
        rings.push_back({end.centre + to * length, end.normal, end.binormal, radius});
    }

    /// A pipe through `rings`, flat-capped at both ends, in a process colour; every
    /// kTransparentPipeEvery-th one transparent.
    void emitPipe(std::string name, const std::vector<Ring>& rings) {
        const bool transparent = nextPipeIsTransparent();
        SolidPart pipe = part(std::move(name), pipeColour(transparent), transparent);
        addTube(pipe.triangles, rings, kPipeSegments, rings.front().centre, rings.back().centre);
        emit(pipe);
    }

    /// Runs along x under every storey's ceiling: four lanes in equipment rows, two in aisle
    /// rows, from the west wall to an elbow turning down before the east wall.
    void addPipeRunsAlongX(int storey) {
        const double y = floorOf(storey);
        for (int j = 0; j < layout_.bays_z; ++j) {
            const int lanes = Layout::isAisleRow(j) ? 2 : 4;
            for (int lane = 0; lane < lanes; ++lane) {
                const double radius = random_.uniform(kMinPipeRadius, kMaxPipeRadius);
                const double axis_y = y + (lane % 2 == 0 ? kXRunLowBottom + radius : kXRunHighAxis);
                const dvec3 axis{0, axis_y, kBay * j + kXRunLanes[lane]};
                std::vector<Ring> rings;
                straightRun(rings, axis, {1, 0, 0}, kRunStart, layout_.width() - kRunEndMargin,
                            radius, {0, 1, 0});
                bend(rings, {1, 0, 0}, {0, -1, 0}, radius, kRunTurnLength);
                emitPipe(label("pipe_x", storey, lane, j), rings);
            }
        }
    }

    /// Runs along z over the equipment, four lanes in every bay column but the one under the
    /// storey's stair, from the south wall to an elbow turning up before the north wall.
    void addPipeRunsAlongZ(int storey) {
        const double y = floorOf(storey);
        for (int i = 0; i < layout_.bays_x; ++i) {
            if (layout_.hasStair(storey, i, kAisleRow)) // its column keeps clear of the flight
                continue;
            for (int lane = 0; lane < 4; ++lane) {
                const double radius = random_.uniform(kMinPipeRadius, kMaxPipeRadius);
                const dvec3 axis{kBay * i + kZRunLanes[lane], y + kZRunAxis, 0};
                std::vector<Ring> rings;
                straightRun(rings, axis, {0, 0, 1}, kRunStart, layout_.depth() - kRunEndMargin,
                            radius, {1, 0, 0});
                bend(rings, {0, 0, 1}, {0, 1, 0}, radius, kRunTurnLength);
                emitPipe(label("pipe_z", storey, i, lane), rings);
            }
        }
    }

    /// A riser standing on a pipe stand, climbing through the grating above and turning along
    /// +x kRiserTurnHeight above the next floor.
    void addRiser(int storey, int i, int j) {
        const double y = floorOf(storey);
        const double x = kBay * i + kRiserUV, z = kBay * j + kRiserUV;
        const double radius = random_.uniform(kMinPipeRadius, kMaxRiserRadius);
        emitBox(label("riser_stand", storey, i, j), kEquipmentColour, {x - 0.2, y + kGap, z - 0.2},
                {x + 0.2, y + 0.25, z + 0.2});
        std::vector<Ring> rings;
        const dvec3 axis{x, 0, z};
        straightRun(rings, axis, {0, 1, 0}, y + 0.25 + kGap, y + kStoreyHeight + kRiserTurnHeight,
                    radius, {0, 0, 1});
        bend(rings, {0, 1, 0}, {1, 0, 0}, radius, kRiserStubLength);
        emitPipe(label("riser", storey, i, j), rings);
    }

    /// A straight flight of treads between two stringers, with a handrail on posts each side.
    void addStair(int storey, int i, int j) {
        const double y = floorOf(storey), x = kBay * i, z = kBay * j;
        SolidPart treads = part(label("stair_treads", storey, i, j), kStairColour);
        for (int k = 0; k < kSteps; ++k) {
            const double top = y + kRise * (k + 1);
            addBox(treads.triangles,
                   {x + kStairStart + kGoing * k, top - kTreadThickness, z + kStairLow},
                   {x + kStairStart + kGoing * (k + 1), top, z + kStairHigh});
        }
        emit(treads);
        // The stringers' outline: a band under the treads, vertical at both ends, kept 3 cm
        // short of the treads' first and last faces so that no face of one lies in the plane of
        // a face of the other.
        const double x0 = x + kStairStart - 0.03, x1 = x + kStairStart + kGoing * kSteps - 0.03;
        const double bottom0 = y + kGap, top0 = bottom0 + kStringerDepth;
        const double top1 = y + kStoreyHeight - kGap, bottom1 = top1 - kStringerDepth;
        const auto stringer_top = [&](double at) {
            return top0 + (at - x0) / (x1 - x0) * (top1 - top0);
        };
        for (int side = 0; side < 2; ++side) {
            const double z0 =
                side == 0 ? z + kStairLow - kGap - kStringerWidth : z + kStairHigh + kGap;
            // Counter-clockwise seen from +z.
            const std::array<dvec3, 4> outline = {dvec3{x0, bottom0, z0}, dvec3{x1, bottom1, z0},
                                                  dvec3{x1, top1, z0}, dvec3{x0, top0, z0}};
            SolidPart stringer =
                part(label(side == 0 ? "stringer_a" : "stringer_b", storey, i, j), kStairColour);
            addPrism(stringer.triangles, outline, {0, 0, 1}, kStringerWidth);
            emit(stringer);
            // The rail kRailHeight above the stringer's top edge, on three posts standing on it;
            // its ends 5 cm inside the stringer's.
            SolidPart rail =
                part(label(side == 0 ? "rail_a" : "rail_b", storey, i, j), kStairColour);
            const double r0 = x0 + 0.05, r1 = x1 - 0.05;
            const double rail_low = kRailHeight, rail_high = kRailHeight + 0.05;
            const std::array<dvec3, 4> rail_outline = {dvec3{r0, stringer_top(r0) + rail_low, z0},
                                                       dvec3{r1, stringer_top(r1) + rail_low, z0},
                                                       dvec3{r1, stringer_top(r1) + rail_high, z0},
                                                       dvec3{r0, stringer_top(r0) + rail_high, z0}};
            addPrism(rail.triangles, rail_outline, {0, 0, 1}, kStringerWidth);
            // A post's square foot must clear the slanted edge at both of its sides.
            const double rise_over_post = 0.04 * (top1 - top0) / (x1 - x0);
            for (const double t : {0.05, 0.5, 0.95}) {
                const double px = r0 + t * (r1 - r0), edge = stringer_top(px);
                addBox(rail.triangles, {px - 0.02, edge + rise_over_post + kGap, z0 + 0.01},
                       {px + 0.02, edge + rail_low - rise_over_post - kGap,
                        z0 + kStringerWidth - 0.01});
            }
            emit(rail);
        }
    }

    /// A vertical tank on a plinth, with an ellipsoidal head.
    void addTank(int storey, int i, int j, const dvec3& centre) {
        const double radius = random_.uniform(1.3, 2.0);
        const double head = 0.45 * radius;
        const double plinth_top = centre.y + 0.2;
        const double height =
            kEquipmentTop - (plinth_top + kGap - centre.y) - head - random_.uniform(0, 0.5);
        emitBox(label("tank_plinth", storey, i, j), kConcreteColour,
                {centre.x - radius - 0.1, centre.y + kGap, centre.z - radius - 0.1},
                {centre.x + radius + 0.1, plinth_top, centre.z + radius + 0.1});
        const dvec3 normal{0, 0, 1}, binormal{1, 0, 0}; // z x x = y
        const double bottom = plinth_top + kGap;
        std::vector<Ring> rings = {
            {{centre.x, bottom, centre.z}, normal, binormal, radius},
            {{centre.x, bottom + height, centre.z}, normal, binormal, radius}};
        for (int k = 1; k < kHeadRings; ++k) {
            const double latitude = std::numbers::pi / 2 * k / kHeadRings;
            rings.push_back({{centre.x, bottom + height + head * std::sin(latitude), centre.z},
                             normal,
                             binormal,
                             radius * std::cos(latitude)});
        }
        const bool transparent = nextVesselIsTransparent();
        SolidPart tank = part(label("tank", storey, i, j), vesselColour(transparent), transparent);
        addTube(tank.triangles, rings, kVesselSegments, rings.front().centre,
                {centre.x, bottom + height + head, centre.z});
        emit(tank);
    }

    /// A vessel lying along `direction` (x or z) with ellipsoidal heads of depth `head` at both
    /// ends of a cylinder of `length`, its axis at `axis`'s height, on two saddles.
    void addHorizontalVessel(const std::string& name, const dvec3& axis, const dvec3& direction,
                             double radius, double length, double head, double floor_y, Rgba colour,
                             bool transparent, int segments) {
        const dvec3 normal{0, 1, 0};
        const dvec3 binormal = glm::cross(direction, normal); // normal x binormal = direction
        const dvec3 start = axis - direction * (length / 2), end = axis + direction * (length / 2);
        std::vector<Ring> rings;
        for (int k = 1; k < kHeadRings; ++k) { // the first head, from its pole outwards
            const double latitude = std::numbers::pi / 2 * k / kHeadRings;
            rings.push_back({start - direction * (head * std::cos(latitude)), normal, binormal,
                             radius * std::sin(latitude)});
        }
        rings.push_back({start, normal, binormal, radius});
        rings.push_back({end, normal, binormal, radius});
        for (int k = kHeadRings - 1; k >= 1; --k) {
            const double latitude = std::numbers::pi / 2 * k / kHeadRings;
            rings.push_back({end + direction * (head * std::cos(latitude)), normal, binormal,
                             radius * std::sin(latitude)});
        }
        SolidPart vessel = part(name, colour, transparent);
        addTube(vessel.triangles, rings, segments, start - direction * head,
                end + direction * head);
        emit(vessel);
        const dvec3 across = glm::abs(binormal);
        for (int s = 0; s < 2; ++s) {
            const dvec3 at = axis + direction * ((s == 0 ? -1 : 1) * length / 3);
            const dvec3 half = glm::abs(direction) * 0.15 + across * (0.7 * radius);
            emitBox(name + (s == 0 ? "_saddle_a" : "_saddle_b"), kColumnColour,
                    {at.x - half.x, floor_y + kGap, at.z - half.z},
                    {at.x + half.x, axis.y - radius - kGap, at.z + half.z});
        }
    }

    /// A pump skid: a base plate, a motor lying along x with a domed fan cover, and a pump
    /// casing standing beside it.
    void addPumpSkid(const std::string& name, const dvec3& centre) {
        const double plate_top = centre.y + 0.2;
        emitBox(name + "_base", kEquipmentColour,
                {centre.x - 1.2, centre.y + kGap, centre.z - 0.45},
                {centre.x + 1.2, plate_top, centre.z + 0.45});
        const double motor_radius = 0.32, motor_axis = plate_top + 0.15 + motor_radius;
        addHorizontalVessel(name + "_motor", {centre.x - 0.45, motor_axis, centre.z}, {1, 0, 0},
                            motor_radius, 1.0, 0.15, plate_top, kMotorColour, false,
                            kSmallSegments);
        const dvec3 normal{0, 0, 1}, binormal{1, 0, 0};
        const double casing_x = centre.x + 0.75, bottom = plate_top + kGap;
        std::vector<Ring> rings = {{{casing_x, bottom, centre.z}, normal, binormal, 0.3},
                                   {{casing_x, bottom + 0.5, centre.z}, normal, binormal, 0.3},
                                   {{casing_x, bottom + 0.5, centre.z}, normal, binormal, 0.38},
                                   {{casing_x, bottom + 0.6, centre.z}, normal, binormal, 0.38},
                                   {{casing_x, bottom + 0.6, centre.z}, normal, binormal, 0.18},
                                   {{casing_x, bottom + 0.9, centre.z}, normal, binormal, 0.18}};
        SolidPart casing = part(name + "_casing", kMotorColour);
        addTube(casing.triangles, rings, kSmallSegments, rings.front().centre, rings.back().centre);
        emit(casing);
    }

    void addEquipment(int storey, int i, int j) {
        const dvec3 centre{kBay * i + kEquipmentCentre, floorOf(storey),
                           kBay * j + kEquipmentCentre};
        switch (random_.index(4)) {
        case 0:
            addTank(storey, i, j, centre);
            break;
        case 1: { // a boiler drum lying along x
            const double radius = random_.uniform(0.9, 1.25);
            const double head = 0.5 * radius;
            const double length = (kEquipmentHigh - kEquipmentLow) - 2 * head - 0.1;
            const bool transparent = nextVesselIsTransparent();
            addHorizontalVessel(label("boiler", storey, i, j),
                                {centre.x, centre.y + 0.45 + radius, centre.z}, {1, 0, 0}, radius,
                                length - random_.uniform(0, 1.0), head, centre.y,
                                vesselColour(transparent), transparent, kVesselSegments);
            break;
        }
        case 2: // two heat exchangers lying along z
            for (int k = 0; k < 2; ++k) {
                const double radius = random_.uniform(0.45, 0.6);
                const bool transparent = nextVesselIsTransparent();
                addHorizontalVessel(
                    label(k == 0 ? "exchanger_a" : "exchanger_b", storey, i, j),
                    {centre.x + (k == 0 ? -1.2 : 1.2), centre.y + 0.45 + radius, centre.z},
                    {0, 0, 1}, radius, 4.2 - 2 * 0.3 * radius, 0.3 * radius, centre.y,
                    vesselColour(transparent), transparent, kVesselSegments / 2);
            }
            break;
        default: // three pump skids
            for (int k = 0; k < 3; ++k)
                addPumpSkid(label("pump", storey, i, j) + "_" + std::to_string(k),
                            {centre.x, centre.y, centre.z + 1.7 * (k - 1)});
            break;
        }
    }

    Scene& scene_;
    const Layout& layout_;
    SceneRandom& random_;
    int pipes_ = 0, vessels_ = 0;
};

/// A camera looking along (yaw, pitch) from `eye`: yaw 0 looks along +x, 90 along -z.
CameraSpec lookFrom(const dvec3& eye, double yaw_degrees, double pitch_degrees) {
    const double yaw = yaw_degrees * std::numbers::pi / 180;
    const double pitch = pitch_degrees * std::numbers::pi / 180;
    const dvec3 direction{std::cos(yaw) * std::cos(pitch), std::sin(pitch),
                          -std::sin(yaw) * std::cos(pitch)};
    const dvec3 target = eye + 4.0 * direction;
    CameraSpec camera;
    camera.eye = {eye.x, eye.y, eye.z};
    camera.target = {target.x, target.y, target.z};
    camera.up = {0, 1, 0};
    camera.fov_degrees = 60;
    return camera;
}

/// The walkthrough: along the ground floor's aisle towards the stair looking at the equipment
/// on both sides, up the stair, then along the first floor's aisle looking around and up at
/// the pipes, and back. Keys are timed by walking and turning speed.
std::vector<CameraKey> walkthrough(const Layout& layout) {
    struct Waypoint {
        double x, y, z, yaw, pitch;
    };
    const double stair_x = kBay * layout.stairBay(0);
    const double aisle_z = kBay * kAisleRow + kAisleV, stair_z = kBay * kAisleRow + kStairV;
    const double start_x = std::max(1.0, stair_x - 10);
    const double along = stair_x - 0.8 - start_x;
    const double upper = kStoreyHeight + kEyeHeight;
    const double off_stair = stair_x + kBay + 1.0;
    const double end_x = std::min(layout.width() - 1.5, off_stair + 14);
    const double walk = end_x - off_stair;
    const Waypoint waypoints[] = {
        {start_x, kEyeHeight, aisle_z, 0, 0},
        {start_x + along / 3, kEyeHeight, aisle_z, 40, -8},
        {start_x + 2 * along / 3, kEyeHeight, aisle_z, -45, 5},
        {stair_x - 0.8, kEyeHeight, aisle_z, 0, 0},
        {stair_x + 0.1, kEyeHeight, stair_z, 0, 10},
        {stair_x + kStairStart + kGoing * kSteps - 0.1, upper, stair_z, 0, 5},
        {off_stair, upper, aisle_z, 0, 0},
        {off_stair + walk / 3, upper, aisle_z, 50, 15},
        {off_stair + 2 * walk / 3, upper, aisle_z, -50, -10},
        {end_x, upper, aisle_z, 0, 25},
        {end_x, upper, aisle_z, 180, 0},
        {end_x - 3, upper, aisle_z, 200, -5},
    };
    std::vector<CameraKey> keys;
    double time = 0;
    for (std::size_t k = 0; k < std::size(waypoints); ++k) {
        const Waypoint& w = waypoints[k];
        if (k > 0) {
            const Waypoint& p = waypoints[k - 1];
            const double distance = glm::length(dvec3(w.x - p.x, w.y - p.y, w.z - p.z));
            const double turn = std::max(std::abs(w.yaw - p.yaw), std::abs(w.pitch - p.pitch));
            time += std::max(distance / kWalkSpeed, turn / kTurnSpeed);
        }
        keys.push_back({time, lookFrom({w.x, w.y, w.z}, w.yaw, w.pitch)});
    }
    return keys;
}

} // namespace

Result<Scene> makePowerplantScene(const SceneParameters& parameters) {
    ParameterReader reader("builtin:powerplant", parameters);
    const double scale = reader.number("scale", 1.0, kMinScale, kMaxScale);
    const uint64_t seed = reader.seed("seed", 1);
    if (std::string error = reader.error(); !error.empty())
        return Result<Scene>::failure(error);

    // The bays grow with the square root of the scale on both axes; at least three along x
    // (the stairs need a bay on each side) and an equipment row and an aisle row along z.
    Layout layout;
    layout.bays_x = std::max(3, static_cast<int>(std::lround(kDefaultBaysX * std::sqrt(scale))));
    layout.bays_z = std::max(2, static_cast<int>(std::lround(kDefaultBaysZ * std::sqrt(scale))));

    SceneRandom random(seed);
    Scene scene;
    scene.name = "builtin:powerplant";
    PlantBuilder(scene, layout, random).build();
    assert(scene.triangleCount() <= kMaxBuiltinTriangles);
    scene.camera_path = walkthrough(layout);
    scene.camera = scene.camera_path.front().camera;
    return Result<Scene>{std::move(scene), {}};
}

} // namespace vissort::detail
