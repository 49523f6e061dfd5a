#pragma once
// A scene: objects made of triangles, with materials, world-space positions, an optional default
// camera and an optional animation (dynamic scenes give positions at time t).
//
// Layer: vissort::scene (the package's `scene` component; docs/architecture.md).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
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

/// A camera stored in a mesh file (Collada, glTF, FBX, 3DS, ...): its name there and the view it
/// gives (orthographic ones keep their direction only: vissort frames the scene along it).
/// `problem` says in one line why it cannot be used (a zero field of view, up along the view
/// direction), else it is empty.
struct StoredCamera {
    std::string name;
    CameraSpec camera;
    std::string problem;
};

struct Scene {
    std::string name;
    std::vector<SceneObject> objects;
    TrianglePositions positions;      // at t = 0
    std::optional<CameraSpec> camera; // for a mesh file, its defaultStoredCamera
    /// A mesh file's own cameras, in file order (`--camera NAME|INDEX` picks one); empty for
    /// other scenes.
    std::vector<StoredCamera> cameras;
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

/// key=value parameters of a `builtin:NAME?key=value&...` specification.
using SceneParameters = std::map<std::string, std::string>;
/// Makes the named scene of a `builtin:NAME?key=value&...` specification, or a one-line error
/// naming the problem. The library has no named scenes of its own: the samples' generators
/// (samples/scenes/scene_library.h: bunnies, the power plant, ...) are one such maker.
using BuiltinSceneMaker =
    std::function<Result<Scene>(const std::string& name, const SceneParameters& parameters)>;

/// Loads a scene from a specification:
///   `PATH.json`                   a JSON scene composing mesh files (docs/scene-format.md);
///   `builtin:NAME?key=value&...`  the scene builtins makes of that name (an error without one);
///   any other path                a mesh file read with assimp (OBJ, PLY, STL, glTF/GLB, ...):
///                                 each mesh of the file is one object, in file order.
/// Rejects missing or unreadable files, empty geometry and non-finite coordinates, and checks
/// what builtins makes the same way (validateScene).
Result<Scene> loadScene(const std::string& specification, const BuiltinSceneMaker& builtins = {});

/// A mesh file's bytes already in memory, read as loadScene reads the file: format_hint is its
/// extension ("obj", "ply", ...), label names it in messages.
Result<Scene> loadMeshFromMemory(const void* data, std::size_t size, const std::string& format_hint,
                                 const std::string& label);

/// The index in scene.cameras of the camera a mesh file's scene uses by default: the first that
/// can be used; none when no stored camera can.
std::optional<std::size_t> defaultStoredCamera(const Scene& scene);

/// The index in scene.cameras of the stored camera `name_or_index` picks: the camera of that
/// name, else the one of that index (0 is the first). Otherwise a one-line error: the scene
/// stores no camera, no camera has that name or index (naming the nearest name), or the camera
/// cannot be used and why.
Result<std::size_t> findStoredCamera(const Scene& scene, const std::string& name_or_index);

/// The camera that frames a scene without one of its own: framingCamera (camera.h) over its
/// geometry; for a dynamic scene over the geometry of frames 0 to max(frames, 300) - 1 (frames
/// kFrameInterval apart, up to 32 of them sampled evenly, fewer when they would hold more than
/// 4M corners), so that the motion stays in the picture. Deterministic.
/// `orientation` as in framingCamera.
CameraSpec framingCameraOf(const Scene& scene, double aspect, int frames = 1,
                           const CameraSpec& orientation = defaultOrientation());

/// Checks a scene's invariants: finite coordinates, object ranges that tile the triangles in
/// order, at least one triangle. A one-line message when one does not hold.
Status validateScene(const Scene& scene);

} // namespace vissort
