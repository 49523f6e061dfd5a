// Vis-sort in 3D: Govindaraju, Henson, Lin, Manocha, "Interactive Visibility Ordering and
// Transparency Computations among Geometric Primitives in Complex Environments", I3D 2005,
// section 4. The running minimum of Algorithm 3.1 becomes a depth buffer holding the union of a
// set of primitives, and "x <= min" becomes an occlusion query that finds no fragment of x behind
// it. docs/algorithm.md explains the passes, the constraints and how cycles are resolved.

#include "vissort/vis_sort.h"

#include <algorithm>
#include <cassert>

#include "contracted_vis_sort.h"
#include "graph_components.h"
#include "hinted_cycles.h" // witnessConnects, for the assertion
#include "source_cycle.h"

namespace vissort {
namespace {

// Walks for source cycles in one stuck iteration. Every other cycle found then saves a stuck
// iteration and the iteration that follows it, each a pass over everything still unsorted.
constexpr uint32_t kWalksPerStuckIteration = 8;

// A stuck set of at least this many primitives is ordered from the oracle's occlusion graph
// where the oracle can give it (OcclusionOracle::occlusionGraph): one draw a member, where the
// walks' group tests grow with the cycles (assimp's 2CylinderEngine.glb: 1,319 cycle draws for
// a component of 84, now 84 draws; the ten-times power plant: 1.76 million for 2,420, now
// 3,313; docs/benchmarks.md). 16 is not measured against the walks yet: two- and three-member
// cycles, the common ones, cost the walks a few group tests.
constexpr std::size_t kGraphPassMembers = 16;

// seen: scratch, so that the check (assertions on) allocates nothing once it has grown.
bool isPermutation(std::span<const uint32_t> ids, uint32_t n, std::vector<uint8_t>& seen) {
    if (ids.size() != n)
        return false;
    seen.assign(n, 0);
    for (uint32_t id : ids) {
        if (id >= n || seen[id])
            return false;
        seen[id] = 1;
    }
    return true;
}

class VisSorter {
public:
    VisSorter(OcclusionOracle& oracle, std::span<const uint32_t> initial_order,
              VisibilityOrder& result, VisSortWorkspace& workspace)
        : oracle_(oracle), unsorted_(workspace.unsorted),
          in_monotone_run_(workspace.in_monotone_run), query_(workspace.query),
          behind_(workspace.behind), in_cycle_(workspace.in_cycle), workspace_(workspace),
          result_(result) {
        unsorted_.assign(initial_order.begin(), initial_order.end());
        total_ = unsorted_.size();
        in_monotone_run_.assign(unsorted_.size(), 0);
        // The cycle search's per-primitive arrays are filled when a cycle is first met (a large
        // input without cycles then never holds them): emptied here, so that they are filled
        // whatever the caller left in the workspace.
        in_cycle_.clear();
        workspace.path_index.clear();
        workspace.walk_state.clear();
        workspace.pending_path.clear(); // a path of another call means nothing here
        result_.order.clear();
        result_.order.reserve(unsorted_.size());
        result_.cycles.clear();
        result_.cycle_witnesses.clear();
        result_.stats = {};
    }

    void run() {
        while (!unsorted_.empty()) {
            ++result_.stats.iterations;
            buildMonotoneRun();
            if (moveSortedToOutput() == 0) {
                ++result_.stats.stuck_iterations;
                outputSourceCycles();
            }
            if (workspace_.on_iteration)
                workspace_.on_iteration(result_.order.size(), total_);
        }
    }

private:
    // Pass 1, back to front. Constraint 1: p joins M only if no fragment of p lies behind the
    // union of the primitives after it. The back-most primitive joins without a query: the
    // depth buffer is empty when it is met.
    void buildMonotoneRun() {
        in_monotone_run_.back() = 1;
        query_.resize(unsorted_.size());
        behind_.resize(unsorted_.size());
        std::size_t queries = 0;
        for (std::size_t i = 0; i < unsorted_.size(); ++i) {
            query_[i] = in_monotone_run_[i] ? 0 : 1;
            queries += query_[i];
        }
        if (queries == 0)
            return; // everything is in M: no pass needed
        oracle_.backToFrontPass(unsorted_, query_, behind_);
        count(queries, unsorted_.size());
        for (std::size_t i = 0; i < unsorted_.size(); ++i)
            if (query_[i] && !behind_[i])
                in_monotone_run_[i] = 1;
    }

    // Pass 2, front to back. Constraint 2: p in M is output only if no fragment of p lies behind
    // the union of the unsorted primitives before it; primitives after it cannot occlude it,
    // because it is in M. Then every primitive that occludes p has been output already.
    // Returns how many primitives were output.
    std::size_t moveSortedToOutput() {
        const std::size_t before = result_.order.size();
        // The leading members of M meet an empty depth buffer: out without a query.
        std::size_t first = 0;
        while (first < unsorted_.size() && in_monotone_run_[first])
            result_.order.push_back(unsorted_[first++]);

        const std::span<const uint32_t> rest = std::span(unsorted_).subspan(first);
        query_.resize(rest.size());
        behind_.resize(rest.size());
        std::size_t queries = 0;
        for (std::size_t i = 0; i < rest.size(); ++i) {
            query_[i] = in_monotone_run_[first + i];
            queries += query_[i];
        }
        std::size_t kept = 0;
        if (queries > 0) {
            oracle_.frontToBackPass(rest, query_, behind_);
            std::size_t draws = 0;
            for (std::size_t i = 0; i < rest.size(); ++i) {
                const uint32_t p = rest[i];
                const bool output = query_[i] && !behind_[i];
                draws += output ? 0 : 1;
                if (output) {
                    result_.order.push_back(p);
                } else {
                    unsorted_[kept] = p;
                    in_monotone_run_[kept++] = in_monotone_run_[first + i];
                }
            }
            count(queries, draws);
        } else {
            // No member of M left to test: nothing else can be output in this pass.
            for (std::size_t i = 0; i < rest.size(); ++i) {
                unsorted_[kept] = rest[i];
                in_monotone_run_[kept++] = in_monotone_run_[first + i];
            }
        }
        unsorted_.resize(kept);
        in_monotone_run_.resize(kept);
        return result_.order.size() - before;
    }

    // No progress: every unsorted primitive is occluded by another unsorted one, so the occlusion
    // graph among them has a cycle. Output source components whole (members in list order: the
    // cycle-breaking rule), several per stuck iteration when the walks find them,
    // and go on; M stays valid because primitives are only removed.
    void outputSourceCycles() {
        if (unsorted_.size() >= kGraphPassMembers && outputFromGraph())
            return;
        in_cycle_.resize(oracle_.primitiveCount(), 0);
        std::vector<detail::SourceComponent> sources =
            detail::findSourceCycles(oracle_, unsorted_, in_monotone_run_, kWalksPerStuckIteration,
                                     result_.stats, workspace_);
        for (const auto& source : sources)
            for (uint32_t p : source.members) {
                in_cycle_[p] = 1;
                result_.order.push_back(p);
            }
        std::size_t kept = 0;
        for (std::size_t i = 0; i < unsorted_.size(); ++i) {
            if (in_cycle_[unsorted_[i]])
                continue;
            unsorted_[kept] = unsorted_[i];
            in_monotone_run_[kept++] = in_monotone_run_[i];
        }
        unsorted_.resize(kept);
        in_monotone_run_.resize(kept);
        for (auto& source : sources) {
            for (uint32_t p : source.members)
                in_cycle_[p] = 0;
            if (source.members.size() > 1) {
                assert(detail::witnessConnects(source.members, source.witness));
                std::sort(source.members.begin(), source.members.end());
                result_.cycles.push_back(std::move(source.members));
                result_.cycle_witnesses.push_back(std::move(source.witness));
            }
        }
    }

    // The whole stuck set at once, from its occlusion graph: the strongly connected components
    // in topological order are a visibility order of the set (each component's members in list
    // order, the cycle-breaking rule), and everything output so far comes before the set.
    // False, with nothing done, where the oracle cannot give the graph.
    bool outputFromGraph() {
        std::vector<Occlusion> edges;
        if (!oracle_.occlusionGraph(unsorted_, edges))
            return false;
        ++result_.stats.graph_passes;
        result_.stats.clears += 1;
        result_.stats.draws += unsorted_.size();
        result_.stats.cycle_draws += unsorted_.size();
        for (detail::SourceComponent& component :
             detail::graphComponents(uint32_t(unsorted_.size()), edges)) {
            for (uint32_t& at : component.members) {
                at = unsorted_[at];
                result_.order.push_back(at);
            }
            if (component.members.size() < 2)
                continue;
            for (Occlusion& o : component.witness)
                o = {unsorted_[o.front], unsorted_[o.back]};
            assert(detail::witnessConnects(component.members, component.witness));
            std::sort(component.members.begin(), component.members.end());
            result_.cycles.push_back(std::move(component.members));
            result_.cycle_witnesses.push_back(std::move(component.witness));
        }
        unsorted_.clear();
        in_monotone_run_.clear();
        return true;
    }

    void count(std::size_t queries, std::size_t draws) {
        result_.stats.clears += 1;
        result_.stats.queries += queries;
        result_.stats.draws += draws;
    }

    OcclusionOracle& oracle_;
    std::vector<uint32_t>& unsorted_;       // the list I, front to back
    std::vector<uint8_t>& in_monotone_run_; // M, parallel to unsorted_
    std::vector<uint8_t>& query_;           // per-pass scratch
    std::vector<uint8_t>& behind_;
    std::vector<uint8_t>& in_cycle_; // per primitive, zero between cycles
    VisSortWorkspace& workspace_;
    VisibilityOrder& result_;
    std::size_t total_ = 0; // primitives to order, for on_iteration
};

} // namespace

void visSort(OcclusionOracle& oracle, std::span<const uint32_t> initial_order,
             VisibilityOrder& result, VisSortWorkspace& workspace, CycleHints hints) {
    assert(isPermutation(initial_order, oracle.primitiveCount(), workspace.seen));
    (void)isPermutation;
    if (hints.cycles.empty())
        VisSorter(oracle, initial_order, result, workspace).run();
    else
        detail::contractedVisSort(oracle, initial_order, hints, result, workspace);
}

VisibilityOrder visSort(OcclusionOracle& oracle, std::span<const uint32_t> initial_order) {
    VisibilityOrder result;
    VisSortWorkspace workspace;
    visSort(oracle, initial_order, result, workspace);
    return result;
}

} // namespace vissort
