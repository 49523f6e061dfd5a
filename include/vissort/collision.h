#pragma once
// N-body collision detection: every pair of intersecting triangles that belong to different
// objects, frame after frame, for dynamic scenes of many moving, deforming objects. The
// `vissort` method culls with visibility ordering, after Govindaraju, Henson, Lin, Manocha,
// "Interactive Visibility Ordering and Transparency Computations among Geometric Primitives in
// Complex Environments" (I3D 2005), section 5.3; `brute`, `bullet` and `fcl` are its peers and
// its ground truth. docs/collision.md explains the method and what makes it exact.
//
// Triangles are closed: touching counts as intersecting (a shared point, an edge on a face, a
// coplanar overlap). Pairs within one object (self-collision) are not reported.
//
// Layer: vissort::collide (the package's `collide` component; docs/architecture.md).

#include <chrono>
#include <compare>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "vissort/enum_names.h"
#include "vissort/geometry.h"
#include "vissort/result.h"
#include "vissort/vertex_positions.h"

namespace vissort {

class WorkerPool;

enum class CollisionMethod {
    vissort, // visibility-ordering culling along view directions, then the exact test
    brute,   // every triangle pair of every box-overlapping object pair: the ground truth
    bullet,  // Bullet's btDbvt per object, refitted each frame, tree against tree
    fcl,     // FCL's dynamic AABB tree of OBBRSS models, its own triangle tests (may miss)
};

/// Every method, in the order the benchmarks list them.
inline constexpr EnumName<CollisionMethod> kCollisionMethodNames[] = {
    {CollisionMethod::vissort, "vissort"},
    {CollisionMethod::brute, "brute"},
    {CollisionMethod::bullet, "bullet"},
    {CollisionMethod::fcl, "fcl"},
};
/// "vissort", "brute", "bullet" or "fcl", or "unknown collision method 'NAME' (expected ...)".
inline Result<CollisionMethod> parseCollisionMethod(std::string_view name) {
    return parseEnum<CollisionMethod>(kCollisionMethodNames, name, "collision method");
}
inline const char* collisionMethodName(CollisionMethod method) {
    return enumName<CollisionMethod>(kCollisionMethodNames, method);
}
/// Every method, in the order the benchmarks list them.
std::vector<CollisionMethod> collisionMethods();

/// The object stage's default directions: the three axes, then the four cube diagonals.
std::vector<Vec3> defaultCollisionDirections();

/// When the vissort method runs its object stage (the paper's lists S and C along view
/// directions). On a CPU it costs about what the tree descents it saves cost, more on scenes
/// whose box pairs the trees separate at once: docs/collision.md measures it.
enum class ObjectStage {
    adaptive, // every frame while it saves more descent time than it takes; else skipped for 2,
              // 4, ... up to 32 frames, then tried again (its cost and savings timed each time)
    always,   // every frame: the paper's method
    never,    // boxes, then the trees: the pairs are the same, only the time differs
};
inline constexpr EnumName<ObjectStage> kObjectStageNames[] = {
    {ObjectStage::adaptive, "adaptive"},
    {ObjectStage::always, "always"},
    {ObjectStage::never, "never"},
};
/// "adaptive", "always" or "never", or "unknown object stage 'NAME' (expected ...)".
inline Result<ObjectStage> parseObjectStage(std::string_view name) {
    return parseEnum<ObjectStage>(kObjectStageNames, name, "object stage");
}
inline const char* objectStageName(ObjectStage stage) {
    return enumName<ObjectStage>(kObjectStageNames, stage);
}

/// Two intersecting triangles: global triangle ids, first < second, of different objects.
struct TrianglePair {
    uint32_t first = 0, second = 0;
    friend bool operator==(const TrianglePair&, const TrianglePair&) = default;
    friend auto operator<=>(const TrianglePair&, const TrianglePair&) = default;
};

struct CollisionSettings {
    CollisionMethod method = CollisionMethod::vissort;
    /// vissort: the orthographic view directions of the object stage, tried in turn while the
    /// candidate pairs keep shrinking. Empty: the three axes, then the four cube diagonals.
    std::vector<Vec3> directions;
    /// vissort: the next direction is tried only while the last one culled at least this
    /// fraction of the candidate object pairs it was given. 0: the paper's rule, until C stops
    /// shrinking. On two CPU cores a direction costs about as much as the tree descents of the
    /// pairs it culls, so later directions rarely pay (docs/collision.md).
    float min_cull_fraction = 0.25f;
    /// vissort: when the object stage runs.
    ObjectStage object_stage = ObjectStage::adaptive;
    /// vissort: image size in pixels of each object-stage view (1 to 4096 each way).
    uint32_t width = 64, height = 64;
    /// vissort and bullet: threads for the per-object and per-pair work, the calling thread
    /// included; 0: one per core (std::thread::hardware_concurrency). The pairs never depend on
    /// it.
    uint32_t threads = 1;
    /// vissort and bullet: the pool those threads come from (it must outlive the detector);
    /// null: the process's shared pool (WorkerPool::shared), grown to `threads`. Never one per
    /// detector.
    WorkerPool* pool = nullptr;
};

/// What one frame cost and how much each stage culled.
struct CollisionStats {
    uint64_t box_object_pairs = 0;       // object pairs whose boxes overlap (every method's start)
    uint64_t object_pairs = 0;           // candidate object pairs that reached the triangle stage
    uint64_t box_triangle_pairs = 0;     // of their triangle pairs, those whose boxes overlap
    uint64_t triangle_pairs = 0;         // candidate triangle pairs that reached the exact test
    uint64_t intersecting = 0;           // intersecting triangle pairs found
    uint64_t colliding_object_pairs = 0; // object pairs with some intersecting triangle pair
    uint32_t candidate_objects = 0;      // objects in some candidate object pair (the paper's C)
    uint32_t directions = 0;             // vissort: object-stage directions used this frame
                                         // (0: the object stage did not run)
    uint64_t queries = 0;                // vissort: occlusion queries of the object stage
    double update_ms = 0;                // per-frame structures from the positions (boxes, refits)
    double cull_ms = 0;                  // every culling stage
    double exact_ms = 0;                 // exact triangle tests
    double total_ms = 0;                 // everything after the positions exist
};

/// Every field of CollisionStats by name, in one list (see forEachStat in vis_sort.h): the
/// command line's JSON and CSV and the Python module's dict are written from it. Times end in _ms.
template <class Visit> void forEachStat(const CollisionStats& s, Visit&& visit) {
    visit("box_object_pairs", s.box_object_pairs);
    visit("object_pairs", s.object_pairs);
    visit("box_triangle_pairs", s.box_triangle_pairs);
    visit("triangle_pairs", s.triangle_pairs);
    visit("intersecting", s.intersecting);
    visit("colliding_object_pairs", s.colliding_object_pairs);
    visit("candidate_objects", s.candidate_objects);
    visit("directions", s.directions);
    visit("queries", s.queries);
    visit("update_ms", s.update_ms);
    visit("cull_ms", s.cull_ms);
    visit("exact_ms", s.exact_ms);
    visit("total_ms", s.total_ms);
}

/// Two objects by their index in the detector's object list, first < second.
struct ObjectPair {
    uint32_t first = 0, second = 0;
    friend bool operator==(const ObjectPair&, const ObjectPair&) = default;
    friend auto operator<=>(const ObjectPair&, const ObjectPair&) = default;
};

struct CollisionResult {
    std::vector<TrianglePair> pairs; // ascending, no duplicates
    /// The objects that collide: each pair of objects with some pair above between them,
    /// ascending, no duplicates.
    std::vector<ObjectPair> object_pairs;
    CollisionStats stats;
};

/// Whether the settings are usable; the error says in one line what is wrong.
Status validateCollisionSettings(const CollisionSettings& settings);

namespace detail {
class Collider;
}

/// Finds the intersecting triangle pairs of a fixed set of objects, frame by frame. Keeps what
/// it learns from one frame for the next (orders per direction, trees to refit), so successive
/// frames of one animation are cheapest; any positions work.
class CollisionDetector {
public:
    /// objects: each object's triangles, as ranges of global triangle ids (Scene::
    /// objectPrimitives()), no triangle in two of them; copied. Settings are checked
    /// (validateCollisionSettings): std::invalid_argument on bad values, and on objects that
    /// share triangles.
    explicit CollisionDetector(std::span<const PrimitiveRange> objects,
                               const CollisionSettings& settings = {});
    ~CollisionDetector();
    CollisionDetector(const CollisionDetector&) = delete;
    CollisionDetector& operator=(const CollisionDetector&) = delete;

    /// Every intersecting pair at positions, which must hold every triangle the objects name and
    /// finite coordinates (else std::invalid_argument, nothing computed). Writes into result,
    /// reusing its memory: steady-state frames of the vissort, brute and bullet methods allocate
    /// nothing large.
    void collide(PositionsView positions, CollisionResult& result);
    CollisionResult collide(PositionsView positions);
    /// The same from a vertex buffer (vertex_positions.h: a stride, optional indices), gathered
    /// once into a buffer the detector keeps; std::invalid_argument when gatherPositions refuses
    /// the view, as for positions above.
    void collide(const VertexPositionsView& vertices, CollisionResult& result);

    const CollisionSettings& settings() const { return settings_; }

private:
    CollisionSettings settings_;
    uint64_t triangles_needed_ = 0; // one past the last triangle an object names
    // The objects by their first triangle (non-empty ones): the object of a triangle.
    std::vector<std::pair<uint32_t, uint32_t>> object_starts_; // (first triangle, object)
    std::unique_ptr<detail::Collider> collider_;
    TrianglePositions gathered_; // the corners of the last vertex-buffer frame

    /// std::invalid_argument when positions are not three equal arrays of whole triangles, or
    /// hold fewer triangles than the objects name.
    void checkTriangleCount(PositionsView positions) const;
    /// The frame at checked positions; total_ms counts from start.
    void run(PositionsView positions, std::chrono::steady_clock::time_point start,
             CollisionResult& result);
};

/// The triangles that take part in some pair, each once, ascending (for highlighting).
std::vector<uint32_t> collidingTriangles(std::span<const TrianglePair> pairs);

} // namespace vissort
