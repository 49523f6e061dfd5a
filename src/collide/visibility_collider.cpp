// The vissort collision method: object boxes, then visibility ordering of the objects along
// view directions (object_culling.h), then the pairs of triangles of each surviving object pair
// whose boxes meet (refitted trees, refit_bvh.h) and whose extents meet along the four
// diagonals too (the object stage's other directions), then the exact test. Every stage is
// conservative, so the pairs are exactly brute force's: docs/collision.md.
//
// Threads (CollisionSettings::threads) share the per-object work (boxes, refits, extents) and
// the per-pair work (tree descent, exact tests); the object stage is sequential and cheap. Each
// thread collects its own pairs: the detector sorts them, so the result does not depend on the
// thread count.

#include <atomic>
#include <thread>

#include "collide/collider.h"
#include "collide/object_culling.h"
#include "collide/refit_bvh.h"
#include "collide/triangle_intersection.h"
#include "vissort/worker_pool.h"

namespace vissort::detail {
namespace {

class VisibilityCollider final : public Collider {
public:
    VisibilityCollider(std::span<const PrimitiveRange> objects, const CollisionSettings& settings)
        : objects_(objects.begin(), objects.end()), object_culling_(objects, settings),
          trees_(objects.size()),
          threads_(settings.threads != 0 ? settings.threads
                                         : std::max(1u, std::thread::hardware_concurrency())),
          workers_(threads_) {
        if (threads_ > 1) {
            pool_ = settings.pool != nullptr ? settings.pool : &WorkerPool::shared();
            pool_->reserve(threads_);
            threads_ = std::min(threads_, pool_->threadCount());
        }
    }

    void collide(PositionsView positions, CollisionResult& result) override {
        CollisionStats& stats = result.stats;
        StageClock clock;
        // Every tree is built on the first frame and refitted on every frame after (the shape
        // stays, the boxes follow the deformation); an object's box is its tree's root.
        object_boxes_.resize(objects_.size());
        parallelFor(objects_.size(), [&](std::size_t o, Worker&) {
            if (objects_[o].triangle_count == 0) {
                object_boxes_[o] = kEmptyBox;
                return;
            }
            if (trees_[o].isBuilt())
                trees_[o].refit(positions);
            else
                trees_[o].build(positions, objects_[o]);
            object_boxes_[o] = trees_[o].bounds();
        });
        overlappingBoxPairs(object_boxes_, candidates_.objects, sweep_order_);
        candidates_.alive.assign(candidates_.objects.size(), 1);
        stats.box_object_pairs = candidates_.objects.size();
        stats.update_ms = clock.lap();

        object_culling_.cull(trees_, object_boxes_, candidates_, stats);
        live_.clear();
        in_pair_.assign(objects_.size(), 0);
        for (std::size_t i = 0; i < candidates_.objects.size(); ++i) {
            if (!candidates_.alive[i])
                continue;
            live_.push_back(uint32_t(i));
            in_pair_[candidates_.objects[i].first] = in_pair_[candidates_.objects[i].second] = 1;
        }
        stats.object_pairs = live_.size();
        for (uint8_t in : in_pair_)
            stats.candidate_objects += in;
        for (Worker& w : workers_)
            w.clear();
        parallelFor(live_.size(), [&](std::size_t i, Worker& w) {
            const auto [a, b] = candidates_.objects[live_[i]];
            w.candidates.clear();
            w.box_triangle_pairs +=
                overlappingTrianglePairs(trees_[a], trees_[b], positions, w.candidates, w.stack);
            w.triangle_pairs += w.candidates.size();
            StageClock exact_clock;
            for (const auto& [ta, tb] : w.candidates)
                if (trianglesIntersect(cornersOf(positions, ta), cornersOf(positions, tb)))
                    w.pairs.push_back({std::min(ta, tb), std::max(ta, tb)});
            w.exact_ms += exact_clock.lap();
        });
        double exact_ms = 0;
        for (const Worker& w : workers_) {
            result.pairs.insert(result.pairs.end(), w.pairs.begin(), w.pairs.end());
            stats.triangle_pairs += w.triangle_pairs;
            stats.box_triangle_pairs += w.box_triangle_pairs;
            exact_ms = std::max(exact_ms, w.exact_ms); // the threads' exact tests overlap
        }
        stats.exact_ms = exact_ms;
        stats.cull_ms = clock.lap() - exact_ms;
    }

private:
    // One thread's scratch and results in the parallel parts.
    struct Worker {
        std::vector<std::pair<uint32_t, uint32_t>> candidates, stack;
        std::vector<TrianglePair> pairs;
        uint64_t triangle_pairs = 0, box_triangle_pairs = 0;
        double exact_ms = 0;
        void clear() {
            pairs.clear();
            triangle_pairs = box_triangle_pairs = 0;
            exact_ms = 0;
        }
    };

    /// body(i, worker) for i = 0..count-1, items claimed one at a time by the threads (pairs
    /// differ widely in cost).
    template <class Body> void parallelFor(std::size_t count, Body&& body) {
        if (!pool_ || count < 2) {
            for (std::size_t i = 0; i < count; ++i)
                body(i, workers_[0]);
            return;
        }
        struct Context {
            Body* body;
            std::vector<Worker>* workers;
            std::size_t count;
            std::atomic<std::size_t> next{0};
        } context{&body, &workers_, count};
        pool_->run(
            uint32_t(std::min<std::size_t>(threads_, count)),
            [](void* c, uint32_t thread) {
                Context& context = *static_cast<Context*>(c);
                for (std::size_t i;
                     (i = context.next.fetch_add(1, std::memory_order_relaxed)) < context.count;)
                    (*context.body)(i, (*context.workers)[thread]);
            },
            &context);
    }

    std::vector<PrimitiveRange> objects_;
    ObjectCulling object_culling_;
    std::vector<RefitBvh> trees_;
    uint32_t threads_;
    std::vector<Worker> workers_;
    WorkerPool* pool_ = nullptr; // the caller's or the shared one; null: single-threaded
    CandidatePairs candidates_;
    std::vector<Box3f> object_boxes_;
    std::vector<uint32_t> sweep_order_; // overlappingBoxPairs' scratch
    std::vector<uint8_t> in_pair_;
    std::vector<uint32_t> live_;
};

} // namespace

std::unique_ptr<Collider> makeVisibilityCollider(std::span<const PrimitiveRange> objects,
                                                 const CollisionSettings& settings) {
    return std::make_unique<VisibilityCollider>(objects, settings);
}

} // namespace vissort::detail
