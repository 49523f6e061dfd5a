// The ground truth of collision detection: every pair of objects whose boxes overlap, every pair
// of their triangles whose boxes overlap, the exact test on each. Nothing but boxes and the exact
// test, so nothing to get wrong: a closed box holds its triangle exactly (float minima and
// maxima), and triangles whose closed boxes are apart cannot share a point.

#include "collide/collider.h"
#include "collide/triangle_boxes.h"
#include "collide/triangle_intersection.h"

namespace vissort::detail {
namespace {

class BruteForceCollider final : public Collider {
public:
    explicit BruteForceCollider(std::span<const PrimitiveRange> objects)
        : objects_(objects.begin(), objects.end()) {}

    void collide(PositionsView positions, CollisionResult& result) override {
        StageClock clock;
        computeTriangleBoxes(positions, triangle_boxes_);
        object_boxes_.resize(objects_.size());
        for (std::size_t o = 0; o < objects_.size(); ++o)
            object_boxes_[o] = boxOfRange(triangle_boxes_, objects_[o]);
        result.stats.update_ms = clock.lap();

        overlappingBoxPairs(object_boxes_, object_pairs_, sweep_order_);
        result.stats.box_object_pairs = result.stats.object_pairs = object_pairs_.size();
        in_pair_.assign(objects_.size(), 0);
        double exact_ms = 0;
        for (const auto& [a, b] : object_pairs_) {
            in_pair_[a] = in_pair_[b] = 1;
            near_a_.clear();
            near_b_.clear();
            appendTrianglesMeetingBox(triangle_boxes_, objects_[a], object_boxes_[b], near_a_);
            appendTrianglesMeetingBox(triangle_boxes_, objects_[b], object_boxes_[a], near_b_);
            for (uint32_t ta : near_a_)
                for (uint32_t tb : near_b_) {
                    if (!boxesOverlap(triangle_boxes_[ta], triangle_boxes_[tb]))
                        continue;
                    ++result.stats.triangle_pairs;
                    if (trianglesIntersect(cornersOf(positions, ta), cornersOf(positions, tb)))
                        result.pairs.push_back({std::min(ta, tb), std::max(ta, tb)});
                }
        }
        for (uint8_t in : in_pair_)
            result.stats.candidate_objects += in;
        result.stats.box_triangle_pairs = result.stats.triangle_pairs;
        // The box filters and the exact tests interleave here; the exact tests are the work.
        exact_ms = clock.lap();
        result.stats.exact_ms = exact_ms;
    }

private:
    std::vector<PrimitiveRange> objects_;
    std::vector<Box3f> triangle_boxes_, object_boxes_;
    std::vector<uint32_t> sweep_order_; // overlappingBoxPairs' scratch
    std::vector<std::pair<uint32_t, uint32_t>> object_pairs_;
    std::vector<uint8_t> in_pair_;
    std::vector<uint32_t> near_a_, near_b_;
};

} // namespace

std::unique_ptr<Collider> makeBruteForceCollider(std::span<const PrimitiveRange> objects) {
    return std::make_unique<BruteForceCollider>(objects);
}

} // namespace vissort::detail
