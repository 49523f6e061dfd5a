#pragma once
// Closed, outward-wound triangle meshes of the shapes the CAD-like built-in scenes are made of
// (plant, powerplant): tubes through rings (pipes, elbows, flanges, tanks, domes), boxes, slanted
// prisms and window frames. Every shape is watertight on its own: each edge has two triangles,
// wound consistently, facing outwards.

#include <array>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "vissort/scene.h"

namespace vissort::detail {

using SolidTriangle = std::array<glm::dvec3, 3>;

/// A circle of a tube: points centre + radius (cos a normal + sin a binormal), a = 2 pi j / n.
/// normal x binormal is the direction the tube runs, which makes its triangles face outwards.
struct Ring {
    glm::dvec3 centre;
    glm::dvec3 normal, binormal;
    double radius;
};

/// A closed tube through `rings` (at least two), closed at each end by a fan from a tip: the
/// first or last ring's centre for a flat cap, a point beyond it for a cone or a dome's pole.
/// Consecutive rings may share a centre (a flange's face) but not both centre and radius.
void addTube(std::vector<SolidTriangle>& out, std::span<const Ring> rings, int segments,
             const glm::dvec3& start_tip, const glm::dvec3& end_tip);

/// An axis-aligned box, 12 triangles facing outwards. low < high on every axis.
void addBox(std::vector<SolidTriangle>& out, const glm::dvec3& low, const glm::dvec3& high);

/// A prism: the quadrilateral `outline` (counter-clockwise seen from +`axis`) swept along `axis`
/// by `length`, 12 triangles facing outwards. A stair's stringer is a parallelogram swept
/// sideways.
void addPrism(std::vector<SolidTriangle>& out, const std::array<glm::dvec3, 4>& outline,
              const glm::dvec3& axis, double length);

/// A rectangular frame around a rectangular hole, as one closed ring-shaped solid (32 triangles):
/// the outer rectangle origin + [0, a_length] a + [0, b_length] b, the hole [a0, a1] x [b0, b1]
/// inside it, `thickness` along a x b (centred on the plane). a and b are unit and orthogonal.
struct FrameShape {
    glm::dvec3 origin, a, b;
    double a_length = 0, b_length = 0;
    double hole_a0 = 0, hole_a1 = 0, hole_b0 = 0, hole_b1 = 0;
    double thickness = 0;
};
void addFrame(std::vector<SolidTriangle>& out, const FrameShape& frame);

/// One object of a generated scene before it is appended: a name, a material and its solids.
struct SolidPart {
    std::string name;
    Rgba colour;
    bool transparent = false;
    std::vector<SolidTriangle> triangles;
};

/// Appends a part to a scene as one object, its corners rounded to float.
void appendPart(Scene& scene, const SolidPart& part);

// What the CAD-like scenes share besides shapes: their colours and their pipes' flanges.

/// Process-pipe colour codes (cooling water, gas, air, hot oil, fire water, steam, chemicals) and
/// pale vessel colours, picked at random; painted steel, equipment and concrete.
inline constexpr float kPipeColours[][3] = {
    {0.20f, 0.62f, 0.32f}, {0.95f, 0.78f, 0.15f}, {0.22f, 0.45f, 0.80f}, {0.90f, 0.45f, 0.12f},
    {0.80f, 0.18f, 0.15f}, {0.72f, 0.72f, 0.70f}, {0.55f, 0.35f, 0.65f}};
inline constexpr float kVesselColours[][3] = {
    {0.86f, 0.88f, 0.90f}, {0.60f, 0.75f, 0.86f}, {0.74f, 0.85f, 0.70f}, {0.90f, 0.80f, 0.62f}};
inline constexpr Rgba kColumnColour{0.36f, 0.40f, 0.46f, 1.0f};
inline constexpr Rgba kGirderColour{0.85f, 0.68f, 0.12f, 1.0f};
inline constexpr Rgba kEquipmentColour{0.15f, 0.35f, 0.55f, 1.0f};
inline constexpr Rgba kConcreteColour{0.48f, 0.48f, 0.46f, 1.0f};

/// A palette entry with an alpha.
inline Rgba pick(const float (&palette)[3], float alpha) {
    return {palette[0], palette[1], palette[2], alpha};
}

/// A flange: a collar of radius kFlangeScale r + kFlangeAdd and width kFlangeWidth on a pipe of
/// radius r.
inline constexpr double kFlangeScale = 1.3, kFlangeAdd = 0.02, kFlangeWidth = 0.12;

/// The four rings of a flange centred at `at` along a pipe of radius `radius`, as (position
/// along the pipe, radius), in order.
inline std::array<std::array<double, 2>, 4> flangeRings(double at, double radius) {
    const double collar = kFlangeScale * radius + kFlangeAdd;
    return {{{at - kFlangeWidth / 2, radius},
             {at - kFlangeWidth / 2, collar},
             {at + kFlangeWidth / 2, collar},
             {at + kFlangeWidth / 2, radius}}};
}

} // namespace vissort::detail
