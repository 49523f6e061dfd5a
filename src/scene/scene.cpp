// Scene queries and the invariant check every loaded scene passes.

#include "vissort/scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace vissort {

void Scene::frame(double t, TrianglePositions& out) const {
    if (animation) {
        animation->positionsAt(t, out);
        return;
    }
    out = positions;
}

TrianglePositions Scene::frame(double t) const {
    TrianglePositions out;
    frame(t, out);
    return out;
}

std::vector<PrimitiveRange> Scene::objectPrimitives() const {
    std::vector<PrimitiveRange> ranges;
    ranges.reserve(objects.size());
    for (const SceneObject& object : objects)
        ranges.push_back({object.first_triangle, object.triangle_count});
    return ranges;
}

std::vector<PrimitiveRange> Scene::trianglePrimitives() const {
    const auto count = static_cast<uint32_t>(triangleCount());
    std::vector<PrimitiveRange> ranges(count);
    for (uint32_t t = 0; t < count; ++t)
        ranges[t] = {t, 1};
    return ranges;
}

uint32_t Scene::objectOfTriangle(uint32_t triangle) const {
    assert(!objects.empty() && triangle < triangleCount());
    // Objects tile the triangles in order (validateScene), so the owner is the last object
    // starting at or before the triangle.
    auto after =
        std::upper_bound(objects.begin(), objects.end(), triangle,
                         [](uint32_t t, const SceneObject& o) { return t < o.first_triangle; });
    assert(after != objects.begin());
    return static_cast<uint32_t>(after - objects.begin() - 1);
}

namespace {

// The first invariant that does not hold, or empty.
std::string sceneProblem(const Scene& scene) {
    PositionsView p = scene.positions;
    if (p.x.size() != p.y.size() || p.x.size() != p.z.size())
        return "position arrays have different lengths";
    if (p.x.size() % 3 != 0)
        return "position arrays are not a whole number of triangles";
    if (p.triangleCount() == 0)
        return "scene has no triangles";
    if (p.triangleCount() > std::numeric_limits<uint32_t>::max())
        return "scene has more triangles than 32-bit triangle ids can name";
    for (std::size_t i = 0; i < p.x.size(); ++i) {
        if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i]) || !std::isfinite(p.z[i]))
            return "triangle " + std::to_string(i / 3) + " has a non-finite coordinate";
    }
    if (scene.objects.empty())
        return "scene has no objects";
    uint64_t next = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        // Built only for a message: a scene of millions of objects checks in a blink.
        const auto label = [&] {
            return "object " + std::to_string(i) + " ('" + object.name + "')";
        };
        if (object.first_triangle != next)
            return label() + " starts at triangle " + std::to_string(object.first_triangle) +
                   ", expected " + std::to_string(next);
        if (object.triangle_count == 0)
            return label() + " has no triangles";
        const Rgba& c = object.colour;
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b) ||
            !std::isfinite(c.a))
            return label() + " has a non-finite colour";
        next += object.triangle_count;
    }
    if (next != p.triangleCount())
        return "objects cover " + std::to_string(next) + " triangles, the scene has " +
               std::to_string(p.triangleCount());
    if (scene.camera) {
        const std::string camera_error = validateCamera(*scene.camera).error;
        if (!camera_error.empty())
            return "default camera: " + camera_error;
    }
    return {};
}

} // namespace

Status validateScene(const Scene& scene) {
    return Status{sceneProblem(scene)};
}

} // namespace vissort
