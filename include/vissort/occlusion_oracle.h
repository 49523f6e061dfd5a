#pragma once
// The comparison operation of Vis-sort in 3D: occlusion queries against a depth buffer that holds
// the union of the primitives drawn since the last clear. The core sees only primitive ids
// 0..primitiveCount()-1; what a primitive is (an object, a triangle) is the backend's business.
//
// To implement an oracle:
//  - primitiveCount(): how many primitives the ids refer to;
//  - clear(): empty the depth buffer (every pixel infinitely far);
//  - draw(p): rasterize p with depth test LESS and depth writes on;
//  - anyBehind(p): true when some fragment of p lies strictly behind the stored depth, beyond the
//    backend's documented tolerance (depth test GREATER, no writes). Must not change the buffer.
//  - optionally override the pass-level batches below, which the core uses; their default
//    implementations call the three primitive operations in the order documented, so an
//    override must give the same answers (it may reorder work that has no data dependency).
// Only standard-library types appear here: the core depends on nothing else.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <cstdint>
#include <span>
#include <vector>

namespace vissort {

/// An edge of the occlusion graph: `front` lies in front of `back` at some pixel.
struct Occlusion {
    uint32_t front = 0, back = 0;
    friend bool operator==(const Occlusion&, const Occlusion&) = default;
};

class OcclusionOracle {
public:
    virtual ~OcclusionOracle() = default;

    virtual uint32_t primitiveCount() const = 0;
    virtual void clear() = 0;
    virtual void draw(uint32_t primitive) = 0;
    virtual bool anyBehind(uint32_t primitive) = 0;

    /// Vis-sort's pass 1. Clears, then for i = sequence.size()-1 down to 0:
    ///   if query[i]: behind[i] = anyBehind(sequence[i]);  then always draw(sequence[i]).
    /// No draw depends on an answer, so a backend may answer every query at the end.
    /// query and behind have sequence.size() entries; behind[i] is untouched where !query[i].
    virtual void backToFrontPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                                 std::span<uint8_t> behind);

    /// Vis-sort's pass 2. Clears, then for i = 0 up to sequence.size()-1:
    ///   if query[i]: behind[i] = anyBehind(sequence[i]); draw only if behind[i];
    ///   else draw(sequence[i]).
    /// Here a draw depends on its own query's answer (conditional rendering on a GPU).
    virtual void frontToBackPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                                 std::span<uint8_t> behind);

    /// The two passes over groups of primitives, each group standing for the union of its
    /// members (Vis-sort over the groups of the last frame's cycles, vis_sort.h): `members`
    /// holds the groups one after another, group g being members[first[g] .. first[g + 1]), and
    /// query and behind have one entry a group. A group's query asks whether any member is
    /// behind, before any member is drawn; its draw draws every member. The defaults call the
    /// primitive operations in that order; an override must give the same answers.
    virtual void backToFrontGroupPass(std::span<const uint32_t> members,
                                      std::span<const uint32_t> first,
                                      std::span<const uint8_t> query, std::span<uint8_t> behind);
    virtual void frontToBackGroupPass(std::span<const uint32_t> members,
                                      std::span<const uint32_t> first,
                                      std::span<const uint8_t> query, std::span<uint8_t> behind);

    /// Group test: clears, draws every occluder, then behind[i] = anyBehind(targets[i]).
    /// Afterwards the depth buffer holds the occluders' depths wherever a target has a fragment;
    /// elsewhere an oracle may have left out occluders that cannot change an answer
    /// (CpuOracle draws only those whose bounds meet the targets').
    virtual void queryAgainst(std::span<const uint32_t> occluders,
                              std::span<const uint32_t> targets, std::span<uint8_t> behind);

    /// Optional: the occlusion graph among `members` (distinct primitives) in one pass, where
    /// Vis-sort is stuck on a large set (vis_sort.cpp) and finding its cycles by group tests
    /// would cost draws growing with the cycles. Appends edges {front, back} as positions in
    /// members: front -> back only where anyBehind(back) would be true with front alone drawn
    /// (a fragment of front strictly in front of one of back), and enough of them that one
    /// member reaches another through them exactly when it does in the whole graph (so the
    /// strongly connected components are the true ones). Returns false, leaving edges as they
    /// were, where the oracle cannot: the default; the core then searches by group tests.
    virtual bool occlusionGraph(std::span<const uint32_t> members, std::vector<Occlusion>& edges);
};

} // namespace vissort
