// Groups of primitives as primitives (grouped_oracle.h).

#include "grouped_oracle.h"

#include <algorithm>
#include <cassert>

namespace vissort::detail {

GroupedOracle::GroupedOracle(OcclusionOracle& base, std::span<const uint32_t> members,
                             std::span<const uint32_t> first)
    : base_(base), members_(members), first_(first) {
    assert(!first.empty() && first.back() == members.size());
}

void GroupedOracle::draw(uint32_t group) {
    const std::span<const uint32_t> members = membersOf(group);
    extra_draws_ += members.size() - 1;
    for (uint32_t p : members)
        base_.draw(p);
}

bool GroupedOracle::anyBehind(uint32_t group) {
    // Queries change nothing: asking members one by one is asking before any is drawn.
    const std::span<const uint32_t> members = membersOf(group);
    extra_queries_ += members.size() - 1;
    for (uint32_t p : members)
        if (base_.anyBehind(p))
            return true;
    return false;
}

void GroupedOracle::countMembers(std::span<const uint32_t> sequence,
                                 std::span<const uint8_t> query) {
    // The caller counts a query and a draw a group; a group of k members costs base up to k of
    // each (a front-to-back pass draws fewer: the same bound the caller counts).
    for (std::size_t i = 0; i < sequence.size(); ++i) {
        const uint32_t extra = first_[sequence[i] + 1] - first_[sequence[i]] - 1;
        extra_draws_ += extra;
        extra_queries_ += query[i] ? extra : 0;
    }
}

bool GroupedOracle::allSingle(std::span<const uint32_t> sequence) const {
    return std::all_of(sequence.begin(), sequence.end(),
                       [&](uint32_t g) { return first_[g + 1] - first_[g] == 1; });
}

std::span<const uint32_t> GroupedOracle::expand(std::span<const uint32_t> groups,
                                                std::vector<uint32_t>& into,
                                                std::vector<uint32_t>* starts) const {
    into.clear();
    if (starts != nullptr)
        starts->assign(1, 0);
    for (uint32_t g : groups) {
        const std::span<const uint32_t> members = membersOf(g);
        into.insert(into.end(), members.begin(), members.end());
        if (starts != nullptr)
            starts->push_back(uint32_t(into.size()));
    }
    return into;
}

void GroupedOracle::backToFrontPass(std::span<const uint32_t> sequence,
                                    std::span<const uint8_t> query, std::span<uint8_t> behind) {
    if (allSingle(sequence)) {
        base_.backToFrontPass(expand(sequence, sequence_), query, behind);
        return;
    }
    countMembers(sequence, query);
    // Expanded first: the span of starts_ must see the groups' starts.
    const std::span<const uint32_t> members = expand(sequence, sequence_, &starts_);
    base_.backToFrontGroupPass(members, starts_, query, behind);
}

void GroupedOracle::frontToBackPass(std::span<const uint32_t> sequence,
                                    std::span<const uint8_t> query, std::span<uint8_t> behind) {
    if (allSingle(sequence)) {
        base_.frontToBackPass(expand(sequence, sequence_), query, behind);
        return;
    }
    countMembers(sequence, query);
    // Expanded first: the span of starts_ must see the groups' starts.
    const std::span<const uint32_t> members = expand(sequence, sequence_, &starts_);
    base_.frontToBackGroupPass(members, starts_, query, behind);
}

void GroupedOracle::queryAgainst(std::span<const uint32_t> occluders,
                                 std::span<const uint32_t> targets, std::span<uint8_t> behind) {
    const std::span<const uint32_t> drawn = expand(occluders, occluders_);
    const std::span<const uint32_t> asked = expand(targets, targets_);
    extra_draws_ += drawn.size() - occluders.size();
    extra_queries_ += asked.size() - targets.size();
    extra_test_draws_ += drawn.size() - occluders.size();
    extra_test_queries_ += asked.size() - targets.size();
    behind_.assign(asked.size(), 0);
    base_.queryAgainst(drawn, asked, behind_);
    for (std::size_t i = 0, k = 0; i < targets.size(); ++i) {
        const std::size_t members = first_[targets[i] + 1] - first_[targets[i]];
        behind[i] = std::any_of(behind_.begin() + k, behind_.begin() + k + members,
                                [](uint8_t b) { return b != 0; });
        k += members;
    }
}

bool GroupedOracle::occlusionGraph(std::span<const uint32_t> groups,
                                   std::vector<Occlusion>& edges) {
    const std::span<const uint32_t> members = expand(groups, sequence_, &starts_);
    std::vector<Occlusion> member_edges;
    if (!base_.occlusionGraph(members, member_edges))
        return false;
    // The group (a position in groups) of each member position.
    std::vector<uint32_t> group_of(members.size());
    for (uint32_t g = 0; g < groups.size(); ++g)
        std::fill(group_of.begin() + starts_[g], group_of.begin() + starts_[g + 1], g);
    for (const Occlusion& e : member_edges)
        if (group_of[e.front] != group_of[e.back])
            edges.push_back({group_of[e.front], group_of[e.back]});
    extra_test_draws_ += members.size() - groups.size();
    extra_draws_ += members.size() - groups.size();
    return true;
}

} // namespace vissort::detail
