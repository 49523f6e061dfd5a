#pragma once
// The object stage of the vissort collision method (Govindaraju et al., I3D 2005, section 5.3):
// Vis-sort of the potentially colliding objects along orthographic view directions, with an
// oracle that fattens each object's parts near a partner to pixel rectangles and depth ranges
// (interval_oracle.h). Objects that sort cleanly along a direction (the paper's list S) cannot
// touch anything; only objects of one reported cycle (strongly connected component) can touch each
// other, so a candidate pair survives a direction only when both lie in one cycle. Internal.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "collide/interval_oracle.h"
#include "collide/refit_bvh.h"
#include "collide/triangle_boxes.h"
#include "vissort/collision.h"
#include "vissort/vis_sort.h"

namespace vissort::detail {

/// Candidate object pairs: object ids a < b, and whether each is still alive (not culled).
struct CandidatePairs {
    std::vector<std::pair<uint32_t, uint32_t>> objects;
    std::vector<uint8_t> alive;

    std::size_t aliveCount() const;
};

class ObjectCulling {
public:
    ObjectCulling(std::span<const PrimitiveRange> objects, const CollisionSettings& settings);

    /// Culls candidates along each direction in turn, keeping alive the pairs whose objects
    /// share a cycle, while a direction culls at least min_cull_fraction of the pairs it was
    /// given (0: until one culls none, the paper's C stopped shrinking) and some are left. trees:
    /// each object's tree, refitted to this frame. Adds the directions used and the queries to
    /// stats.
    void cull(std::span<const RefitBvh> trees, std::span<const Box3f> object_boxes,
              CandidatePairs& candidates, CollisionStats& stats);

private:
    /// One direction: Vis-sort of the candidates' fattened parts; returns the pairs culled.
    std::size_t cullAlong(std::size_t direction, std::span<const RefitBvh> trees,
                          std::span<const Box3f> object_boxes, CandidatePairs& candidates,
                          CollisionStats& stats);

    std::vector<PrimitiveRange> objects_;
    std::vector<Vec3> directions_;
    uint32_t width_, height_;
    float min_cull_fraction_;
    IntervalOracle oracle_;
    // Per direction, each object's place in that direction's last order (coherence): the next
    // frame starts from it. kNoRank until the object was first sorted along it.
    std::vector<std::vector<uint32_t>> rank_;
    // Scratch, reused every frame.
    std::vector<std::vector<uint32_t>> node_marks_; // per object, per tree node: last round cut
    uint32_t mark_round_ = 0;
    std::vector<int32_t> slot_of_; // per object: its place in start_, or -1
    std::vector<uint32_t> start_, slots_, box_starts_, identity_;
    std::vector<std::vector<Box3f>> object_parts_; // per place in start_: the boxes it binds
    std::vector<Box3f> bound_boxes_;
    std::vector<int32_t> cycle_of_;
    std::vector<double> key_;
    VisSortWorkspace workspace_;
    VisibilityOrder sorted_;
};

} // namespace vissort::detail
