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

std::vector<uint32_t> findSourceCycle(OcclusionOracle& oracle, std::span<const uint32_t> stuck,
                                      std::span<const uint8_t> in_monotone_run,
                                      VisSortStats& stats, VisSortWorkspace& scratch) {
    assert(!stuck.empty() && in_monotone_run.size() == stuck.size());
    GroupTester tester(oracle, stats);
    // Every entry is kNotOnPath between calls; only the stuck primitives' entries are touched.
    std::vector<int32_t>& path_index = scratch.path_index;
    path_index.resize(oracle.primitiveCount(), kNotOnPath);
    // path[k + 1] holds an occluder of a member of path[k]; each entry is strongly connected.
    std::vector<std::vector<uint32_t>> path{{stuck.front()}};
    path_index[stuck.front()] = 0;

    std::vector<uint32_t>& outside = scratch.outside;
    std::vector<uint8_t>& behind = scratch.behind;
    std::vector<uint32_t>& position = scratch.position;  // in stuck, valid for stuck primitives
    position.resize(oracle.primitiveCount());
    for (std::size_t i = 0; i < stuck.size(); ++i) position[stuck[i]] = uint32_t(i);
    for (;;) {
        const auto top = static_cast<int32_t>(path.size() - 1);
        const std::vector<uint32_t>& component = path.back();
        if (component.size() == 1) {
            // A lone primitive is occluded by another stuck one, on the side of the list the
            // passes found it behind: search that side only, with no test of the whole rest.
            const uint32_t target = component.front();
            const uint32_t at = position[target];
            scratch.candidates.clear();
            if (in_monotone_run[at])
                scratch.candidates.assign(stuck.begin(), stuck.begin() + at);
            else
                scratch.candidates.assign(stuck.begin() + at + 1, stuck.end());
            if (!scratch.candidates.empty()) {
                const uint32_t occluder = tester.findOccluder(scratch.candidates, target);
                extendPath(path, path_index, occluder);
                continue;
            }
            // An empty side means the oracle contradicted itself; fall back to the full test.
        }
        outside.clear();
        for (uint32_t p : stuck)
            if (path_index[p] != top) outside.push_back(p);
        behind.assign(component.size(), 0);
        if (!outside.empty()) tester.test(outside, component, behind);
        const auto occluded = std::find(behind.begin(), behind.end(), 1);
        if (occluded == behind.end()) {
            // Nothing outside occludes the component: it is a source. List it in stuck order.
            std::vector<uint32_t> members;
            for (uint32_t p : stuck) {
                if (path_index[p] == top) members.push_back(p);
                path_index[p] = kNotOnPath;
            }
            return members;
        }
        const uint32_t target = component[occluded - behind.begin()];
        scratch.candidates.assign(outside.begin(), outside.end());
        extendPath(path, path_index, tester.findOccluder(scratch.candidates, target));
    }
}

} // namespace vissort::detail
