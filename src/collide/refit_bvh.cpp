// Refitted AABB trees (refit_bvh.h): van den Bergen, "Efficient Collision Detection of Complex
// Deformable Models using AABB Trees", Journal of Graphics Tools 2(4), 1997.

#include "collide/refit_bvh.h"

#include <algorithm>
#include <bit>
#include <numeric>

namespace vissort::detail {

Box3f triangleBox(PositionsView positions, uint32_t t) {
    const std::size_t c = 3 * std::size_t(t);
    Box3f b;
    const float* axes[3] = {positions.x.data(), positions.y.data(), positions.z.data()};
    for (int k = 0; k < 3; ++k) {
        const float p = axes[k][c], q = axes[k][c + 1], r = axes[k][c + 2];
        b.min[k] = std::min(std::min(p, q), r);
        b.max[k] = std::max(std::max(p, q), r);
    }
    return b;
}

void RefitBvh::build(PositionsView positions, PrimitiveRange object) {
    first_triangle_ = object.first_triangle;
    triangles_.resize(object.triangle_count);
    std::iota(triangles_.begin(), triangles_.end(), object.first_triangle);
    BuildScratch scratch;
    scratch.boxes.resize(object.triangle_count);
    for (uint32_t i = 0; i < object.triangle_count; ++i)
        scratch.boxes[i] = triangleBox(positions, triangles_[i]);
    nodes_.clear();
    nodes_.reserve(2 * std::size_t(object.triangle_count) / kLeafSize + 1);
    buildRange(0, object.triangle_count, scratch);
    // The triangles' boxes are not kept: see overlappingTrianglePairs.
    leaf_of_.resize(object.triangle_count);
    leaves_.clear();
    for (uint32_t i = 0; i < nodes_.size(); ++i)
        if (nodes_[i].isLeaf()) {
            leaves_.push_back(i);
            for (uint32_t k = nodes_[i].first; k < nodes_[i].first + nodes_[i].size; ++k)
                leaf_of_[triangles_[k] - first_triangle_] = i;
        }
    refit(positions);
}

// Splits at the median box centre on the best of the three axes, keeping triangles_ and
// scratch.boxes in step. The centres are sorted as (key, position) pairs side by side, not as
// positions compared through the boxes: half the build time of 144 bunnies went to those
// indirect reads.
uint32_t RefitBvh::buildRange(uint32_t first, uint32_t size, BuildScratch& scratch) {
    const uint32_t index = uint32_t(nodes_.size());
    nodes_.push_back({{}, first, size, 0, index + 1});
    if (size <= kLeafSize)
        return index;
    // Of the median splits along the three axes, the one whose halves' boxes have the least
    // surface area (the surface area heuristic's estimate of how often they are visited).
    const auto area = [](const Box3f& b) {
        const float dx = b.max[0] - b.min[0], dy = b.max[1] - b.min[1], dz = b.max[2] - b.min[2];
        return dx * dy + dy * dz + dz * dx;
    };
    const std::vector<Box3f>& boxes = scratch.boxes;
    const uint32_t half = size / 2;
    int best = 0;
    float best_cost = INFINITY;
    for (int axis = 0; axis < 3; ++axis) {
        auto& centres = scratch.centres[axis];
        centres.resize(size);
        for (uint32_t i = 0; i < size; ++i)
            centres[i] = {boxes[first + i].min[axis] + boxes[first + i].max[axis], first + i};
        std::nth_element(centres.begin(), centres.begin() + half, centres.end(),
                         [](const auto& p, const auto& q) { return p.first < q.first; });
        Box3f left = boxes[centres[0].second], right = boxes[centres[half].second];
        for (uint32_t i = 1; i < half; ++i)
            includeBox(left, boxes[centres[i].second]);
        for (uint32_t i = half + 1; i < size; ++i)
            includeBox(right, boxes[centres[i].second]);
        const float cost = area(left) + area(right);
        if (axis == 0 || cost < best_cost) {
            best_cost = cost;
            best = axis;
        }
    }
    const auto& order = scratch.centres[best];
    scratch.triangles.resize(size);
    scratch.moved_boxes.resize(size);
    for (uint32_t i = 0; i < size; ++i) {
        scratch.triangles[i] = triangles_[order[i].second];
        scratch.moved_boxes[i] = boxes[order[i].second];
    }
    std::copy(scratch.triangles.begin(), scratch.triangles.end(), triangles_.begin() + first);
    std::copy(scratch.moved_boxes.begin(), scratch.moved_boxes.end(),
              scratch.boxes.begin() + first);
    buildRange(first, half, scratch);
    const uint32_t right = buildRange(first + half, size - half, scratch);
    nodes_[index].right = right;
    nodes_[index].after = uint32_t(nodes_.size());
    return index;
}

void RefitBvh::refit(PositionsView positions) {
    // One forward pass over the corners: each triangle's box goes straight into its leaf's (the
    // leaves' boxes are a few kilobytes, so they stay in the cache while the corners stream).
    for (uint32_t leaf : leaves_)
        nodes_[leaf].box = kEmptyBox;
    const std::size_t first_corner = 3 * std::size_t(first_triangle_);
    const float* axes[3] = {positions.x.data() + first_corner, positions.y.data() + first_corner,
                            positions.z.data() + first_corner};
    for (std::size_t i = 0; i < leaf_of_.size(); ++i) {
        Box3f& box = nodes_[leaf_of_[i]].box;
        for (int k = 0; k < 3; ++k) {
            const float* c = axes[k] + 3 * i;
            box.min[k] = std::min(box.min[k], std::min(std::min(c[0], c[1]), c[2]));
            box.max[k] = std::max(box.max[k], std::max(std::max(c[0], c[1]), c[2]));
        }
    }
    // Children come after their parent: back to front, every child is refitted first.
    for (std::size_t i = nodes_.size(); i-- > 0;) {
        Node& n = nodes_[i];
        if (!n.isLeaf()) {
            n.box = nodes_[i + 1].box;
            includeBox(n.box, nodes_[n.right].box);
        }
    }
}

void RefitBvh::appendCut(const Box3f& region, uint32_t max_size, std::vector<uint32_t>& marks,
                         uint32_t round, std::vector<Box3f>& out) const {
    if (marks.size() < nodes_.size())
        marks.resize(nodes_.size(), 0);
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
            i = i + 1; // open: the left child follows
        }
    }
}

uint64_t overlappingTrianglePairs(const RefitBvh& a, const RefitBvh& b, PositionsView positions,
                                  std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                                  TrianglePairScratch& scratch) {
    const auto na = a.nodes(), nb = b.nodes();
    const auto ta = a.triangles(), tb = b.triangles();
    uint64_t box_pairs = 0;
    if (++scratch.call == 0) { // wrapped: old marks could match again
        for (auto& computed : scratch.computed)
            std::fill(computed.begin(), computed.end(), 0);
        for (auto& boxed : scratch.boxed)
            std::fill(boxed.begin(), boxed.end(), 0);
        scratch.call = 1;
    }
    const std::span<const uint32_t> triangles[2] = {ta, tb};
    for (int side = 0; side < 2; ++side)
        if (scratch.computed[side].size() < triangles[side].size()) {
            scratch.computed[side].resize(triangles[side].size(), 0);
            scratch.diagonals[side].resize(triangles[side].size());
        }
    // The triangles' boxes of a leaf, from the positions, the first time this call reaches it:
    // the descent reaches few leaves, and a refit that kept every triangle's box would write
    // (and the descent read) a box per triangle of every tree every frame.
    for (int side = 0; side < 2; ++side) {
        if (scratch.boxed[side].size() < triangles[side].size())
            scratch.boxed[side].resize(triangles[side].size(), 0);
        scratch.boxes[side].resize(triangles[side].size());
    }
    const auto leafBoxes = [&](int side, const RefitBvh::Node& leaf) -> const BoxColumns& {
        BoxColumns& boxes = scratch.boxes[side];
        if (scratch.boxed[side][leaf.first] != scratch.call) {
            scratch.boxed[side][leaf.first] = scratch.call;
            for (uint32_t k = leaf.first; k < leaf.first + leaf.size; ++k)
                boxes.set(k, triangleBox(positions, triangles[side][k]));
        }
        return boxes;
    };
    const auto diagonals = [&](int side, uint32_t leaf_index) -> const DiagonalExtents& {
        DiagonalExtents& extents = scratch.diagonals[side][leaf_index];
        if (scratch.computed[side][leaf_index] != scratch.call) {
            scratch.computed[side][leaf_index] = scratch.call;
            extents = diagonalExtents(positions, triangles[side][leaf_index]);
        }
        return extents;
    };
    auto& stack = scratch.stack;
    stack.clear();
    if (!boxesOverlap(na[0].box, nb[0].box))
        return 0;
    stack.emplace_back(0, 0);
    // Every pair on the stack has overlapping boxes: children are tested before they are pushed.
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        const RefitBvh::Node& x = na[i];
        const RefitBvh::Node& y = nb[j];
        if (x.isLeaf() && y.isLeaf()) {
            const BoxColumns& ba = leafBoxes(0, x);
            const BoxColumns& bb = leafBoxes(1, y);
            // The triangles of x that meet y's box, each against y's triangles four at a time.
            for (unsigned near = overlapMask8(BoxLanes(y.box), ba, x.first, x.size); near != 0;
                 near &= near - 1) {
                const uint32_t p = x.first + uint32_t(std::countr_zero(near));
                // The diagonals only for boxes that meet, once per triangle; the pairs they
                // keep (about half: a coin toss the predictor loses) written without a branch.
                std::size_t kept = pairs.size();
                pairs.resize(kept + RefitBvh::kLeafSize);
                for (unsigned meet = overlapMask8(BoxLanes(ba.box(p)), bb, y.first, y.size);
                     meet != 0; meet &= meet - 1) {
                    const uint32_t q = y.first + uint32_t(std::countr_zero(meet));
                    ++box_pairs;
                    pairs[kept] = {ta[p], tb[q]};
                    kept += diagonalsOverlap(diagonals(0, p), diagonals(1, q));
                }
                pairs.resize(kept);
            }
            continue;
        }
        // Open both nodes at once (four child pairs, as Bullet's collideTT does), or the one
        // that is not a leaf.
        if (!x.isLeaf() && !y.isLeaf()) {
            for (uint32_t cx : {i + 1, x.right})
                for (uint32_t cy : {j + 1, y.right})
                    if (boxesOverlap(na[cx].box, nb[cy].box))
                        stack.emplace_back(cx, cy);
        } else if (!x.isLeaf()) {
            for (uint32_t child : {i + 1, x.right})
                if (boxesOverlap(na[child].box, y.box))
                    stack.emplace_back(child, j);
        } else {
            for (uint32_t child : {j + 1, y.right})
                if (boxesOverlap(x.box, nb[child].box))
                    stack.emplace_back(i, child);
        }
    }
    return box_pairs;
}

} // namespace vissort::detail
