// Finding a source strongly connected component by following occluders and contracting the
// cycles the walk closes: the path-based idea of Purdom's transitive-closure algorithm (1970) and
// Gabow's path-based SCC algorithm (2000), with edges discovered by group tests: one occlusion
// query answers "is p behind any of this set", so one occluder is found by halving.

#include "source_cycle.h"

#include <algorithm>
#include <cassert>

namespace vissort::detail {
namespace {

// One member of candidates that occludes target, given that the whole set does, by halving;
// candidates is consumed. Behind a union means behind one of its members, so when the first
// half does not occlude the target, the second half does.
uint32_t halveToOccluder(OcclusionOracle& oracle, std::vector<uint32_t>& candidates,
                         uint32_t target, VisSortStats& stats) {
    uint8_t behind = 0;
    while (candidates.size() > 1) {
        const std::size_t half = candidates.size() / 2;
        groupTest(oracle, std::span(candidates).first(half), std::span(&target, 1),
                  std::span(&behind, 1), stats);
        if (behind)
            candidates.resize(half);
        else
            candidates.erase(candidates.begin(), candidates.begin() + half);
    }
    return candidates.front();
}

class GroupTester {
public:
    GroupTester(OcclusionOracle& oracle, VisSortStats& stats) : oracle_(oracle), stats_(stats) {}

    void test(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
              std::span<uint8_t> behind) {
        groupTest(oracle_, occluders, targets, behind, stats_);
    }

    /// One member of candidates that occludes target, given that the whole set does.
    /// candidates is consumed.
    uint32_t findOccluder(std::vector<uint32_t>& candidates, uint32_t target) {
        return halveToOccluder(oracle_, candidates, target, stats_);
    }

    /// An occluder of target among the usable primitives of `side`, a part of the list next
    /// to target (before it when backwards: then searched from its end), found by galloping:
    /// windows of 1, 2, 4, ... of the nearest untested ones until one occludes target, then
    /// halving within it. Lists are nearly sorted, so occluders lie near: the draws are about 4
    /// times the distance to the nearest occluder, not the side's length. False when none does.
    template <class Usable>
    bool findNearOccluder(std::span<const uint32_t> side, bool backwards, Usable&& usable,
                          uint32_t target, std::vector<uint32_t>& window, uint32_t& occluder) {
        uint8_t behind = 0;
        std::size_t next = 0;
        for (std::size_t width = 1; next < side.size(); width *= 2) {
            window.clear();
            for (; next < side.size() && window.size() < width; ++next) {
                const uint32_t p = backwards ? side[side.size() - 1 - next] : side[next];
                if (usable(p))
                    window.push_back(p);
            }
            if (window.empty())
                continue;
            test(window, std::span(&target, 1), std::span(&behind, 1));
            if (behind) {
                occluder = findOccluder(window, target);
                return true;
            }
        }
        return false;
    }

private:
    OcclusionOracle& oracle_;
    VisSortStats& stats_;
};

constexpr int32_t kNotOnPath = -1;

} // namespace

void groupTest(OcclusionOracle& oracle, std::span<const uint32_t> occluders,
               std::span<const uint32_t> targets, std::span<uint8_t> behind, VisSortStats& stats) {
    oracle.queryAgainst(occluders, targets, behind);
    stats.clears += 1;
    stats.draws += occluders.size();
    stats.queries += targets.size();
    stats.cycle_draws += occluders.size();
    stats.cycle_queries += targets.size();
}

bool findOccluderAmong(OcclusionOracle& oracle, std::span<const uint32_t> candidates,
                       uint32_t target, VisSortStats& stats, uint32_t& occluder) {
    uint8_t behind = 0;
    if (candidates.empty())
        return false;
    groupTest(oracle, candidates, std::span(&target, 1), std::span(&behind, 1), stats);
    if (!behind)
        return false;
    std::vector<uint32_t> left(candidates.begin(), candidates.end());
    occluder = halveToOccluder(oracle, left, target, stats);
    return true;
}

namespace {

// Adds an occluder of a member of the path's top component (the occlusion `found`): a new
// component on the path, or, when it is already on the path, the merge of the cycle it closes,
// whose witness is then the merged components' witnesses, the links between them and `found`.
// Returns true when it pushed.
bool extendPath(std::vector<CycleSearchStep>& path, std::vector<int32_t>& path_index,
                Occlusion found) {
    const auto top = static_cast<int32_t>(path.size() - 1);
    const int32_t found_at = path_index[found.front];
    if (found_at == kNotOnPath) {
        path.push_back({{found.front}, {}, found});
        path_index[found.front] = top + 1;
        return true;
    }
    // occluder -> path[top] -> ... -> path[found_at] ∋ occluder closes a cycle: merge.
    CycleSearchStep& into = path[found_at];
    for (int32_t k = found_at + 1; k <= top; ++k) {
        for (uint32_t p : path[k].members) {
            path_index[p] = found_at;
            into.members.push_back(p);
        }
        into.witness.insert(into.witness.end(), path[k].witness.begin(), path[k].witness.end());
        into.witness.push_back(path[k].link);
    }
    into.witness.push_back(found);
    path.resize(found_at + 1);
    return false;
}

} // namespace

std::vector<SourceComponent> findSourceCycles(OcclusionOracle& oracle,
                                              std::span<const uint32_t> stuck,
                                              std::span<const uint8_t> in_monotone_run,
                                              uint32_t max_walks, VisSortStats& stats,
                                              VisSortWorkspace& scratch) {
    assert(!stuck.empty() && in_monotone_run.size() == stuck.size() && max_walks >= 1);
    GroupTester tester(oracle, stats);
    // Every entry is kNotOnPath (path_index) or kUnknown (walk_state) between calls; only the
    // stuck primitives' entries are touched, and they are reset before returning.
    std::vector<int32_t>& path_index = scratch.path_index;
    path_index.resize(oracle.primitiveCount(), kNotOnPath);
    enum : uint8_t { kUnknown = 0, kInSource = 1, kDownstream = 2 };
    std::vector<uint8_t>& walk_state = scratch.walk_state;
    walk_state.resize(oracle.primitiveCount(), kUnknown);
    std::vector<uint32_t>& position = scratch.position; // in stuck, valid for stuck primitives
    position.resize(oracle.primitiveCount());
    for (std::size_t i = 0; i < stuck.size(); ++i)
        position[stuck[i]] = uint32_t(i);
    const auto is_stuck = [&](uint32_t p) {
        return p < position.size() && position[p] < stuck.size() && stuck[position[p]] == p;
    };
    // What a search may pick: stuck, and not in a source found by this call (it leaves).
    const auto usable = [&](uint32_t p) { return walk_state[p] != kInSource; };
    // Coverage: member p of a component was a target of a group test against every usable
    // primitive of stuck positions [covered_first[p], covered_last[p]] outside its component,
    // and is behind none of them. Components only grow and primitives only leave the usable
    // set within a call, so the claim stays true while the component grows, and a ring
    // already covered is not tested again: without it, each merge re-tested every member
    // against every ring (about k^2/2 queries for a cycle of k; 1.9M a frame for the power
    // plant's 2,413-member cycle at scale 10). Empty: first > last.
    std::vector<uint32_t>& covered_first = scratch.covered_first;
    std::vector<uint32_t>& covered_last = scratch.covered_last;
    covered_first.resize(oracle.primitiveCount());
    covered_last.resize(oracle.primitiveCount());
    for (uint32_t p : stuck) {
        covered_first[p] = 1;
        covered_last[p] = 0;
    }
    const auto covers = [&](uint32_t p, std::size_t first, std::size_t last) {
        return covered_first[p] <= first && last <= covered_last[p];
    };
    // p was tested against [first, last] and is behind nothing there: its coverage grows to
    // their union when that is one interval, else becomes [first, last].
    const auto cover = [&](uint32_t p, std::size_t first, std::size_t last) {
        const bool joined = covered_first[p] <= covered_last[p] && covered_first[p] <= last + 1 &&
                            first <= covered_last[p] + 1;
        covered_first[p] =
            joined ? std::min<uint32_t>(covered_first[p], uint32_t(first)) : uint32_t(first);
        covered_last[p] =
            joined ? std::max<uint32_t>(covered_last[p], uint32_t(last)) : uint32_t(last);
    };
    std::vector<uint32_t>& outside = scratch.outside;
    std::vector<uint8_t>& behind = scratch.behind;

    // The path the last call left (see the header), up to its first component with a member
    // that is no longer stuck: Vis-sort outputs a component once the source above it has left.
    std::vector<CycleSearchStep> path = std::move(scratch.pending_path);
    scratch.pending_path.clear();
    for (std::size_t k = 0; k < path.size(); ++k)
        if (!std::all_of(path[k].members.begin(), path[k].members.end(), is_stuck)) {
            path.resize(k);
            break;
        }
    for (std::size_t k = 0; k < path.size(); ++k)
        for (uint32_t p : path[k].members)
            path_index[p] = int32_t(k);

    std::vector<SourceComponent> sources;
    std::vector<uint32_t> whole_targets; // the cycle search's members tested on a whole window
    std::size_t next_start = 0;
    for (uint32_t walk = 0; walk < max_walks; ++walk) {
        if (path.empty()) {
            while (next_start < stuck.size() && walk_state[stuck[next_start]] != kUnknown)
                ++next_start;
            if (next_start == stuck.size())
                break;
            // path[k + 1] holds an occluder of a member of path[k]; each entry is strongly
            // connected.
            path.push_back({{stuck[next_start]}, {}, {}});
            path_index[stuck[next_start]] = 0;
        }
        bool found_source = false;
        constexpr uint32_t kNoPosition = ~uint32_t(0);
        uint32_t merged_at = kNoPosition;
        for (;;) {
            const auto top = static_cast<int32_t>(path.size() - 1);
            const std::vector<uint32_t>& component = path.back().members;
            uint32_t occluder = 0, occluded = 0;
            bool have_occluder = false;
            if (component.size() == 1) {
                // A lone primitive: search its sides nearest first. A member of M has every
                // occluder before it (pass 1 found nothing after it in front of it); any other
                // one was found behind something after it, so that side goes first.
                const uint32_t target = component.front();
                occluded = target;
                const uint32_t at = position[target];
                const std::span<const uint32_t> before = std::span(stuck).first(at),
                                                after = std::span(stuck).subspan(at + 1);
                if (!in_monotone_run[at])
                    have_occluder = tester.findNearOccluder(after, false, usable, target,
                                                            scratch.candidates, occluder);
                if (!have_occluder)
                    have_occluder = tester.findNearOccluder(before, true, usable, target,
                                                            scratch.candidates, occluder);
                if (!have_occluder) {
                    // Nothing stuck and usable occludes it (the source that did has left): a
                    // source of one, output as an ordinary primitive.
                    sources.push_back({{target}, {}});
                    found_source = true;
                    break;
                }
            }
            if (!have_occluder) {
                // Galloping again, over rings of the list around where the component last
                // grew (the occluder that closed its cycle; else its span): windows of 1, 2,
                // 4, ... each side. Each member inside the window is tested against what its
                // coverage lacks: the new ring when it covers the window before (behind a
                // union is behind one of its members, so a ring that occludes nothing need not
                // be drawn again), else the whole window; a member covering the window is not
                // tested. The list is nearly sorted, so occluders lie near a member in it. A
                // source is a component whose every member covers the whole list.
                uint32_t lo = uint32_t(stuck.size()), hi = 0;
                if (merged_at != kNoPosition) {
                    lo = hi = merged_at;
                } else {
                    for (uint32_t p : component) {
                        lo = std::min(lo, position[p]);
                        hi = std::max(hi, position[p]);
                    }
                }
                std::vector<uint32_t>& targets = scratch.targets;
                const auto add = [&](std::size_t begin, std::size_t end) {
                    for (std::size_t i = begin; i < end; ++i)
                        if (path_index[stuck[i]] != top && usable(stuck[i]))
                            outside.push_back(stuck[i]);
                };
                uint32_t occluded_member = 0;
                // Tests `group` against outside ([first, last] less the component); covers
                // the members behind nothing; true on a member behind something.
                const auto test = [&](const std::vector<uint32_t>& group, std::size_t first,
                                      std::size_t last) -> bool {
                    if (group.empty())
                        return false;
                    bool hit = false;
                    if (!outside.empty()) {
                        behind.assign(group.size(), 0);
                        tester.test(outside, group, behind);
                        const auto at = std::find(behind.begin(), behind.end(), 1);
                        if (at != behind.end()) {
                            occluded_member = group[at - behind.begin()];
                            hit = true;
                        }
                    }
                    for (std::size_t i = 0; i < group.size(); ++i)
                        if (!hit || !behind[i])
                            cover(group[i], first, last);
                    return hit;
                };
                std::size_t first = lo, last = hi; // the window
                bool have_before = false;          // the window before this step's
                std::size_t before_first = 0, before_last = 0;
                bool found = false;
                for (std::size_t reach = 1;; reach *= 2) {
                    targets.clear();
                    whole_targets.clear();
                    for (uint32_t p : component) {
                        if (position[p] < first || position[p] > last || covers(p, first, last))
                            continue;
                        if (have_before && covers(p, before_first, before_last))
                            targets.push_back(p); // lacks the new ring only
                        else
                            whole_targets.push_back(p);
                    }
                    if (!targets.empty()) {
                        outside.clear();
                        add(first, before_first);
                        add(before_last + 1, last + 1);
                        found = test(targets, first, last);
                    }
                    if (!found && !whole_targets.empty()) {
                        outside.clear();
                        add(first, last + 1);
                        found = test(whole_targets, first, last);
                    }
                    if (found || (first == 0 && last + 1 == stuck.size()))
                        break;
                    have_before = true;
                    before_first = first;
                    before_last = last;
                    first = first > reach ? first - reach : 0;
                    last = std::min(stuck.size() - 1, last + reach);
                }
                if (!found) {
                    // Every member covers the whole list: nothing else that is stuck occludes
                    // the component, a source. Stuck order.
                    std::vector<uint32_t> members;
                    for (uint32_t p : stuck)
                        if (path_index[p] == top)
                            members.push_back(p);
                    sources.push_back({std::move(members), std::move(path.back().witness)});
                    found_source = true;
                    break;
                }
                scratch.candidates.assign(outside.begin(), outside.end());
                occluder = tester.findOccluder(scratch.candidates, occluded_member);
                occluded = occluded_member;
            }
            // Reaching what lies behind an earlier walk's path puts this one behind it too.
            if (walk_state[occluder] != kUnknown)
                break;
            merged_at = extendPath(path, path_index, {occluder, occluded}) ? kNoPosition
                                                                           : position[occluder];
        }
        if (found_source) {
            // The source leaves; the rest of the path stays valid (each component strongly
            // connected, occluded by the next one's members), and the next walk goes on from
            // its top, which lost its occluder: no path is ever walked twice.
            for (uint32_t p : path.back().members) {
                walk_state[p] = kInSource;
                path_index[p] = kNotOnPath;
            }
            path.pop_back();
        } else {
            for (const auto& component : path)
                for (uint32_t p : component.members) {
                    walk_state[p] = kDownstream;
                    path_index[p] = kNotOnPath;
                }
            path.clear();
        }
    }
    for (const auto& component : path)
        for (uint32_t p : component.members)
            path_index[p] = kNotOnPath;
    scratch.pending_path = std::move(path);
    for (uint32_t p : stuck)
        walk_state[p] = kUnknown;
    return sources;
}

} // namespace vissort::detail
