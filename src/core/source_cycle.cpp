// Finding a source strongly connected component by following occluders and contracting the
// cycles the walk closes: the path-based idea of Purdom's transitive-closure algorithm (1970) and
// Gabow's path-based SCC algorithm (2000), with edges discovered by group tests: one occlusion
// query answers "is p behind any of this set", so one occluder is found by halving.

#include "source_cycle.h"

#include <algorithm>
#include <cassert>

namespace vissort::detail {
namespace {

class GroupTester {
public:
    GroupTester(OcclusionOracle& oracle, VisSortStats& stats) : oracle_(oracle), stats_(stats) {}

    void test(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
              std::span<uint8_t> behind) {
        oracle_.queryAgainst(occluders, targets, behind);
        stats_.clears += 1;
        stats_.draws += occluders.size();
        stats_.queries += targets.size();
        stats_.cycle_draws += occluders.size();
        stats_.cycle_queries += targets.size();
    }

    /// One member of candidates that occludes target, given that the whole set does.
    /// candidates is consumed.
    uint32_t findOccluder(std::vector<uint32_t>& candidates, uint32_t target) {
        uint8_t behind = 0;
        while (candidates.size() > 1) {
            const std::size_t half = candidates.size() / 2;
            test(std::span(candidates).first(half), std::span(&target, 1), std::span(&behind, 1));
            // Behind a union means behind one of its members, so when the first half does not
            // occlude the target, the second half does.
            if (behind)
                candidates.resize(half);
            else
                candidates.erase(candidates.begin(), candidates.begin() + half);
        }
        return candidates.front();
    }

private:
    OcclusionOracle& oracle_;
    VisSortStats& stats_;
};

constexpr int32_t kNotOnPath = -1;

// Adds an occluder of the path's top component: a new component on the path, or, when it is
// already on the path, the merge of the cycle it closes. Returns true when it pushed.
bool extendPath(std::vector<std::vector<uint32_t>>& path, std::vector<int32_t>& path_index,
                uint32_t occluder) {
    const auto top = static_cast<int32_t>(path.size() - 1);
    const int32_t found_at = path_index[occluder];
    if (found_at == kNotOnPath) {
        path.push_back({occluder});
        path_index[occluder] = top + 1;
        return true;
    }
    // occluder -> path[top] -> ... -> path[found_at] ∋ occluder closes a cycle: merge.
    for (int32_t k = found_at + 1; k <= top; ++k) {
        for (uint32_t p : path[k]) {
            path_index[p] = found_at;
            path[found_at].push_back(p);
        }
    }
    path.resize(found_at + 1);
    return false;
}

} // namespace

std::vector<std::vector<uint32_t>> findSourceCycles(OcclusionOracle& oracle,
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
    std::vector<uint32_t>& outside = scratch.outside;
    std::vector<uint8_t>& behind = scratch.behind;

    std::vector<std::vector<uint32_t>> sources;
    std::size_t next_start = 0;
    for (uint32_t walk = 0; walk < max_walks; ++walk) {
        while (next_start < stuck.size() && walk_state[stuck[next_start]] != kUnknown)
            ++next_start;
        if (next_start == stuck.size())
            break;
        // path[k + 1] holds an occluder of a member of path[k]; each entry is strongly connected.
        std::vector<std::vector<uint32_t>> path{{stuck[next_start]}};
        path_index[stuck[next_start]] = 0;
        bool found_source = false;
        for (;;) {
            const auto top = static_cast<int32_t>(path.size() - 1);
            const std::vector<uint32_t>& component = path.back();
            uint32_t occluder = 0;
            bool have_occluder = false;
            if (component.size() == 1) {
                // A lone primitive is occluded by another stuck one, on the side of the list the
                // passes found it behind: search that side only, with no test of the whole rest.
                const uint32_t target = component.front();
                const uint32_t at = position[target];
                if (in_monotone_run[at])
                    scratch.candidates.assign(stuck.begin(), stuck.begin() + at);
                else
                    scratch.candidates.assign(stuck.begin() + at + 1, stuck.end());
                if (!scratch.candidates.empty()) {
                    occluder = tester.findOccluder(scratch.candidates, target);
                    have_occluder = true;
                }
                // An empty side means the oracle contradicted itself: fall back to the full test.
            }
            if (!have_occluder) {
                outside.clear();
                for (uint32_t p : stuck)
                    if (path_index[p] != top)
                        outside.push_back(p);
                behind.assign(component.size(), 0);
                if (!outside.empty())
                    tester.test(outside, component, behind);
                const auto occluded = std::find(behind.begin(), behind.end(), 1);
                if (occluded == behind.end()) {
                    // Nothing else that is stuck occludes the component: a source. Stuck order.
                    std::vector<uint32_t> members;
                    for (uint32_t p : stuck)
                        if (path_index[p] == top)
                            members.push_back(p);
                    sources.push_back(std::move(members));
                    found_source = true;
                    break;
                }
                scratch.candidates.assign(outside.begin(), outside.end());
                occluder =
                    tester.findOccluder(scratch.candidates, component[occluded - behind.begin()]);
            }
            // Reaching a found source, or what lies behind one, puts the whole path behind it.
            if (walk_state[occluder] != kUnknown)
                break;
            extendPath(path, path_index, occluder);
        }
        const uint8_t state = found_source ? kInSource : kDownstream;
        for (const auto& component : path)
            for (uint32_t p : component) {
                walk_state[p] = state;
                path_index[p] = kNotOnPath;
            }
    }
    for (uint32_t p : stuck)
        walk_state[p] = kUnknown;
    return sources;
}

} // namespace vissort::detail
