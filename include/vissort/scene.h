#pragma once
// A scene: objects made of triangles, with materials, world-space positions, an optional default
// camera and an optional animation (dynamic scenes give positions at time t).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vissort/camera.h"
#include "vissort/camera_path.h"
#include "vissort/geometry.h"
#include "vissort/result.h"

namespace vissort {

struct SceneObject {
    std::string name;
    Rgba colour;
    bool transparent = false;
    uint32_t first_triangle = 0; // triangle ids are global, object 0's triangles first
    uint32_t triangle_count = 0;
};

/// Moves a scene's triangles over time. Implementations must be deterministic.
class Animation {
public:
    virtual ~Animation() = default;
    /// Writes the positions at time t (seconds) into out, resized to the scene's triangle count.
    virtual void positionsAt(double t, TrianglePositions& out) const = 0;
};

struct Scene {
    std::string name;
    std::vector<SceneObject> objects;
    TrianglePositions positions; // at t = 0
    std::optional<CameraSpec> camera;
    /// Key frames for `--path scene` (camera_path.h), times increasing; empty when the scene
    /// has none.
    std::vector<CameraKey> camera_path;
    std::shared_ptr<const Animation> animation; // null for static scenes

    bool isDynamic() const { return animation != nullptr; }
    std::size_t triangleCount() const { return positions.triangleCount(); }
    /// Positions at time t; static scenes ignore t.
    void frame(double t, TrianglePositions& out) const;
    TrianglePositions frame(double t) const;
    /// One primitive per object, in object id order.
    std::vector<PrimitiveRange> objectPrimitives() const;
    /// One primitive per triangle, in triangle id order.
    std::vector<PrimitiveRange> trianglePrimitives() const;
    /// The object that owns a triangle id.
    uint32_t objectOfTriangle(uint32_t triangle) const;
};

/// Loads a scene from a specification:
///   `builtin:NAME?key=value&...`  a named generated scene (see scene_library.h);
///   `PATH.json`                   a JSON scene composing mesh files (docs/scene-format.md);
///   any other path                a mesh file read with assimp (OBJ, PLY, STL, glTF/GLB, ...):
///                                 each mesh of the file is one object, in file order.
/// Rejects missing or unreadable files, empty geometry and non-finite coordinates.
Result<Scene> loadScene(const std::string& specification);

/// Checks a scene's invariants: finite coordinates, object ranges that tile the triangles in
/// order, at least one triangle. A one-line message when one does not hold.
Status validateScene(const Scene& scene);

} // namespace vissort
