// Scene queries and the invariant check every loaded scene passes.

#include "vissort/scene.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <limits>

#include "vissort/closest_name.h"

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

std::vector<ObjectPart> SceneObject::drawnParts() const {
    if (!parts.empty())
        return parts;
    return {{name, colour, first_triangle, triangle_count}};
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
        const auto finite = [](const Rgba& c) {
            return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) &&
                   std::isfinite(c.a);
        };
        if (!finite(object.colour))
            return label() + " has a non-finite colour";
        uint64_t next_part = object.first_triangle;
        for (const ObjectPart& part : object.parts) {
            if (part.first_triangle != next_part || part.triangle_count == 0)
                return label() + "'s part '" + part.name + "' does not follow its previous part";
            if (!finite(part.colour))
                return label() + "'s part '" + part.name + "' has a non-finite colour";
            next_part += part.triangle_count;
        }
        if (!object.parts.empty() && next_part != next + object.triangle_count)
            return label() + "'s parts do not cover its triangles";
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

std::optional<std::size_t> defaultStoredCamera(const Scene& scene) {
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        if (scene.cameras[i].problem.empty())
            return i;
    return std::nullopt;
}

Result<std::size_t> findStoredCamera(const Scene& scene, const std::string& name_or_index) {
    using Picked = Result<std::size_t>;
    if (scene.cameras.empty())
        return Picked::failure("the scene stores no camera (mesh files such as Collada, glTF or "
                               "FBX can; 'vissort info SCENE' lists them)");
    const auto found = std::find_if(scene.cameras.begin(), scene.cameras.end(),
                                    [&](const StoredCamera& c) { return c.name == name_or_index; });
    std::size_t index = scene.cameras.size();
    if (found != scene.cameras.end()) {
        index = std::size_t(found - scene.cameras.begin());
    } else {
        std::size_t number = 0;
        const char* end = name_or_index.data() + name_or_index.size();
        auto [ptr, ec] = std::from_chars(name_or_index.data(), end, number);
        if (!name_or_index.empty() && ec == std::errc() && ptr == end)
            index = number;
    }
    if (index >= scene.cameras.size()) {
        std::vector<std::string> names;
        for (const StoredCamera& c : scene.cameras)
            names.push_back(c.name);
        const std::string nearest = closestName(name_or_index, names);
        return Picked::failure(
            "no camera '" + name_or_index + "': the scene stores " +
            std::to_string(scene.cameras.size()) +
            (scene.cameras.size() == 1 ? " camera (index 0"
             : scene.cameras.size() == 2
                 ? " cameras (indices 0 and 1"
                 : " cameras (indices 0 to " + std::to_string(scene.cameras.size() - 1)) +
            ", or a name 'vissort info SCENE' lists)" +
            (nearest.empty() ? "" : "; did you mean '" + nearest + "'?"));
    }
    const StoredCamera& picked = scene.cameras[index];
    if (!picked.problem.empty())
        return Picked::failure("camera " + std::to_string(index) + " '" + picked.name +
                               "' cannot be used: " + picked.problem);
    return Picked{index, {}};
}

CameraSpec framingCameraOf(const Scene& scene, double aspect, int frames,
                           const CameraSpec& orientation) {
    if (!scene.isDynamic())
        return framingCamera(scene.positions, aspect, orientation);
    // The frames that will be run, at a bounded number of samples: framed over more (10 s used
    // to be the least), two spiders approaching each other over 30 frames filled 0.6% of it.
    constexpr int kMaxSamples = 32;
    constexpr std::size_t kMaxCorners = std::size_t(4) << 20;
    const std::size_t corners = std::max<std::size_t>(scene.positions.x.size(), 1);
    const int span = std::max(frames, 1);
    const int samples =
        int(std::clamp<std::size_t>(kMaxCorners / corners, 1, std::min(kMaxSamples, span)));
    TrianglePositions all, one;
    for (int s = 0; s < samples; ++s) {
        const int frame = samples == 1 ? 0 : int(std::lround(double(span - 1) * s / (samples - 1)));
        scene.frame(frame * kFrameInterval, one);
        all.x.insert(all.x.end(), one.x.begin(), one.x.end());
        all.y.insert(all.y.end(), one.y.begin(), one.y.end());
        all.z.insert(all.z.end(), one.z.begin(), one.z.end());
    }
    return framingCamera(all, aspect, orientation);
}

} // namespace vissort
