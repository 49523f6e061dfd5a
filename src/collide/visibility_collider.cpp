// The vissort collision method: object boxes, then visibility ordering of the objects along
// view directions (object_culling.h) on the frames where it pays (object_stage_schedule.h),
// then the pairs of triangles of each surviving object pair whose boxes meet (refitted trees,
// refit_bvh.h) and whose extents meet along the four diagonals too (the object stage's other
// directions), then the exact test. Every stage is conservative, so the pairs are exactly brute
// force's: docs/collision.md.
//
// Threads (CollisionSettings::threads) share the per-object work (boxes, refits) and the
// per-pair work (tree descent, exact tests); the object stage is sequential. Each thread
// collects its own pairs: the detector sorts them, so the result does not depend on the thread
// count.

#include "collide/collider.h"
#include "collide/collision_threads.h"
#include "collide/object_culling.h"
#include "collide/object_stage_schedule.h"
#include "collide/refit_bvh.h"
#include "collide/small_pair_scan.h"
#include "collide/triangle_intersection.h"

namespace vissort::detail {
namespace {

class VisibilityCollider final : public Collider {
public:
    VisibilityCollider(std::span<const PrimitiveRange> objects, const CollisionSettings& settings)
        : objects_(objects.begin(), objects.end()), object_culling_(objects, settings),
          schedule_(settings.object_stage), trees_(objects.size()), threads_(settings) {}

    void collide(PositionsView positions, CollisionResult& result) override {
        CollisionStats& stats = result.stats;
        StageClock clock;
        // Only the objects of a pair whose boxes overlap need anything more than their box this
        // frame: their tree, or for a pair of small objects when the object stage does not run,
        // their triangles' boxes (small_pair_scan.h). Coherence guesses which: what an object
        // needed last frame is made at once (a tree's root, or the union of the triangle boxes,
        // is then its box), any other object gets its box straight from its corners (one
        // streaming pass), and what the guess missed is made once the pairs are known. A tree
        // is built the first time its object needs it and refitted every later time (the shape
        // stays, the boxes follow the deformation); a skipped frame leaves nothing stale, as a
        // refit recomputes every box from the positions.
        const bool object_stage = schedule_.runsThisFrame();
        object_boxes_.resize(objects_.size());
        made_.assign(objects_.size(), 0);
        if (triangle_boxes_.empty())
            for (const PrimitiveRange& o : objects_)
                triangle_boxes_.resize(std::max<std::size_t>(
                    triangle_boxes_.size(), std::size_t(o.first_triangle) + o.triangle_count));
        const auto make = [&](uint32_t o, uint8_t what) {
            if (what & kTree) {
                if (trees_[o].isBuilt())
                    trees_[o].refit(positions);
                else
                    trees_[o].build(positions, objects_[o]);
            }
            if (what & kTriangleBoxes)
                computeTriangleBoxes(
                    positions, objects_[o],
                    std::span(triangle_boxes_)
                        .subspan(objects_[o].first_triangle, objects_[o].triangle_count));
            made_[o] |= what;
        };
        threads_.forEach(objects_.size(), [&](std::size_t o, Worker&) {
            const uint8_t guess = needs_.size() == objects_.size() ? needs_[o] : 0;
            if (objects_[o].triangle_count == 0) {
                object_boxes_[o] = kEmptyBox;
            } else if (guess & kTree) {
                make(uint32_t(o), guess);
                object_boxes_[o] = trees_[o].bounds();
            } else if (guess & kTriangleBoxes) {
                make(uint32_t(o), guess);
                object_boxes_[o] = boxOfRange(triangle_boxes_, objects_[o]);
            } else {
                object_boxes_[o] = boxOfCorners(positions, objects_[o]);
            }
        });
        overlappingBoxPairs(object_boxes_, candidates_.objects, sweep_order_);
        candidates_.alive.assign(candidates_.objects.size(), 1);
        stats.box_object_pairs = candidates_.objects.size();
        needs_.assign(objects_.size(), 0);
        for (const auto& [a, b] : candidates_.objects) {
            const uint8_t need = scans(a, b, object_stage) ? kTriangleBoxes : kTree;
            needs_[a] |= need;
            needs_[b] |= need;
        }
        unmade_.clear();
        for (uint32_t o = 0; o < objects_.size(); ++o)
            if (needs_[o] & ~made_[o])
                unmade_.push_back(o);
        threads_.forEach(unmade_.size(), [&](std::size_t i, Worker&) {
            const uint32_t o = unmade_[i];
            make(o, uint8_t(needs_[o] & ~made_[o]));
        });
        stats.update_ms = clock.lap();

        if (object_stage)
            object_culling_.cull(trees_, object_boxes_, candidates_, stats);
        const double object_stage_ms = clock.lap();
        live_.clear();
        in_live_pair_.assign(objects_.size(), 0);
        for (std::size_t i = 0; i < candidates_.objects.size(); ++i) {
            if (!candidates_.alive[i])
                continue;
            live_.push_back(uint32_t(i));
            in_live_pair_[candidates_.objects[i].first] =
                in_live_pair_[candidates_.objects[i].second] = 1;
        }
        stats.object_pairs = live_.size();
        for (uint8_t in : in_live_pair_)
            stats.candidate_objects += in;
        for (Worker& w : threads_.workers())
            w.clear();
        threads_.forEach(live_.size(), [&](std::size_t i, Worker& w) {
            const auto [a, b] = candidates_.objects[live_[i]];
            w.candidates.clear();
            StageClock pair_clock;
            const uint64_t box_pairs =
                scans(a, b, object_stage)
                    ? scannedTrianglePairs(positions, triangle_boxes_, objects_[a], objects_[b],
                                           object_boxes_[a], object_boxes_[b], w.candidates,
                                           w.small_pair_scratch)
                    : overlappingTrianglePairs(trees_[a], trees_[b], positions, w.candidates,
                                               w.scratch);
            if (box_pairs == 0) { // what a pair the object stage culls is like: see below
                w.empty_pair_ms += pair_clock.lap();
                ++w.empty_pairs;
            }
            w.box_triangle_pairs += box_pairs;
            w.triangle_pairs += w.candidates.size();
            StageClock exact_clock;
            for (const auto& [ta, tb] : w.candidates)
                if (trianglesIntersect(cornersOf(positions, ta), cornersOf(positions, tb)))
                    w.pairs.push_back({std::min(ta, tb), std::max(ta, tb)});
            w.exact_ms += exact_clock.lap();
        });
        double exact_ms = 0, empty_pair_ms = 0;
        uint64_t empty_pairs = 0;
        for (const Worker& w : threads_.workers()) {
            empty_pair_ms += w.empty_pair_ms;
            empty_pairs += w.empty_pairs;
            result.pairs.insert(result.pairs.end(), w.pairs.begin(), w.pairs.end());
            stats.triangle_pairs += w.triangle_pairs;
            stats.box_triangle_pairs += w.box_triangle_pairs;
            exact_ms = std::max(exact_ms, w.exact_ms); // the threads' exact tests overlap
        }
        const double descent_ms = clock.lap();
        if (object_stage) {
            // What the stage saved: the descents of the pairs it culled, which would have found
            // no box pair of triangles (they cannot touch), so each costs about what a live pair
            // that found none cost this frame (on one thread: the culled descents would have
            // been shared over the threads too). Without such a pair, the mean of all pairs,
            // which overstates it.
            const std::size_t culled = candidates_.objects.size() - live_.size();
            const double per_pair_ms = empty_pairs > 0 ? empty_pair_ms / double(empty_pairs)
                                       : live_.empty()
                                           ? 0.0
                                           : descent_ms * threads_.count() / double(live_.size());
            schedule_.record(object_stage_ms,
                             double(culled) * per_pair_ms / double(threads_.count()));
        }
        stats.exact_ms = exact_ms;
        stats.cull_ms = object_stage_ms + descent_ms - exact_ms;
    }

private:
    // What an object needs made from this frame's positions, besides its box.
    static constexpr uint8_t kTree = 1, kTriangleBoxes = 2;

    /// Whether the pair of objects a and b takes the scan of small objects rather than their
    /// trees: both small, and no object stage this frame (it draws the trees' parts).
    bool scans(uint32_t a, uint32_t b, bool object_stage) const {
        return !object_stage && objects_[a].triangle_count <= kScanTriangles &&
               objects_[b].triangle_count <= kScanTriangles;
    }

    // One thread's scratch and results in the parallel parts.
    struct Worker {
        std::vector<std::pair<uint32_t, uint32_t>> candidates;
        TrianglePairScratch scratch;
        SmallPairScratch small_pair_scratch;
        std::vector<TrianglePair> pairs;
        uint64_t triangle_pairs = 0, box_triangle_pairs = 0;
        double exact_ms = 0;
        uint64_t empty_pairs = 0; // descended pairs without a box pair of triangles
        double empty_pair_ms = 0; // their descents' time
        void clear() {
            pairs.clear();
            triangle_pairs = box_triangle_pairs = empty_pairs = 0;
            exact_ms = empty_pair_ms = 0;
        }
    };

    std::vector<PrimitiveRange> objects_;
    ObjectCulling object_culling_;
    ObjectStageSchedule schedule_;
    std::vector<RefitBvh> trees_;
    CollisionThreads<Worker> threads_;
    CandidatePairs candidates_;
    std::vector<Box3f> object_boxes_;
    std::vector<uint32_t> sweep_order_; // overlappingBoxPairs' scratch
    std::vector<uint8_t> needs_; // per object: what it needs (kTree, kTriangleBoxes), this frame's
                                 // once the pairs are known, last frame's until then
    std::vector<uint8_t> made_;  // per object: what is made from this frame's positions
    std::vector<uint32_t> unmade_;      // objects needing what the guess did not make
    std::vector<Box3f> triangle_boxes_; // by triangle id: this frame's, for the scanned objects
    std::vector<uint8_t> in_live_pair_; // per object: in some pair the object stage left alive
    std::vector<uint32_t> live_;
};

} // namespace

std::unique_ptr<Collider> makeVisibilityCollider(std::span<const PrimitiveRange> objects,
                                                 const CollisionSettings& settings) {
    return std::make_unique<VisibilityCollider>(objects, settings);
}

} // namespace vissort::detail
