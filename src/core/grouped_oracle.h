#pragma once
// An occlusion oracle over groups of another oracle's primitives: a group is drawn by drawing
// every member and is behind when any member is, its members queried before any is drawn. What
// Vis-sort orders when the cycles of the last frame are contracted (hinted_cycles.h): a group
// known to be strongly connected is one primitive of the order. Internal to the core.

#include <cstdint>
#include <span>
#include <vector>

#include "vissort/occlusion_oracle.h"

namespace vissort::detail {

class GroupedOracle final : public OcclusionOracle {
public:
    /// Group g has members[first[g] .. first[g + 1]) of base's primitives; every primitive of
    /// base belongs to exactly one group. Both spans must outlive the oracle.
    GroupedOracle(OcclusionOracle& base, std::span<const uint32_t> members,
                  std::span<const uint32_t> first);

    uint32_t primitiveCount() const override { return uint32_t(first_.size() - 1); }
    void clear() override { base_.clear(); }
    void draw(uint32_t group) override;
    bool anyBehind(uint32_t group) override;
    /// Both passes are base's: its plain passes when every group of the sequence has one member,
    /// else its group passes (batched where base batches them).
    void backToFrontPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                         std::span<uint8_t> behind) override;
    void frontToBackPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                         std::span<uint8_t> behind) override;
    /// One group test of base over the members, its answers OR-ed per group.
    void queryAgainst(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
                      std::span<uint8_t> behind) override;

    /// base's graph of the groups' members, each edge taken to the groups of its ends (edges
    /// within a group dropped): a group reaches another exactly when one of its members reaches
    /// one of the other's, since each group is strongly connected.
    bool occlusionGraph(std::span<const uint32_t> groups, std::vector<Occlusion>& edges) override;

    /// The members' draws and queries beyond one a group: what base did on top of what the
    /// caller counted in groups (all of it, and of it the group tests').
    uint64_t extraDraws() const { return extra_draws_; }
    uint64_t extraQueries() const { return extra_queries_; }
    uint64_t extraGroupTestDraws() const { return extra_test_draws_; }
    uint64_t extraGroupTestQueries() const { return extra_test_queries_; }

private:
    std::span<const uint32_t> membersOf(uint32_t group) const {
        return members_.subspan(first_[group], first_[group + 1] - first_[group]);
    }
    bool allSingle(std::span<const uint32_t> sequence) const;
    // Counts the members beyond one a group of a pass in the extras.
    void countMembers(std::span<const uint32_t> sequence, std::span<const uint8_t> query);
    // Expands groups into their members' ids, one group after another; where each group's
    // members begin in `into`, and its end, into `starts` when given.
    std::span<const uint32_t> expand(std::span<const uint32_t> groups, std::vector<uint32_t>& into,
                                     std::vector<uint32_t>* starts = nullptr) const;

    OcclusionOracle& base_;
    std::span<const uint32_t> members_, first_;
    std::vector<uint32_t> sequence_, starts_, occluders_, targets_;
    std::vector<uint8_t> behind_;
    uint64_t extra_draws_ = 0, extra_queries_ = 0, extra_test_draws_ = 0, extra_test_queries_ = 0;
};

} // namespace vissort::detail
