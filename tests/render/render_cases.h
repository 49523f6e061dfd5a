#pragma once
// The transparency renderer's test scenes and helpers, shared by the renderer's test files: the
// shared OpenGL context, the scenes (cycles, intersections, nesting, depth complexity up to 72),
// their views, settings and one-call renders, and the flat colours the A-buffer reproduces.

#include <gtest/gtest.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "test_scene_loading.h"
#include "vissort/transparency_renderer.h"

namespace vissort::test {

inline std::shared_ptr<GlContext> context() {
    static const Result<std::shared_ptr<GlContext>> shared = GlContext::shared();
    if (!shared)
        ADD_FAILURE() << shared.error;
    return shared ? *shared.value : nullptr;
}

constexpr uint32_t kWidth = 200, kHeight = 150; // not square: rows and columns cannot swap

struct RenderCase {
    std::string name;
    std::string scene;
    bool all_transparent = false; // the scene's files carry no alpha
    float alpha = 0.5f;
    std::optional<CameraSpec> camera; // else the scene's own
    bool wrong_methods_show = true;   // centroid and unsorted miss by more than 1/255 here
    uint32_t min_layers = 1;          // transparent layers the A-buffer must find at some pixel
};

inline void PrintTo(const RenderCase& c, std::ostream* out) {
    *out << c.name;
}

inline CameraSpec orthographic(Vec3 direction) {
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.ortho_direction = direction;
    return camera;
}

inline CameraSpec lookingAt(Vec3 eye, Vec3 target) {
    CameraSpec camera;
    camera.eye = eye;
    camera.target = target;
    return camera;
}

inline std::vector<RenderCase> renderCases() {
    return {
        // Three sticks each over the next: a cycle of objects, no intersection.
        {"ThreeSticksCycle", "tests/data/scenes/three_sticks.json", true, 0.5f, {}, true, 2},
        // A bunny half inside a cow, Suzanne in a box, crossed bars: intersections.
        {"Interpenetrating", "tests/data/scenes/interpenetrating.json", true, 0.5f, {}, true, 4},
        {"InterpenetratingOrthographic", "tests/data/scenes/interpenetrating.json", true, 0.5f,
         orthographic({-0.1, -0.2, -1}), true, 4},
        // Boxes in boxes, Suzanne inside, an opaque core: nesting (every object one cycle).
        {"Nested", "tests/data/scenes/nested.json", false, 0.5f, {}, true, 6},
        // 16 nested boxes: depth complexity 32 at the centre.
        {"NestedBoxesDepth32", "tests/data/scenes/nested_boxes.json", true, 0.25f, {}, true, 31},
        // 36 thin slabs seen from below, against their submission order: depth complexity 72.
        // Centroids sort these slabs right, so only exactness is asked here.
        {"StackDepth72", "tests/data/scenes/stack.json", true, 0.25f,
         lookingAt({0.3, 0.2, -9}, {0, 0, 3.5}), false, 71},
        // The paper's dynamic scene at t = 0: bunnies that intersect and form cycles.
        {"Bunnies", "builtin:bunnies", false, 0.5f, {}, true, 4},
        // Opaque steel and floor with transparent pipes and tanks.
        {"PlantOpaqueAndTransparent", "builtin:plant?layers=3", false, 0.5f, {}, true, 4},
        // One object of four meshes, each in its material: transparent shells, opaque claws
        // through them.
        {"PartsOfOneObject", "tests/data/scenes/crabs.json", false, 0.5f,
         lookingAt({6, -5, 7}, {6, 1, 0}), false, 1},
    };
}

inline ViewProjection viewOf(const Scene& scene, const RenderCase& c) {
    const Bounds bounds = scene.positions.bounds();
    const CameraSpec camera =
        c.camera.value_or(scene.camera.value_or(defaultCamera(bounds, double(kWidth) / kHeight)));
    return frameCamera(camera, bounds, kWidth, kHeight);
}

inline RenderSettings settingsOf(const RenderCase& c, BlendMethod method,
                                 OrderLevel level = OrderLevel::object) {
    RenderSettings settings;
    settings.method = method;
    settings.level = level;
    settings.all_transparent = c.all_transparent;
    settings.alpha = c.alpha;
    return settings;
}

inline std::vector<uint8_t> render(const Scene& scene, const RenderSettings& settings,
                                   const ViewProjection& view, RenderStats* stats = nullptr) {
    TransparencyRenderer renderer(context(), scene, settings);
    RenderStats local;
    return renderer.render(scene.positions, view, stats ? *stats : local).toRgba8();
}

// Each triangle's colour as the renderer's flat shading uses it.
inline std::vector<Rgba> triangleColours(const Scene& scene, const RenderSettings& settings) {
    std::vector<Rgba> colours(scene.triangleCount());
    for (const SceneObject& object : scene.objects) {
        const bool transparent =
            settings.all_transparent || (object.transparent && object.colour.a < 1.0f);
        // Each mesh of an object in its own colour: the parts, or the object's one colour.
        const std::vector<ObjectPart> parts =
            object.parts.empty()
                ? std::vector<ObjectPart>{{object.name, object.colour, object.first_triangle,
                                           object.triangle_count}}
                : object.parts;
        for (const ObjectPart& part : parts) {
            Rgba colour = part.colour;
            colour.a = settings.all_transparent ? settings.alpha : transparent ? colour.a : 1.0f;
            for (uint32_t t = 0; t < part.triangle_count; ++t)
                colours[part.first_triangle + t] = colour;
        }
    }
    return colours;
}

/// The colours shading.h documents for highlighted triangles: the highlighted magenta and opaque,
/// every other (untinted) triangle dimmed: 60% of the way to grey 0.5, a transparent one's alpha
/// 0.3 of its own. `untinted` says which triangles carry no other tint (all when null).
inline void highlightColours(std::vector<Rgba>& colours, const std::vector<uint32_t>& highlighted,
                             const std::vector<bool>* untinted = nullptr) {
    for (std::size_t t = 0; t < colours.size(); ++t) {
        if (untinted && !(*untinted)[t])
            continue;
        Rgba& c = colours[t];
        c = {c.r + 0.6f * (0.5f - c.r), c.g + 0.6f * (0.5f - c.g), c.b + 0.6f * (0.5f - c.b),
             c.a < 1.0f ? c.a * 0.3f : 1.0f};
    }
    for (uint32_t t : highlighted)
        colours[t] = {1.0f, 0.1f, 0.55f, 1.0f};
}

} // namespace vissort::test
