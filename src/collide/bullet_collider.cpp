// The Bullet peer of collision detection: one btDbvt per object over its triangles' boxes, built
// once and refitted bottom-up every frame; the objects' boxes in a btDbvtBroadphase, as Bullet's
// users run it; btDbvt::collideTT between the trees of overlapping objects; the exact test on
// every pair of leaves that meet. The refits and the object pairs are shared over
// CollisionSettings::threads as the vissort method's are (collision_threads.h), so that the two
// are measured on the same resources.
// This work is based on: Erwin Coumans et al., Bullet Physics SDK 3.24, btDbvt; and Gino van den
// Bergen, "Efficient Collision Detection of Complex Deformable Models using AABB Trees", Journal
// of Graphics Tools 2(4), 1997 (refit the tree of a deforming mesh rather than rebuild it).

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>

#include "collide/collision_threads.h"
#include "collide/peer_colliders.h"
#include "collide/triangle_boxes.h"
#include "collide/triangle_intersection.h"

namespace vissort::detail {
namespace {

/// Leaves carry their global triangle id in btDbvtNode::data.
void* leafData(uint32_t triangle) {
    return reinterpret_cast<void*>(uintptr_t(triangle));
}
uint32_t triangleOfLeaf(const btDbvtNode* leaf) {
    return uint32_t(reinterpret_cast<uintptr_t>(leaf->data));
}

/// The exact float box of triangle t: no margin, so the trees cull exactly what brute force's
/// boxes cull (closed boxes: Bullet's Intersect counts touching).
btDbvtVolume triangleVolume(PositionsView positions, uint32_t t) {
    const std::size_t i = 3 * std::size_t(t);
    const float* x = positions.x.data() + i;
    const float* y = positions.y.data() + i;
    const float* z = positions.z.data() + i;
    return btDbvtVolume::FromMM(
        btVector3(std::min({x[0], x[1], x[2]}), std::min({y[0], y[1], y[2]}),
                  std::min({z[0], z[1], z[2]})),
        btVector3(std::max({x[0], x[1], x[2]}), std::max({y[0], y[1], y[2]}),
                  std::max({z[0], z[1], z[2]})));
}

/// collideTT's policy: records each pair of leaves whose boxes meet; the exact tests run after
/// the traversal, in their own loop, so that cull_ms and exact_ms each time one stage without a
/// clock read per test.
struct LeafPairRecorder final : btDbvt::ICollide {
    using btDbvt::ICollide::Process;
    void Process(const btDbvtNode* a, const btDbvtNode* b) override {
        candidates->push_back({triangleOfLeaf(a), triangleOfLeaf(b)});
    }
    std::vector<TrianglePair>* candidates = nullptr;
};

class BulletCollider final : public Collider {
public:
    BulletCollider(std::span<const PrimitiveRange> objects, const CollisionSettings& settings)
        : objects_(objects.begin(), objects.end()), roots_(objects.size(), nullptr),
          blocks_(objects.size()), proxies_(objects.size(), nullptr), threads_(settings) {}

    ~BulletCollider() override {
        for (btBroadphaseProxy* proxy : proxies_)
            if (proxy)
                broadphase_.destroyProxy(proxy, nullptr);
    }

    void collide(PositionsView positions, CollisionResult& result) override {
        CollisionStats& stats = result.stats;
        StageClock clock;
        if (!built_)
            build(positions);
        else
            threads_.forEach(objects_.size(),
                             [&](std::size_t o, Worker&) { refit(positions, blocks_[o]); });
        stats.update_ms = clock.lap();

        // The broad phase as Bullet's users run it: one proxy per object in a btDbvtBroadphase,
        // its box the root's volume (the union of the exact triangle boxes), then the pairs of
        // its cache. Its proxies' volumes are fattened (Bullet's margin and prediction), so a
        // pair's roots are tested again before the descent.
        for (std::size_t o = 0; o < objects_.size(); ++o) {
            if (!roots_[o]) // an object without triangles meets nothing
                continue;
            const btDbvtVolume& box = roots_[o]->volume;
            if (!proxies_[o])
                proxies_[o] = broadphase_.createProxy(box.Mins(), box.Maxs(), 0, objectData(o), 1,
                                                      -1, nullptr);
            else
                broadphase_.setAabb(proxies_[o], box.Mins(), box.Maxs(), nullptr);
        }
        broadphase_.calculateOverlappingPairs(nullptr);
        const btBroadphasePairArray& cached =
            broadphase_.getOverlappingPairCache()->getOverlappingPairArray();
        object_pairs_.clear();
        for (int k = 0; k < cached.size(); ++k) {
            const uint32_t a = objectOf(cached[k].m_pProxy0), b = objectOf(cached[k].m_pProxy1);
            if (Intersect(roots_[a]->volume, roots_[b]->volume))
                object_pairs_.emplace_back(a, b);
        }
        stats.box_object_pairs = stats.object_pairs = object_pairs_.size();
        in_pair_.assign(objects_.size(), 0);
        for (const auto& [a, b] : object_pairs_)
            in_pair_[a] = in_pair_[b] = 1;
        for (uint8_t in : in_pair_)
            stats.candidate_objects += in;

        // Tree against tree per object pair, shared over the threads; each pair's leaf pairs
        // are tested exactly at once, by the thread that found them.
        for (Worker& w : threads_.workers())
            w.clear();
        threads_.forEach(object_pairs_.size(), [&](std::size_t i, Worker& w) {
            const auto [a, b] = object_pairs_[i];
            w.candidates.clear();
            LeafPairRecorder recorder;
            recorder.candidates = &w.candidates;
            // Two distinct trees: every pair of leaves is reached at most once, so no duplicates.
            w.traverser.collideTTpersistentStack(roots_[a], roots_[b], recorder);
            w.triangle_pairs += w.candidates.size();
            StageClock exact_clock;
            for (const TrianglePair& c : w.candidates)
                if (trianglesIntersect(cornersOf(positions, c.first),
                                       cornersOf(positions, c.second)))
                    w.pairs.push_back({std::min(c.first, c.second), std::max(c.first, c.second)});
            w.exact_ms += exact_clock.lap();
        });
        double exact_ms = 0;
        for (const Worker& w : threads_.workers()) {
            result.pairs.insert(result.pairs.end(), w.pairs.begin(), w.pairs.end());
            stats.triangle_pairs += w.triangle_pairs;
            exact_ms = std::max(exact_ms, w.exact_ms); // the threads' exact tests overlap
        }
        stats.box_triangle_pairs = stats.triangle_pairs;
        stats.exact_ms = exact_ms;
        stats.cull_ms = clock.lap() - exact_ms;
    }

private:
    // One thread's traverser, scratch and results.
    struct Worker {
        btDbvt traverser; // owns no nodes: lends collideTT and the stack it keeps between calls
        std::vector<TrianglePair> candidates; // leaf pairs whose boxes meet, this object pair
        std::vector<TrianglePair> pairs;
        uint64_t triangle_pairs = 0;
        double exact_ms = 0;
        void clear() {
            pairs.clear();
            triangle_pairs = 0;
            exact_ms = 0;
        }
    };

    static void* objectData(std::size_t object) {
        return reinterpret_cast<void*>(uintptr_t(object));
    }
    static uint32_t objectOf(const btBroadphaseProxy* proxy) {
        return uint32_t(reinterpret_cast<uintptr_t>(proxy->m_clientObject));
    }

    /// First frame: Bullet builds each object's tree (insert every triangle's box, then
    /// optimizeTopDown for a better tree than incremental insertion gives); the tree is then
    /// copied into nodes_, one block per object: its leaves in triangle order, then its internal
    /// nodes in post-order, root last. Refit is then one forward pass over nodes_, streaming the
    /// positions, instead of chasing Bullet's separately allocated nodes.
    void build(PositionsView positions) {
        std::size_t node_count = 0;
        for (const PrimitiveRange& range : objects_)
            if (range.triangle_count > 0)
                node_count += 2 * std::size_t(range.triangle_count) - 1;
        nodes_.resize(node_count); // never resized again: the nodes point at each other
        btDbvt tree;
        std::size_t block = 0;
        for (std::size_t o = 0; o < objects_.size(); ++o) {
            const PrimitiveRange range = objects_[o];
            if (range.triangle_count == 0)
                continue;
            for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
                 ++t)
                tree.insert(triangleVolume(positions, t), leafData(t));
            tree.optimizeTopDown();
            std::size_t next_internal = block + range.triangle_count;
            roots_[o] = copyTree(tree.m_root, range, block, next_internal);
            nodes_[next_internal - 1].parent = nullptr;
            blocks_[o] = {block, next_internal};
            block = next_internal;
            tree.clear();
        }
        built_ = true;
    }

    /// Copies the subtree at node into the block starting at block; returns the copy, whose parent
    /// the caller sets.
    btDbvtNode* copyTree(const btDbvtNode* node, PrimitiveRange range, std::size_t block,
                         std::size_t& next_internal) {
        btDbvtNode* copy;
        if (node->isleaf()) {
            copy = &nodes_[block + (triangleOfLeaf(node) - range.first_triangle)];
            copy->data = node->data;
            copy->childs[1] = nullptr; // what makes it a leaf
        } else {
            btDbvtNode* child0 = copyTree(node->childs[0], range, block, next_internal);
            btDbvtNode* child1 = copyTree(node->childs[1], range, block, next_internal);
            copy = &nodes_[next_internal++];
            copy->childs[0] = child0;
            copy->childs[1] = child1;
            child0->parent = child1->parent = copy;
        }
        copy->volume = node->volume;
        return copy;
    }

    /// One object's tree (its block of nodes_): the shape stays; leaves take the new triangle
    /// boxes and every internal node the union of its children's, which come before it in the
    /// block. No allocation.
    void refit(PositionsView positions, std::pair<std::size_t, std::size_t> block) {
        for (std::size_t i = block.first; i < block.second; ++i) {
            btDbvtNode& node = nodes_[i];
            if (node.isleaf())
                node.volume = triangleVolume(positions, triangleOfLeaf(&node));
            else
                Merge(node.childs[0]->volume, node.childs[1]->volume, node.volume);
        }
    }

    std::vector<PrimitiveRange> objects_;
    bool built_ = false;
    std::vector<btDbvtNode> nodes_;                           // every object's tree, one block each
    std::vector<const btDbvtNode*> roots_;                    // per object; null without triangles
    std::vector<std::pair<std::size_t, std::size_t>> blocks_; // per object: its nodes_ [begin, end)
    btDbvtBroadphase broadphase_;
    std::vector<btBroadphaseProxy*> proxies_; // per object; null without triangles
    CollisionThreads<Worker> threads_;
    std::vector<std::pair<uint32_t, uint32_t>> object_pairs_;
    std::vector<uint8_t> in_pair_;
};

} // namespace

std::unique_ptr<Collider> makeBulletCollider(std::span<const PrimitiveRange> objects,
                                             const CollisionSettings& settings) {
    return std::make_unique<BulletCollider>(objects, settings);
}

} // namespace vissort::detail
