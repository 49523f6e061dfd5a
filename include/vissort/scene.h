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
#include "vissort/enum_names.h"
#include "vissort/geometry.h"
#include "vissort/result.h"

namespace vissort {

/// A run of an object's triangles with a material of its own: an object made of several meshes
/// of a file (ObjectGrouping node or file) keeps each mesh as a part, drawn in the mesh's colour.
struct ObjectPart {
    std::string name;
    Rgba colour;
    uint32_t first_triangle = 0; // scene triangle ids, inside the object's range
    uint32_t triangle_count = 0;
};

/// The unit that orders, cycles and collisions speak of.
struct SceneObject {
    std::string name;
    /// For an object with parts: the colour of its largest part, with the least alpha of any
    /// part (so that the object is transparent when a part is).
    Rgba colour;
    bool transparent = false;
    uint32_t first_triangle = 0; // triangle ids are global, object 0's triangles first
    uint32_t triangle_count = 0;
    /// Empty when the whole object has `colour`; else parts tiling its triangles in order.
    std::vector<ObjectPart> parts;

    /// The parts as drawn: `parts`, or the object as one part.
    std::vector<ObjectPart> drawnParts() const;
};

/// How a mesh file's meshes become objects (docs/scene-format.md):
///  - mesh: one object per mesh (an OBJ `g`/`o` group of one material, a glTF primitive);
///  - node: one object per node of the file's hierarchy, its meshes as parts (an OBJ group
///    with several materials, a glTF mesh of several primitives);
///  - file: the whole file one object, its meshes as parts.
/// Triangle ids are the same under mesh and file; node puts a node's meshes together.
enum class ObjectGrouping { mesh, node, file };
inline constexpr EnumName<ObjectGrouping> kObjectGroupingNames[] = {
    {ObjectGrouping::mesh, "mesh"}, {ObjectGrouping::node, "node"}, {ObjectGrouping::file, "file"}};

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
    /// Every file its loading read, as opened: a mesh file and what its reader opened beside
    /// it (an OBJ's .mtl, a glTF's .bin), a JSON scene and its meshes' files. Empty for
    /// built-in scenes and scenes made from arrays. An output must be none of them (the
    /// command line refuses to overwrite an input).
    std::vector<std::string> source_files;

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
///                                 each entry is one object unless it says otherwise;
///   `builtin:NAME?key=value&...`  the scene builtins makes of that name (an error without one);
///   any other path                a mesh file read with assimp (OBJ, PLY, STL, glTF/GLB, ...):
///                                 its meshes become objects as `mesh_file_objects` says (one
///                                 per mesh when unset), in file order.
/// Rejects missing or unreadable files, empty geometry and non-finite coordinates, and checks
/// what builtins makes the same way (validateScene). `mesh_file_objects` set for a JSON or
/// built-in scene is an error: a JSON scene says it in its entries.
Result<Scene> loadScene(const std::string& specification, const BuiltinSceneMaker& builtins = {},
                        std::optional<ObjectGrouping> mesh_file_objects = std::nullopt);

/// A mesh file's bytes already in memory, read as loadScene reads the file: format_hint is its
/// extension ("obj", "ply", ...), label names it in messages.
Result<Scene> loadMeshFromMemory(const void* data, std::size_t size, const std::string& format_hint,
                                 const std::string& label,
                                 ObjectGrouping objects = ObjectGrouping::mesh);

/// The index in scene.cameras of the camera a mesh file's scene uses by default: the first that
/// can be used; none when no stored camera can.
std::optional<std::size_t> defaultStoredCamera(const Scene& scene);

/// The index in scene.cameras of the stored camera `name_or_index` picks: the camera of that
/// name, else the one of that index (0 is the first). Otherwise a one-line error: the scene
/// stores no camera, no camera has that name or index (naming the nearest name), or the camera
/// cannot be used and why.
Result<std::size_t> findStoredCamera(const Scene& scene, const std::string& name_or_index);

/// The camera that frames a scene without one of its own: framingCamera (camera.h) over its
/// geometry; for a dynamic scene over the geometry of the frames that will be run, 0 to
/// frames - 1 (frames kFrameInterval apart, up to 32 of them sampled evenly, fewer when they
/// would hold more than 4M corners), so that the motion stays in the picture. Deterministic.
/// `orientation` as in framingCamera.
CameraSpec framingCameraOf(const Scene& scene, double aspect, int frames = 1,
                           const CameraSpec& orientation = defaultOrientation());

/// Checks a scene's invariants: finite coordinates, object ranges that tile the triangles in
/// order (and parts their object's), at least one triangle. A one-line message when one does not
/// hold.
Status validateScene(const Scene& scene);

} // namespace vissort
