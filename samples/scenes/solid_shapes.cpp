// Closed meshes of simple solids for the built-in CAD-like scenes (solid_shapes.h).

#include "scenes/solid_shapes.h"

#include <cassert>
#include <cmath>
#include <numbers>
#include <utility>

namespace vissort::detail {

using glm::dvec3;

void addTube(std::vector<SolidTriangle>& out, std::span<const Ring> rings, int segments,
             const dvec3& start_tip, const dvec3& end_tip) {
    assert(rings.size() >= 2);
    std::vector<dvec3> previous(segments), current(segments);
    for (std::size_t i = 0; i < rings.size(); ++i) {
        const Ring& ring = rings[i];
        for (int j = 0; j < segments; ++j) {
            const double angle = 2 * std::numbers::pi * j / segments;
            current[j] = ring.centre + ring.radius * (std::cos(angle) * ring.normal +
                                                      std::sin(angle) * ring.binormal);
        }
        for (int j = 0; j < segments; ++j) {
            const int next = (j + 1) % segments;
            if (i == 0)
                out.push_back({start_tip, current[next], current[j]});
            else {
                out.push_back({previous[j], previous[next], current[next]});
                out.push_back({previous[j], current[next], current[j]});
            }
            if (i + 1 == rings.size())
                out.push_back({end_tip, current[j], current[next]});
        }
        std::swap(previous, current);
    }
}

void addBox(std::vector<SolidTriangle>& out, const dvec3& low, const dvec3& high) {
    assert(low.x < high.x && low.y < high.y && low.z < high.z);
    dvec3 corner[8];
    for (int i = 0; i < 8; ++i)
        corner[i] = {i & 1 ? high.x : low.x, i & 2 ? high.y : low.y, i & 4 ? high.z : low.z};
    // Each face counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
    constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                  {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& face : kFaces) {
        out.push_back({corner[face[0]], corner[face[1]], corner[face[2]]});
        out.push_back({corner[face[0]], corner[face[2]], corner[face[3]]});
    }
}

namespace {

void addQuad(std::vector<SolidTriangle>& out, const dvec3& a, const dvec3& b, const dvec3& c,
             const dvec3& d) {
    out.push_back({a, b, c});
    out.push_back({a, c, d});
}

} // namespace

void addPrism(std::vector<SolidTriangle>& out, const std::array<dvec3, 4>& outline,
              const dvec3& axis, double length) {
    const dvec3 step = glm::normalize(axis) * length;
    std::array<dvec3, 4> top;
    for (int i = 0; i < 4; ++i)
        top[i] = outline[i] + step;
    // The outline faces +axis: the bottom is it reversed, the top as it is.
    addQuad(out, outline[0], outline[3], outline[2], outline[1]);
    addQuad(out, top[0], top[1], top[2], top[3]);
    for (int i = 0; i < 4; ++i) {
        const int next = (i + 1) % 4;
        addQuad(out, outline[i], outline[next], top[next], top[i]);
    }
}

void addFrame(std::vector<SolidTriangle>& out, const FrameShape& f) {
    assert(0 < f.hole_a0 && f.hole_a0 < f.hole_a1 && f.hole_a1 < f.a_length);
    assert(0 < f.hole_b0 && f.hole_b0 < f.hole_b1 && f.hole_b1 < f.b_length);
    const dvec3 normal = glm::cross(f.a, f.b) * (f.thickness / 2);
    const auto at = [&](double s, double t) { return f.origin + s * f.a + t * f.b; };
    // The outer and the hole's rectangles, counter-clockwise seen from +normal.
    const dvec3 outer[4] = {at(0, 0), at(f.a_length, 0), at(f.a_length, f.b_length),
                            at(0, f.b_length)};
    const dvec3 hole[4] = {at(f.hole_a0, f.hole_b0), at(f.hole_a1, f.hole_b0),
                           at(f.hole_a1, f.hole_b1), at(f.hole_a0, f.hole_b1)};
    for (int i = 0; i < 4; ++i) {
        const int next = (i + 1) % 4;
        // Front (+normal) and back faces: the band between the two rectangles, side i.
        addQuad(out, outer[i] + normal, outer[next] + normal, hole[next] + normal,
                hole[i] + normal);
        addQuad(out, outer[i] - normal, hole[i] - normal, hole[next] - normal,
                outer[next] - normal);
        // The outer rim faces away from the frame, the hole's rim into the hole.
        addQuad(out, outer[i] - normal, outer[next] - normal, outer[next] + normal,
                outer[i] + normal);
        addQuad(out, hole[i] - normal, hole[i] + normal, hole[next] + normal, hole[next] - normal);
    }
}

void appendPart(Scene& scene, const SolidPart& part) {
    SceneObject object;
    object.name = part.name;
    object.colour = part.colour;
    object.transparent = part.transparent;
    object.first_triangle = static_cast<uint32_t>(scene.positions.x.size() / 3);
    object.triangle_count = static_cast<uint32_t>(part.triangles.size());
    TrianglePositions& out = scene.positions;
    for (const SolidTriangle& triangle : part.triangles)
        for (const dvec3& p : triangle) {
            out.x.push_back(static_cast<float>(p.x));
            out.y.push_back(static_cast<float>(p.y));
            out.z.push_back(static_cast<float>(p.z));
        }
    scene.objects.push_back(std::move(object));
}

} // namespace vissort::detail
