// The Bullet peer of collision detection: one btDbvt per object over its triangles' boxes, built
// once and refitted bottom-up every frame; object boxes by sweep and prune; btDbvt::collideTT
// between the trees of overlapping objects; the exact test on every pair of leaves that meet.
// This work is based on: Erwin Coumans et al., Bullet Physics SDK 3.24, btDbvt; and Gino van den
// Bergen, "Efficient Collision Detection of Complex Deformable Models using AABB Trees", Journal
// of Graphics Tools 2(4), 1997 (refit the tree of a deforming mesh rather than rebuild it).

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>

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
    explicit BulletCollider(std::span<const PrimitiveRange> objects)
        : objects_(objects.begin(), objects.end()), roots_(objects.size(), nullptr),
          object_boxes_(objects.size()) {}

    void collide(PositionsView positions, CollisionResult& result) override {
        StageClock clock;
        if (!built_)
            build(positions);
        else
            refit(positions);
        result.stats.update_ms = clock.lap();

        // Object boxes are the roots' volumes: the union of the exact triangle boxes.
        for (std::size_t o = 0; o < objects_.size(); ++o) {
            Box3f& box = object_boxes_[o];
            if (!roots_[o]) { // an object without triangles meets nothing
                box = kEmptyBox;
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                box.min[k] = roots_[o]->volume.Mins()[k];
                box.max[k] = roots_[o]->volume.Maxs()[k];
            }
        }
        overlappingBoxPairs(object_boxes_, object_pairs_, sweep_order_);
        result.stats.box_object_pairs = result.stats.object_pairs = object_pairs_.size();
        in_pair_.assign(objects_.size(), 0);
        candidates_.clear();
        LeafPairRecorder recorder;
        recorder.candidates = &candidates_;
        for (const auto& [a, b] : object_pairs_) {
            in_pair_[a] = in_pair_[b] = 1;
            // Two distinct trees: every pair of leaves is reached at most once, so no duplicates.
            traverser_.collideTTpersistentStack(roots_[a], roots_[b], recorder);
        }
        for (uint8_t in : in_pair_)
            result.stats.candidate_objects += in;
        result.stats.box_triangle_pairs = result.stats.triangle_pairs = candidates_.size();
        result.stats.cull_ms = clock.lap();

        for (const TrianglePair& c : candidates_)
            if (trianglesIntersect(cornersOf(positions, c.first), cornersOf(positions, c.second)))
                result.pairs.push_back({std::min(c.first, c.second), std::max(c.first, c.second)});
        result.stats.exact_ms = clock.lap();
    }

private:
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

    /// The trees' shapes stay; leaves take the new triangle boxes and every internal node the
    /// union of its children's, which come before it in nodes_. No allocation.
    void refit(PositionsView positions) {
        for (btDbvtNode& node : nodes_)
            if (node.isleaf())
                node.volume = triangleVolume(positions, triangleOfLeaf(&node));
            else
                Merge(node.childs[0]->volume, node.childs[1]->volume, node.volume);
    }

    std::vector<PrimitiveRange> objects_;
    bool built_ = false;
    std::vector<btDbvtNode> nodes_;        // every object's tree, one block each
    std::vector<const btDbvtNode*> roots_; // per object; null without triangles
    btDbvt traverser_; // owns no nodes: lends collideTT and the stack it keeps between calls
    std::vector<Box3f> object_boxes_;
    std::vector<uint32_t> sweep_order_; // overlappingBoxPairs' scratch
    std::vector<std::pair<uint32_t, uint32_t>> object_pairs_;
    std::vector<uint8_t> in_pair_;
    std::vector<TrianglePair> candidates_; // leaf pairs whose boxes meet, this frame
};

} // namespace

std::unique_ptr<Collider> makeBulletCollider(std::span<const PrimitiveRange> objects) {
    return std::make_unique<BulletCollider>(objects);
}

} // namespace vissort::detail
