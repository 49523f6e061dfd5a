#pragma once
// A bounding-volume hierarchy of one object's triangles whose shape is built once and whose
// boxes are refitted bottom-up every frame (van den Bergen, "Efficient Collision Detection of
// Complex Deformable Models using AABB Trees", 1997): deforming objects keep their topology, so
// a refit costs one pass over the triangles and one over the nodes. Used for the fattened parts
// of the object stage (cuts of the tree) and to pair the triangles of two objects. Internal.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "collide/box_columns.h"
#include "collide/triangle_boxes.h"
#include "vissort/geometry.h"

namespace vissort::detail {

class RefitBvh {
public:
    /// A node over the leaf-order triangles [first, first + size). A leaf when size <=
    /// kLeafSize; otherwise its children are the next node and node `right`. Its subtree ends
    /// before node `after`.
    struct Node {
        Box3f box;
        uint32_t first = 0, size = 0, right = 0, after = 0;
        bool isLeaf() const { return size <= kLeafSize; }
    };
    static constexpr uint32_t kLeafSize = 8;
    static_assert(kLeafSize <= 2 * BoxColumns::kLanes, "a leaf is tested in at most two masks");

    /// Builds the tree of object's triangles (at least one) at positions: median splits of the
    /// triangles' box centres, on the axis whose halves have the least surface area. The boxes
    /// are then current.
    void build(PositionsView positions, PrimitiveRange object);
    /// Recomputes every node's box from positions (the same triangle count); the triangles'
    /// boxes are not kept (overlappingTrianglePairs makes those of the leaves it reaches).
    void refit(PositionsView positions);
    bool isBuilt() const { return !nodes_.empty(); }

    const Box3f& bounds() const { return nodes_.front().box; }
    std::span<const Node> nodes() const { return nodes_; }
    /// Global triangle ids in leaf order.
    std::span<const uint32_t> triangles() const { return triangles_; }

    /// Appends the boxes of the shallowest nodes of at most max_size triangles that meet
    /// region, once each (marks: per node, round: this call's mark).
    void appendCut(const Box3f& region, uint32_t max_size, std::vector<uint32_t>& marks,
                   uint32_t round, std::vector<Box3f>& out) const;

private:
    /// What building needs and the tree does not keep: boxes[i] is the box of triangles_[i];
    /// the rest is one node's work space, reused by the next (a node is done with it before
    /// its children start).
    struct BuildScratch {
        std::vector<Box3f> boxes;
        std::vector<std::pair<float, uint32_t>> centres[3]; // per axis: (2 x centre, position)
        std::vector<uint32_t> triangles;
        std::vector<Box3f> moved_boxes;
    };
    uint32_t buildRange(uint32_t first, uint32_t size, BuildScratch& scratch);
    std::vector<Node> nodes_; // pre-order: a parent before its children
    std::vector<uint32_t> triangles_;
    uint32_t first_triangle_ = 0;
    std::vector<uint32_t> leaf_of_; // per triangle, in id order from first_triangle_: its leaf
    std::vector<uint32_t> leaves_;  // the leaf nodes
};

/// The box of triangle t of positions.
Box3f triangleBox(PositionsView positions, uint32_t t);

/// The scratch of overlappingTrianglePairs, one per thread: its stack, and each triangle's
/// diagonal extents, computed once per call at most (a triangle near the other object meets
/// several of its triangles' boxes).
struct TrianglePairScratch {
    std::vector<std::pair<uint32_t, uint32_t>> stack;
    std::vector<DiagonalExtents> diagonals[2]; // per leaf-order triangle of a, of b
    std::vector<uint32_t> computed[2];         // per leaf-order triangle: the call that set it
    BoxColumns boxes[2];                       // per leaf-order triangle of a, of b: its box
    std::vector<uint32_t> boxed[2]; // per leaf's first triangle: the call that set its boxes
    uint32_t call = 0;
};

/// Every pair (ta, tb) of a triangle of a and one of b whose boxes overlap and whose diagonal
/// extents overlap too (triangle_boxes.h), appended to pairs. Returns how many pairs' boxes
/// overlapped (before the diagonals).
uint64_t overlappingTrianglePairs(const RefitBvh& a, const RefitBvh& b, PositionsView positions,
                                  std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                                  TrianglePairScratch& scratch);

} // namespace vissort::detail
