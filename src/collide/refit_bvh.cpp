// Refitted AABB trees (refit_bvh.h): van den Bergen, "Efficient Collision Detection of Complex
// Deformable Models using AABB Trees", Journal of Graphics Tools 2(4), 1997.

#include "collide/refit_bvh.h"

#include <algorithm>
#include <numeric>

namespace vissort::detail {

void RefitBvh::build(std::span<const Box3f> triangle_boxes, PrimitiveRange object) {
    triangles_.resize(object.triangle_count);
    std::iota(triangles_.begin(), triangles_.end(), object.first_triangle);
    nodes_.clear();
    nodes_.reserve(2 * std::size_t(object.triangle_count) / kLeafSize + 1);
    buildRange(triangle_boxes, 0, object.triangle_count);
    refit(triangle_boxes);
}

uint32_t RefitBvh::buildRange(std::span<const Box3f> triangle_boxes, uint32_t first, uint32_t size) {
    const uint32_t index = uint32_t(nodes_.size());
    nodes_.push_back({{}, first, size, 0, index + 1});
    if (size <= kLeafSize) return index;
    // Split at the median centre along the longest axis of the centres' extent.
    Box3f extent;
    bool started = false;
    for (uint32_t i = first; i < first + size; ++i) {
        const Box3f& b = triangle_boxes[triangles_[i]];
        Box3f centre;
        for (int k = 0; k < 3; ++k) centre.min[k] = centre.max[k] = 0.5f * (b.min[k] + b.max[k]);
        if (started) includeBox(extent, centre);
        else extent = centre;
        started = true;
    }
    const int axis = longestAxis(extent);
    const auto middle = triangles_.begin() + first + size / 2;
    std::nth_element(triangles_.begin() + first, middle, triangles_.begin() + first + size,
                     [&](uint32_t p, uint32_t q) {
                         return triangle_boxes[p].min[axis] + triangle_boxes[p].max[axis] <
                                triangle_boxes[q].min[axis] + triangle_boxes[q].max[axis];
                     });
    buildRange(triangle_boxes, first, size / 2);
    const uint32_t right = buildRange(triangle_boxes, first + size / 2, size - size / 2);
    nodes_[index].right = right;
    nodes_[index].after = uint32_t(nodes_.size());
    return index;
}

void RefitBvh::refit(std::span<const Box3f> triangle_boxes) {
    // Children come after their parent: back to front, every child is refitted first.
    for (std::size_t i = nodes_.size(); i-- > 0;) {
        Node& n = nodes_[i];
        if (n.isLeaf()) {
            n.box = triangle_boxes[triangles_[n.first]];
            for (uint32_t k = 1; k < n.size; ++k) includeBox(n.box, triangle_boxes[triangles_[n.first + k]]);
        } else {
            n.box = nodes_[i + 1].box;
            includeBox(n.box, nodes_[n.right].box);
        }
    }
}

void RefitBvh::appendCut(const Box3f& region, uint32_t max_size, std::vector<uint32_t>& marks,
                         uint32_t round, std::vector<Box3f>& out) const {
    if (marks.size() < nodes_.size()) marks.resize(nodes_.size(), 0);
    // Pre-order walk: a node that meets the region is cut when small enough, else opened.
    for (uint32_t i = 0; i < nodes_.size();) {
        const Node& n = nodes_[i];
        if (!boxesOverlap(n.box, region)) {
            i = n.after;
        } else if (n.size <= max_size) {
            if (marks[i] != round) {
                marks[i] = round;
                out.push_back(n.box);
            }
            i = n.after;
        } else {
            i = i + 1;  // open: the left child follows
        }
    }
}

void overlappingTrianglePairs(const RefitBvh& a, const RefitBvh& b,
                              std::span<const Box3f> triangle_boxes,
                              std::span<const DiagonalExtents> diagonals,
                              std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                              std::vector<std::pair<uint32_t, uint32_t>>& stack) {
    const auto na = a.nodes(), nb = b.nodes();
    const auto ta = a.triangles(), tb = b.triangles();
    stack.clear();
    stack.emplace_back(0, 0);
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        const RefitBvh::Node& x = na[i];
        const RefitBvh::Node& y = nb[j];
        if (!boxesOverlap(x.box, y.box)) continue;
        if (x.isLeaf() && y.isLeaf()) {
            for (uint32_t p = x.first; p < x.first + x.size; ++p)
                for (uint32_t q = y.first; q < y.first + y.size; ++q)
                    if (boxesOverlap(triangle_boxes[ta[p]], triangle_boxes[tb[q]]) &&
                        diagonalsOverlap(diagonals[ta[p]], diagonals[tb[q]]))
                        pairs.emplace_back(ta[p], tb[q]);
            continue;
        }
        // Open the larger node (by triangles), or the one that is not a leaf.
        if (y.isLeaf() || (!x.isLeaf() && x.size >= y.size)) {
            stack.emplace_back(i + 1, j);
            stack.emplace_back(x.right, j);
        } else {
            stack.emplace_back(i, j + 1);
            stack.emplace_back(i, y.right);
        }
    }
}

} // namespace vissort::detail
