// Vis-sort over the groups of the last frame's cycles (contracted_vis_sort.h).

#include "contracted_vis_sort.h"

#include <algorithm>
#include <cassert>
#include <numeric>

#include "grouped_oracle.h"
#include "hinted_cycles.h"
#include "source_cycle.h"

namespace vissort::detail {
namespace {

// An occlusion between members for an occlusion between two groups (a member of `front`
// occludes one of `back`, as the contracted order's search found): one test of every member of
// front against every member of back for an occluded one, then its occluder among front.
bool refineOcclusion(OcclusionOracle& oracle, std::span<const uint32_t> front,
                     std::span<const uint32_t> back, VisSortStats& stats, Occlusion& found) {
    uint32_t occluded = back.front();
    if (back.size() > 1) {
        std::vector<uint8_t> behind(back.size(), 0);
        groupTest(oracle, front, back, behind, stats);
        const auto hit = std::find(behind.begin(), behind.end(), 1);
        if (hit == behind.end())
            return false; // an oracle that answers differently the second time
        occluded = back[hit - behind.begin()];
    }
    uint32_t occluder = front.front();
    if (front.size() > 1 && !findOccluderAmong(oracle, front, occluded, stats, occluder))
        return false;
    found = {occluder, occluded};
    return true;
}

} // namespace

void contractedVisSort(OcclusionOracle& oracle, std::span<const uint32_t> initial_order,
                       const CycleHints& hints, VisibilityOrder& result,
                       VisSortWorkspace& workspace) {
    VisSortStats confirming;
    std::vector<ConfirmedGroup> groups = confirmHints(oracle, hints, confirming);
    if (groups.empty()) {
        visSort(oracle, initial_order, result, workspace);
        result.stats += confirming;
        return;
    }
    // Nodes in list order: a group where its first member is, its members in list order (the
    // order a cycle's members come out in), every other primitive alone.
    const uint32_t n = oracle.primitiveCount();
    constexpr uint32_t kAlone = ~uint32_t(0);
    std::vector<uint32_t> group_of(n, kAlone), position(n);
    for (uint32_t i = 0; i < initial_order.size(); ++i)
        position[initial_order[i]] = i;
    for (uint32_t g = 0; g < groups.size(); ++g) {
        for (uint32_t p : groups[g].members)
            group_of[p] = g;
        std::sort(groups[g].members.begin(), groups[g].members.end(),
                  [&](uint32_t a, uint32_t b) { return position[a] < position[b]; });
    }
    std::vector<uint32_t> members, first{0}, node_group;
    std::vector<uint8_t> placed(groups.size(), 0);
    for (uint32_t p : initial_order) {
        const uint32_t g = group_of[p];
        if (g == kAlone) {
            members.push_back(p);
        } else if (!placed[g]) {
            placed[g] = 1;
            members.insert(members.end(), groups[g].members.begin(), groups[g].members.end());
        } else {
            continue;
        }
        first.push_back(uint32_t(members.size()));
        node_group.push_back(g);
    }
    const auto membersOf = [&](uint32_t node) {
        return std::span(members).subspan(first[node], first[node + 1] - first[node]);
    };

    GroupedOracle grouped(oracle, members, first);
    std::vector<uint32_t> nodes(node_group.size());
    std::iota(nodes.begin(), nodes.end(), 0u);
    VisibilityOrder contracted;
    visSort(grouped, nodes, contracted, workspace);

    result.order.clear();
    result.cycles.clear();
    result.cycle_witnesses.clear();
    result.stats = contracted.stats;
    for (uint32_t node : contracted.order) {
        const auto m = membersOf(node);
        result.order.insert(result.order.end(), m.begin(), m.end());
    }
    // Every cycle of the contracted order: its groups' witnesses, and for each occlusion its
    // search found between nodes, one between members.
    std::vector<uint8_t> in_cycle(node_group.size(), 0);
    for (std::size_t c = 0; c < contracted.cycles.size(); ++c) {
        std::vector<uint32_t> cycle;
        std::vector<Occlusion> witness;
        for (uint32_t node : contracted.cycles[c]) {
            in_cycle[node] = 1;
            const auto m = membersOf(node);
            cycle.insert(cycle.end(), m.begin(), m.end());
            if (node_group[node] != kAlone) {
                const auto& inner = groups[node_group[node]].witness;
                witness.insert(witness.end(), inner.begin(), inner.end());
            }
        }
        for (const Occlusion& o : contracted.cycle_witnesses[c]) {
            Occlusion between;
            if (refineOcclusion(oracle, membersOf(o.front), membersOf(o.back), result.stats,
                                between))
                witness.push_back(between);
        }
        std::sort(cycle.begin(), cycle.end());
        result.cycles.push_back(std::move(cycle));
        result.cycle_witnesses.push_back(std::move(witness));
    }
    // A group in no cycle of the contracted order is a component by itself: last frame's cycle,
    // confirmed.
    for (uint32_t node = 0; node < node_group.size(); ++node) {
        if (node_group[node] == kAlone || in_cycle[node])
            continue;
        ConfirmedGroup& group = groups[node_group[node]];
        std::sort(group.members.begin(), group.members.end());
        result.cycles.push_back(std::move(group.members));
        result.cycle_witnesses.push_back(std::move(group.witness));
        ++result.stats.hinted_cycles;
    }
    // The confirmation's tests, and the members' draws and queries beyond one a node.
    result.stats += confirming;
    result.stats.queries += grouped.extraQueries();
    result.stats.draws += grouped.extraDraws();
    result.stats.cycle_queries += grouped.extraGroupTestQueries();
    result.stats.cycle_draws += grouped.extraGroupTestDraws();
}

} // namespace vissort::detail
