// The object stage of collision culling by visibility ordering: Govindaraju, Henson, Lin,
// Manocha, "Interactive Visibility Ordering and Transparency Computations among Geometric
// Primitives in Complex Environments", I3D 2005, section 5.3 (lists S and C along several
// directions), on Vis-sort's cycles. Why it never drops a colliding pair: docs/collision.md.

#include "collide/object_culling.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace vissort::detail {
namespace {

constexpr uint32_t kNoRank = std::numeric_limits<uint32_t>::max();
// Triangles per fattened part: a part's box is one splat, so fewer splats against tighter ones.
constexpr uint32_t kPartTriangles = 8;

// The least distance along direction d of a box's corners: a depth key for the first order.
double nearestAlong(const Box3f& box, const Vec3& d) {
    const double axis[3] = {d.x, d.y, d.z};
    double key = 0;
    for (int k = 0; k < 3; ++k)
        key += axis[k] * (axis[k] >= 0 ? box.min[k] : box.max[k]);
    return key;
}

} // namespace

std::size_t CandidatePairs::aliveCount() const {
    return std::size_t(std::count(alive.begin(), alive.end(), uint8_t(1)));
}

ObjectCulling::ObjectCulling(std::span<const PrimitiveRange> objects,
                             const CollisionSettings& settings)
    : objects_(objects.begin(), objects.end()),
      directions_(settings.directions.empty() ? defaultCollisionDirections() : settings.directions),
      width_(settings.width), height_(settings.height),
      min_cull_fraction_(settings.min_cull_fraction) {
    rank_.assign(directions_.size(), std::vector<uint32_t>(objects_.size(), kNoRank));
    cycle_of_.assign(objects_.size(), -1);
    slot_of_.assign(objects_.size(), -1);
}

void ObjectCulling::cull(std::span<const RefitBvh> trees, std::span<const Box3f> object_boxes,
                         CandidatePairs& candidates, CollisionStats& stats) {
    for (std::size_t d = 0; d < directions_.size(); ++d) {
        const std::size_t given = candidates.aliveCount();
        if (given == 0)
            break;
        const std::size_t culled = cullAlong(d, trees, object_boxes, candidates, stats);
        if (culled == 0 || double(culled) < double(min_cull_fraction_) * double(given))
            break;
    }
}

std::size_t ObjectCulling::cullAlong(std::size_t direction, std::span<const RefitBvh> trees,
                                     std::span<const Box3f> object_boxes,
                                     CandidatePairs& candidates, CollisionStats& stats) {
    const Vec3& d = directions_[direction];
    std::vector<uint32_t>& rank = rank_[direction];
    // C: the objects of the live pairs, each bound to the boxes of its tree's shallowest nodes of
    // at most kPartTriangles triangles that meet a partner's box (only those can touch it).
    start_.clear();
    node_marks_.resize(objects_.size());
    if (++mark_round_ == 0) { // wrapped: old marks could match again
        for (auto& marks : node_marks_)
            std::fill(marks.begin(), marks.end(), 0);
        mark_round_ = 1;
    }
    const auto add = [&](uint32_t object, uint32_t partner) {
        if (slot_of_[object] < 0) {
            slot_of_[object] = int32_t(start_.size());
            start_.push_back(object);
            if (object_parts_.size() < start_.size())
                object_parts_.resize(start_.size());
            object_parts_[start_.size() - 1].clear();
        }
        trees[object].appendCut(object_boxes[partner], kPartTriangles, node_marks_[object],
                                mark_round_, object_parts_[std::size_t(slot_of_[object])]);
    };
    for (std::size_t i = 0; i < candidates.objects.size(); ++i) {
        if (!candidates.alive[i])
            continue;
        add(candidates.objects[i].first, candidates.objects[i].second);
        add(candidates.objects[i].second, candidates.objects[i].first);
    }

    // The start list: last frame's order along this direction (coherence), or a depth key.
    std::vector<uint32_t>& slots = slots_; // places in start_, in start-list order
    slots.resize(start_.size());
    std::iota(slots.begin(), slots.end(), 0u);
    const bool all_ranked =
        std::all_of(start_.begin(), start_.end(), [&](uint32_t o) { return rank[o] != kNoRank; });
    if (all_ranked) {
        std::sort(slots.begin(), slots.end(),
                  [&](uint32_t a, uint32_t b) { return rank[start_[a]] < rank[start_[b]]; });
    } else {
        key_.resize(start_.size());
        for (std::size_t s = 0; s < start_.size(); ++s)
            key_[s] = nearestAlong(object_boxes[start_[s]], d);
        std::sort(slots.begin(), slots.end(), [&](uint32_t a, uint32_t b) {
            return key_[a] < key_[b] || (key_[a] == key_[b] && start_[a] < start_[b]);
        });
    }

    // Bind in start order (Vis-sort's list is then the identity), framed by the parts' boxes.
    bound_boxes_.clear();
    box_starts_.assign(1, 0);
    for (uint32_t s : slots) {
        bound_boxes_.insert(bound_boxes_.end(), object_parts_[s].begin(), object_parts_[s].end());
        box_starts_.push_back(uint32_t(bound_boxes_.size()));
    }
    Box3f frame{};
    if (!bound_boxes_.empty())
        frame = bound_boxes_.front();
    for (const Box3f& part : bound_boxes_)
        includeBox(frame, part);
    oracle_.bind(bound_boxes_, box_starts_, frame, d, width_, height_);
    if (identity_.size() != slots.size()) {
        identity_.resize(slots.size());
        std::iota(identity_.begin(), identity_.end(), 0u);
    }
    visSort(oracle_, identity_, sorted_, workspace_);
    stats.queries += sorted_.stats.queries;
    ++stats.directions;

    const auto object_at = [&](uint32_t bound) { return start_[slots[bound]]; };
    for (std::size_t i = 0; i < sorted_.order.size(); ++i)
        rank[object_at(sorted_.order[i])] = uint32_t(i);
    for (std::size_t c = 0; c < sorted_.cycles.size(); ++c)
        for (uint32_t p : sorted_.cycles[c])
            cycle_of_[object_at(p)] = int32_t(c);
    std::size_t culled = 0;
    for (std::size_t i = 0; i < candidates.objects.size(); ++i) {
        if (!candidates.alive[i])
            continue;
        const auto [a, b] = candidates.objects[i];
        if (cycle_of_[a] < 0 || cycle_of_[a] != cycle_of_[b]) {
            candidates.alive[i] = 0;
            ++culled;
        }
    }
    for (uint32_t o : start_) {
        cycle_of_[o] = -1;
        slot_of_[o] = -1;
    }
    return culled;
}

} // namespace vissort::detail
