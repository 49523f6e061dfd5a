// The vissort collision method: object boxes, then visibility ordering of the objects along
// view directions (object_culling.h), then the pairs of triangle boxes of each surviving object
// pair from refitted trees (refit_bvh.h), then the exact test. Every stage is conservative, so
// the pairs are exactly brute force's: docs/collision.md.

#include "collide/collider.h"
#include "collide/object_culling.h"
#include "collide/refit_bvh.h"
#include "collide/triangle_intersection.h"

namespace vissort::detail {
namespace {

class VisibilityCollider final : public Collider {
public:
    VisibilityCollider(std::span<const PrimitiveRange> objects, const CollisionSettings& settings)
        : objects_(objects.begin(), objects.end()), object_culling_(objects, settings),
          trees_(objects.size()) {}

    void collide(const TrianglePositions& positions, CollisionResult& result) override {
        CollisionStats& stats = result.stats;
        StageClock clock;
        computeTriangleBoxes(positions, triangle_boxes_);
        object_boxes_.resize(objects_.size());
        for (std::size_t o = 0; o < objects_.size(); ++o)
            object_boxes_[o] = boxOfRange(triangle_boxes_, objects_[o]);
        // Only the objects whose boxes meet another's take part: their trees are brought up to
        // date (built on first use; the shape stays, the boxes follow the deformation).
        overlappingBoxPairs(object_boxes_, candidates_.objects);
        candidates_.alive.assign(candidates_.objects.size(), 1);
        refitted_.assign(objects_.size(), 0);
        for (const auto& [a, b] : candidates_.objects)
            for (uint32_t o : {a, b})
                if (!refitted_[o]) {
                    refitted_[o] = 1;
                    if (trees_[o].nodes().empty()) trees_[o].build(triangle_boxes_, objects_[o]);
                    else trees_[o].refit(triangle_boxes_);
                }
        stats.update_ms = clock.lap();

        object_culling_.cull(trees_, object_boxes_, candidates_, stats);
        in_pair_.assign(objects_.size(), 0);
        double exact_ms = 0;
        for (std::size_t i = 0; i < candidates_.objects.size(); ++i) {
            if (!candidates_.alive[i]) continue;
            const auto [a, b] = candidates_.objects[i];
            in_pair_[a] = in_pair_[b] = 1;
            ++stats.object_pairs;
            triangle_pairs_.clear();
            overlappingTrianglePairs(trees_[a], trees_[b], triangle_boxes_, triangle_pairs_, stack_);
            stats.triangle_pairs += triangle_pairs_.size();
            StageClock exact_clock;
            for (const auto& [ta, tb] : triangle_pairs_)
                if (trianglesIntersect(cornersOf(positions, ta), cornersOf(positions, tb)))
                    result.pairs.push_back({std::min(ta, tb), std::max(ta, tb)});
            exact_ms += exact_clock.lap();
        }
        for (uint8_t in : in_pair_) stats.colliding_objects += in;
        stats.exact_ms = exact_ms;
        stats.cull_ms = clock.lap() - exact_ms;
    }

private:
    std::vector<PrimitiveRange> objects_;
    ObjectCulling object_culling_;
    std::vector<RefitBvh> trees_;
    CandidatePairs candidates_;
    std::vector<Box3f> triangle_boxes_, object_boxes_;
    std::vector<uint8_t> refitted_, in_pair_;
    std::vector<std::pair<uint32_t, uint32_t>> triangle_pairs_, stack_;
};

} // namespace

std::unique_ptr<Collider> makeVisibilityCollider(std::span<const PrimitiveRange> objects,
                                                 const CollisionSettings& settings) {
    return std::make_unique<VisibilityCollider>(objects, settings);
}

} // namespace vissort::detail
