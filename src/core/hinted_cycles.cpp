// Confirming last frame's cycles. A hint is a set of members and a witness: occlusions among
// them that made them strongly connected. Re-checking each occlusion of the witness (one occluder
// drawn, the members it occluded queried) proves the parts it still connects strongly connected
// now, for about as many small tests as the hint has members, where the cycle search gallops and
// halves over the list for each member.

#include "hinted_cycles.h"

#include <algorithm>
#include <cassert>

namespace vissort::detail {
namespace {

// A hint's lost occlusions are replaced only when they are at most one in this many of its
// witness (and at most 2 otherwise).
constexpr std::size_t kRepairableShare = 8;

// Adjacency lists of n vertices in compressed form: vertex v's targets are
// next[first[v] .. first[v + 1]).
struct Adjacency {
    std::vector<uint32_t> first, next;
    Adjacency(std::size_t n, std::span<const std::pair<uint32_t, uint32_t>> edges)
        : first(n + 1, 0), next(edges.size()) {
        for (const auto& edge : edges)
            ++first[edge.first + 1];
        for (std::size_t v = 0; v < n; ++v)
            first[v + 1] += first[v];
        std::vector<uint32_t> fill(first.begin(), first.end() - 1);
        for (const auto& [from, to] : edges)
            next[fill[from]++] = to;
    }
};

// The witness's occlusions between members, as local indices into `sorted`.
std::vector<std::pair<uint32_t, uint32_t>> localEdges(std::span<const uint32_t> sorted,
                                                      std::span<const Occlusion> witness) {
    const auto local = [&](uint32_t p) -> int64_t {
        const auto it = std::lower_bound(sorted.begin(), sorted.end(), p);
        return it != sorted.end() && *it == p ? it - sorted.begin() : -1;
    };
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (const Occlusion& o : witness) {
        const int64_t front = local(o.front), back = local(o.back);
        if (front >= 0 && back >= 0 && front != back)
            edges.emplace_back(uint32_t(front), uint32_t(back));
    }
    return edges;
}

// The members nearest to p (ascending ids, p among them) on each side, up to kNear in all, and
// the others; p in neither.
constexpr std::size_t kNear = 8;
void splitNear(std::span<const uint32_t> members, uint32_t p, std::vector<uint32_t>& near,
               std::vector<uint32_t>& rest) {
    near.clear();
    rest.clear();
    const std::size_t at = std::lower_bound(members.begin(), members.end(), p) - members.begin();
    const std::size_t first = at > kNear / 2 ? at - kNear / 2 : 0;
    const std::size_t last = std::min(members.size(), at + kNear / 2 + 1);
    for (std::size_t i = 0; i < members.size(); ++i) {
        if (members[i] == p)
            continue;
        (i >= first && i < last ? near : rest).push_back(members[i]);
    }
}

} // namespace

std::vector<Occlusion> witnessWithin(std::span<const uint32_t> part,
                                     std::span<const Occlusion> witness) {
    std::vector<Occlusion> kept;
    for (const Occlusion& o : witness)
        if (std::binary_search(part.begin(), part.end(), o.front) &&
            std::binary_search(part.begin(), part.end(), o.back))
            kept.push_back(o);
    return kept;
}

std::vector<std::vector<uint32_t>> connectedParts(std::span<const uint32_t> members,
                                                  std::span<const Occlusion> witness) {
    std::vector<uint32_t> sorted(members.begin(), members.end());
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    const std::size_t n = sorted.size();
    std::vector<std::pair<uint32_t, uint32_t>> edges = localEdges(sorted, witness);
    const Adjacency forwards(n, edges);
    for (auto& edge : edges)
        std::swap(edge.first, edge.second);
    const Adjacency backwards(n, edges);
    // Kosaraju: vertices by finishing time of a depth-first search forwards, then components as
    // the searches backwards from the latest finished, iteratively (no recursion depth limit).
    std::vector<uint32_t> finished;
    std::vector<uint8_t> seen(n, 0);
    std::vector<std::pair<uint32_t, uint32_t>> stack; // vertex, next edge
    for (uint32_t root = 0; root < n; ++root) {
        if (seen[root])
            continue;
        seen[root] = 1;
        stack.push_back({root, forwards.first[root]});
        while (!stack.empty()) {
            auto& [v, k] = stack.back();
            if (k < forwards.first[v + 1]) {
                const uint32_t w = forwards.next[k++];
                if (!seen[w]) {
                    seen[w] = 1;
                    stack.push_back({w, forwards.first[w]});
                }
            } else {
                finished.push_back(v);
                stack.pop_back();
            }
        }
    }
    std::vector<uint32_t> component_of(n, ~uint32_t(0)), queue;
    std::vector<std::vector<uint32_t>> parts;
    for (std::size_t i = n; i-- > 0;) {
        const uint32_t root = finished[i];
        if (component_of[root] != ~uint32_t(0))
            continue;
        queue.assign(1, root);
        component_of[root] = root;
        for (std::size_t q = 0; q < queue.size(); ++q)
            for (uint32_t k = backwards.first[queue[q]]; k < backwards.first[queue[q] + 1]; ++k)
                if (component_of[backwards.next[k]] == ~uint32_t(0)) {
                    component_of[backwards.next[k]] = root;
                    queue.push_back(backwards.next[k]);
                }
        if (queue.size() < 2)
            continue;
        std::vector<uint32_t>& part = parts.emplace_back();
        for (uint32_t v : queue)
            part.push_back(sorted[v]);
        std::sort(part.begin(), part.end());
    }
    return parts;
}

bool witnessConnects(std::span<const uint32_t> members, std::span<const Occlusion> witness) {
    if (members.size() < 2)
        return false;
    std::vector<uint32_t> sorted(members.begin(), members.end());
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end() &&
           connectedParts(members, witness) ==
               std::vector<std::vector<uint32_t>>{std::move(sorted)};
}

std::vector<ConfirmedGroup> confirmHints(OcclusionOracle& oracle, const CycleHints& hints,
                                         VisSortStats& stats) {
    assert(hints.witnesses.size() == hints.cycles.size());
    const uint32_t n = oracle.primitiveCount();
    std::vector<ConfirmedGroup> groups;
    std::vector<uint8_t> grouped(n, 0);
    std::vector<Occlusion> witness;
    std::vector<uint32_t> backs, near, rest;
    std::vector<uint8_t> behind;
    std::vector<Occlusion> lost;
    for (std::size_t h = 0; h < hints.cycles.size() && h < hints.witnesses.size(); ++h) {
        // The occlusions between members in range, once each, by occluder: one test each.
        witness.clear();
        for (const Occlusion& o : hints.witnesses[h])
            if (o.front < n && o.back < n && o.front != o.back)
                witness.push_back(o);
        std::sort(witness.begin(), witness.end(), [](const Occlusion& a, const Occlusion& b) {
            return a.front != b.front ? a.front < b.front : a.back < b.back;
        });
        witness.erase(std::unique(witness.begin(), witness.end()), witness.end());
        std::vector<uint32_t> members;
        for (uint32_t p : hints.cycles[h])
            if (p < n && !grouped[p]) // a caller's overlapping hints: each primitive once
                members.push_back(p);
        // Only what the witness could connect is worth a query.
        std::vector<std::vector<uint32_t>> claimed = connectedParts(members, witness);
        if (claimed.empty())
            continue;
        members.clear();
        for (const auto& part : claimed)
            members.insert(members.end(), part.begin(), part.end());
        std::sort(members.begin(), members.end());
        witness = witnessWithin(members, witness);
        std::size_t kept = 0;
        for (std::size_t i = 0; i < witness.size();) {
            const uint32_t front = witness[i].front;
            const std::size_t begin = i;
            backs.clear();
            for (; i < witness.size() && witness[i].front == front; ++i)
                backs.push_back(witness[i].back);
            behind.assign(backs.size(), 0);
            groupTest(oracle, std::span(&front, 1), backs, behind, stats);
            // Confirmed occlusions to the front, lost ones after them (order within kept).
            for (std::size_t j = 0; j < backs.size(); ++j)
                if (behind[j])
                    std::swap(witness[kept++], witness[begin + j]);
        }
        // An occlusion that no longer holds (the camera moved off the few pixels where it did)
        // is replaced, where the members allow, by two that do: an occluder of its back member
        // among the members (one test, then halving) and a member behind its front one (one
        // test). What the witness then connects is what the hint confirms; the
        // contracted order's search joins the parts if they still form one component.
        // Repairs cost a test of all members each: only for a few lost occlusions. Where many
        // are lost the cycle has changed (the cold frame's large cycle split in two on the
        // power plant's first coherent frame: 14,464 queries repairing it); the parts the
        // confirmed ones connect are kept and the search finds the rest.
        const std::size_t tested = witness.size();
        if (tested - kept <= std::max<std::size_t>(2, tested / kRepairableShare))
            for (std::size_t i = kept; i < tested; ++i)
                lost.push_back(witness[i]);
        witness.resize(kept);
        for (const Occlusion& o : lost) {
            // Members are in list order, and in a nearly sorted list occluders lie near: the
            // nearest few first, then the rest.
            uint32_t occluder = 0;
            bool found = false;
            for (int round = 0; round < 2 && !found; ++round) {
                splitNear(members, o.back, near, rest);
                found =
                    findOccluderAmong(oracle, round == 0 ? near : rest, o.back, stats, occluder);
            }
            if (found)
                witness.push_back({occluder, o.back});
            found = false;
            for (int round = 0; round < 2 && !found; ++round) {
                splitNear(members, o.front, near, rest);
                const std::vector<uint32_t>& asked = round == 0 ? near : rest;
                if (asked.empty())
                    continue;
                behind.assign(asked.size(), 0);
                groupTest(oracle, std::span(&o.front, 1), asked, behind, stats);
                if (const auto hit = std::find(behind.begin(), behind.end(), 1);
                    hit != behind.end()) {
                    witness.push_back({o.front, asked[hit - behind.begin()]});
                    found = true;
                }
            }
        }
        lost.clear();
        for (std::vector<uint32_t>& part : connectedParts(members, witness)) {
            for (uint32_t p : part)
                grouped[p] = 1;
            std::vector<Occlusion> within = witnessWithin(part, witness);
            groups.push_back({std::move(part), std::move(within)});
        }
    }
    return groups;
}

} // namespace vissort::detail
