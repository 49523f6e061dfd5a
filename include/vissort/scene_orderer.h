#pragma once
// Ordering primitives frame by frame: the primitive level (objects, triangles, or the paper's
// multi-stage scheme), the first-frame depth-key order, and coherence between frames. Inputs are
// objects' triangle ranges and positions views: no Scene is needed (a Scene gives its objects'
// ranges with Scene::objectPrimitives()).
//
// Layer: vissort::order (the package's `order` component; docs/architecture.md).

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "vissort/camera.h"
#include "vissort/enum_names.h"
#include "vissort/geometry_oracle.h"
#include "vissort/vertex_positions.h"
#include "vissort/vis_sort.h"

namespace vissort {

enum class OrderLevel {
    object,     // one primitive per object; ids are object ids
    triangle,   // one primitive per triangle; ids are triangle ids
    multistage, // objects first, then the triangles of each object or cycle; triangle ids
};

inline constexpr EnumName<OrderLevel> kOrderLevelNames[] = {
    {OrderLevel::object, "object"},
    {OrderLevel::triangle, "triangle"},
    {OrderLevel::multistage, "multistage"},
};
/// "object", "triangle" or "multistage", or "unknown level 'NAME' (expected ...)".
inline Result<OrderLevel> parseOrderLevel(std::string_view name) {
    return parseEnum<OrderLevel>(kOrderLevelNames, name, "level");
}
inline const char* orderLevelName(OrderLevel level) {
    return enumName<OrderLevel>(kOrderLevelNames, level);
}

struct FrameOrder {
    OrderLevel level = OrderLevel::object;
    std::vector<uint32_t> order;               // front to back: object or triangle ids
    std::vector<std::vector<uint32_t>> cycles; // in the same ids, each ascending
    VisSortStats stats;                        // summed over every stage
    double milliseconds = 0;                   // wall time of orderFrame
};

/// The primitives whose ids a level's orders hold: the objects' ranges at object level, else one
/// range per triangle 0..triangle_count-1 (multistage's output is triangles).
std::vector<PrimitiveRange> levelPrimitives(std::span<const PrimitiveRange> objects,
                                            uint32_t triangle_count, OrderLevel level);

/// The same for a scene (vissort::Scene, or anything with objectPrimitives() and
/// triangleCount()): a template, so that ordering does not depend on the scene layer.
template <class SceneLike>
requires requires(const SceneLike& s) {
    s.objectPrimitives();
    s.triangleCount();
}
std::vector<PrimitiveRange> primitivesOf(const SceneLike& scene, OrderLevel level) {
    return levelPrimitives(scene.objectPrimitives(), uint32_t(scene.triangleCount()), level);
}

/// The first-frame order: primitives sorted front to back by the depth of their nearest corner
/// in front of the near plane (a cheap key; ties and primitives entirely behind the camera keep
/// id order after the rest).
std::vector<uint32_t> depthKeyOrder(PositionsView positions, const ViewProjection& view,
                                    std::span<const PrimitiveRange> primitives);

/// Orders successive frames of one set of objects at one level with one oracle. Each frame
/// starts from the previous frame's order (coherence); the first from depthKeyOrder.
class SceneOrderer {
public:
    /// objects: each object's contiguous triangle range, in object id order (copied);
    /// triangle_count: the triangles of the positions given to orderFrame, every object's
    /// range within it. The oracle is bound anew every frame and must outlive the orderer.
    SceneOrderer(std::span<const PrimitiveRange> objects, uint32_t triangle_count, OrderLevel level,
                 GeometryOracle& oracle);

    /// Orders the triangles at `positions` (triangle_count of them) seen through view into out.
    /// out's vectors and the orderer's buffers keep their capacity: once they have grown, a frame
    /// allocates nothing unless Vis-sort meets a cycle (see vis_sort.h).
    void orderFrame(PositionsView positions, const ViewProjection& view, FrameOrder& out);
    /// The same, returning a new FrameOrder (allocates it every frame).
    FrameOrder orderFrame(PositionsView positions, const ViewProjection& view);
    /// The same from a vertex buffer (vertex_positions.h: a stride, optional indices), gathered
    /// once into a buffer the orderer keeps from frame to frame. std::invalid_argument, nothing
    /// ordered, when gatherPositions refuses the view or it holds other than triangle_count
    /// triangles.
    void orderFrame(const VertexPositionsView& vertices, const ViewProjection& view,
                    FrameOrder& out);
    /// The list the next frame starts from, instead of the last frame's order (or, on the first
    /// frame, the depth-key order): a permutation of stage 1's primitives (objects, or triangles
    /// at triangle level), front to back as the caller best knows it. Last frame's cycles are
    /// forgotten. A better start costs fewer queries, never a different validity. Throws
    /// std::invalid_argument when start is not such a permutation.
    void seed(std::span<const uint32_t> start);

    /// New ranges for the same objects (as many as the orderer was made with), from the next
    /// frame on: a level of detail switched, or an object left out of view (an empty range). The
    /// next frame's positions hold triangle_count triangles. Object ids keep their meaning, so
    /// object orders (object level, multistage's first stage) still start from last frame's;
    /// triangle orders start again from the depth-key order when any range changed. Throws
    /// std::invalid_argument for another number of objects.
    void setObjects(std::span<const PrimitiveRange> objects, uint32_t triangle_count);

    /// Reports the share of the frame's primitives ordered so far (0 to 1), after each Vis-sort
    /// iteration, on the thread that orders; for a progress display of a long frame. Multistage
    /// reports its triangle stage. An empty function stops the reports.
    void setProgress(std::function<void(double fraction)> report);

private:
    /// Multistage: each triangle's object (object_of_triangle_), from objects_.
    void indexObjects();
    void orderMultistage(PositionsView positions, const ViewProjection& view, FrameOrder& frame);
    /// Multistage: the end of the group (an object, or the objects of one cycle of cycle_of_)
    /// that starts at object_order[first].
    std::size_t groupEnd(std::span<const uint32_t> object_order, std::size_t first) const;
    /// Multistage: each group's start list (its triangles in last frame's order, as ids local to
    /// the group) into starts_, from group_starts_at_[g]; false on the first frame.
    bool buildGroupStarts(std::span<const uint32_t> object_order);
    /// Sorts stage 1's primitives (triangles at triangle level, else objects) into sorted_,
    /// starting from previous_order_ when it has the right size, else from the depth-key order;
    /// then swaps the order into previous_order_.
    void sortStage1(PositionsView positions, const ViewProjection& view);
    /// Vis-sort of n primitives (primitive(i) is the range of primitive i) from the list `start`
    /// (a permutation of 0..n-1), with the oracle bound to them in that order and the answer
    /// mapped back to primitive indices. same_frame: the positions and view of the last bind
    /// (GeometryOracle::rebind).
    enum class Bind { new_frame, same_frame };
    template <class PrimitiveAt>
    void sortFrom(PositionsView positions, const ViewProjection& view, std::size_t n,
                  const PrimitiveAt& primitive, std::span<const uint32_t> start,
                  VisibilityOrder& into, Bind how = Bind::new_frame, CycleHints hints = {});

    std::vector<PrimitiveRange> objects_;
    uint32_t triangle_count_;
    OrderLevel level_;
    GeometryOracle& oracle_;
    std::function<void(double)> progress_;
    std::size_t progress_base_ = 0, progress_total_ = 0; // what sortFrom's share is out of
    std::vector<uint32_t> previous_order_; // last frame, at level_ (objects for multistage)
    std::vector<uint32_t> previous_triangle_order_; // multistage: last frame's order
    // Last frame's cycles and witnesses (sorted_'s) as hints in this frame's bound ids
    // (CycleHints): cycles are as coherent as orders.
    std::vector<std::vector<uint32_t>> hint_cycles_;
    std::vector<std::vector<Occlusion>> hint_witnesses_;
    std::vector<uint32_t> bound_id_; // primitive -> its id in this frame's bind
    // Reused every frame, so that a steady-state frame without cycles allocates nothing
    // (tests/order/orderer_allocation_tests.cpp).
    VisSortWorkspace workspace_;
    VisibilityOrder sorted_, group_sorted_;
    std::vector<PrimitiveRange> group_;
    std::vector<uint32_t> group_start_;
    std::vector<PrimitiveRange> bound_;     // primitives in start order, as bound
    std::vector<uint32_t> identity_;        // 0..n-1: the start list of the bound primitives
    std::vector<uint32_t> visible_, empty_; // stage 1's objects with triangles, and without
    std::vector<int32_t> cycle_of_;         // multistage: object -> its cycle in stage 1, or -1
    // Multistage's groups (an object, or the objects of a cycle) and their start lists.
    static constexpr uint32_t kNoObject = 0xFFFFFFFFu;
    // Each triangle's object, or kNoObject (a triangle of no object); empty when objects share
    // triangles.
    std::vector<uint32_t> object_of_triangle_;
    std::vector<uint32_t> group_of_object_, first_local_; // object -> group, its first local id
    std::vector<uint32_t> starts_;          // every group's start list, one after another
    std::vector<uint32_t> group_starts_at_; // where each group's start list begins in starts_
    TrianglePositions gathered_;            // the corners of the last vertex-buffer frame
};

} // namespace vissort
