// Cycles carried from one frame to the next (CycleHints): every order made with hints is checked
// against the graph of its own frame (brute-force components, every edge), whatever the hints
// say, and the witnesses Vis-sort returns are checked to be edges of that graph that connect
// their cycle.
#include <random>
#include <set>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "graph_oracle.h"
#include "vissort/vis_sort.h"

namespace vissort {
namespace {

// Every cycle's witness: edges of the graph between its members that make it strongly
// connected (reachability by the test's own search, not the core's).
void expectWitnessesConnectCycles(const GraphOracle& g, const VisibilityOrder& r) {
    ASSERT_EQ(r.cycle_witnesses.size(), r.cycles.size());
    for (std::size_t c = 0; c < r.cycles.size(); ++c) {
        const std::vector<uint32_t>& members = r.cycles[c];
        const std::set<uint32_t> in_cycle(members.begin(), members.end());
        for (const Occlusion& o : r.cycle_witnesses[c]) {
            EXPECT_TRUE(in_cycle.count(o.front) && in_cycle.count(o.back));
            EXPECT_TRUE(g.edges()[o.front][o.back]) << o.front << " -> " << o.back;
        }
        for (int direction = 0; direction < 2; ++direction) {
            std::set<uint32_t> reached{members.front()};
            for (bool grew = true; grew;) {
                grew = false;
                for (const Occlusion& o : r.cycle_witnesses[c]) {
                    const uint32_t from = direction == 0 ? o.front : o.back;
                    const uint32_t to = direction == 0 ? o.back : o.front;
                    if (reached.count(from) && reached.insert(to).second)
                        grew = true;
                }
            }
            EXPECT_EQ(reached.size(), members.size()) << "cycle " << c;
        }
    }
}

void expectExact(const GraphOracle& g, const VisibilityOrder& r) {
    expectRespectsEdges(g, r);
    const std::set<std::vector<uint32_t>> reported(r.cycles.begin(), r.cycles.end());
    EXPECT_EQ(reported.size(), r.cycles.size()) << "a cycle was reported twice";
    EXPECT_EQ(reported, referenceCycles(g));
    expectWitnessesConnectCycles(g, r);
}

GraphOracle randomGraph(uint32_t n, double density, std::mt19937& rng) {
    GraphOracle g(n);
    for (uint32_t a = 0; a < n; ++a)
        for (uint32_t b = 0; b < n; ++b)
            if (a != b && (rng() % 10000) < density * 10000)
                g.addEdge(a, b);
    return g;
}

VisibilityOrder sortWithHints(GraphOracle& g, std::span<const uint32_t> start,
                              const std::vector<std::vector<uint32_t>>& cycles,
                              const std::vector<std::vector<Occlusion>>& witnesses) {
    VisibilityOrder result;
    VisSortWorkspace workspace;
    visSort(g, start, result, workspace, {cycles, witnesses});
    return result;
}

VisibilityOrder sortWithHints(GraphOracle& g, const VisibilityOrder& last) {
    return sortWithHints(g, last.order, last.cycles, last.cycle_witnesses);
}

TEST(CycleHints, TheSameFrameAgainConfirmsEveryCycleForFewerQueries) {
    std::mt19937 rng(5);
    int frames_with_cycles = 0;
    for (int trial = 0; trial < 100; ++trial) {
        GraphOracle g = randomGraph(10 + rng() % 50, 0.02 + (rng() % 100) / 100.0 * 0.06, rng);
        std::vector<uint32_t> start = identity(g.primitiveCount());
        std::shuffle(start.begin(), start.end(), rng);
        const VisibilityOrder first = visSort(g, start);
        expectExact(g, first);
        const VisibilityOrder again = visSort(g, first.order); // coherent, without hints
        const VisibilityOrder hinted = sortWithHints(g, first);
        expectExact(g, hinted);
        EXPECT_EQ(hinted.stats.hinted_cycles, first.cycles.size()) << "trial " << trial;
        if (!first.cycles.empty()) {
            ++frames_with_cycles;
            EXPECT_LE(hinted.stats.cycle_queries, again.stats.cycle_queries) << "trial " << trial;
        }
    }
    EXPECT_GT(frames_with_cycles, 30);
}

TEST(CycleHints, NextFramesWithEdgesGainedAndLostStayExact) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 60; ++trial) {
        const uint32_t n = 10 + rng() % 40;
        GraphOracle g = randomGraph(n, 0.03 + (rng() % 100) / 100.0 * 0.05, rng);
        std::vector<uint32_t> start = identity(n);
        std::shuffle(start.begin(), start.end(), rng);
        VisibilityOrder last = visSort(g, start);
        for (int frame = 1; frame < 6; ++frame) {
            // The next frame: a few edges appear and disappear (cycles grow, split, vanish).
            for (int change = 0; change < 4; ++change) {
                const uint32_t a = rng() % n, b = rng() % n;
                if (a == b)
                    continue;
                if (g.edges()[a][b])
                    g.removeEdge(a, b);
                else
                    g.addEdge(a, b);
            }
            VisibilityOrder next = sortWithHints(g, last);
            expectExact(g, next);
            if (HasFailure())
                FAIL() << "trial " << trial << " frame " << frame;
            last = std::move(next);
        }
    }
}

TEST(CycleHints, AFalseOcclusionInAWitnessIsCaught) {
    // 0 <-> 1 is a true cycle and 1 -> 2 -> 3 hangs behind it. The hint names all four with a
    // witness that closes them with 3 -> 0, which does not hold: without that test the four would
    // be reported as one cycle (nothing outside occludes them). Only {0, 1} is.
    GraphOracle g(4, {{0, 1}, {1, 0}, {1, 2}, {2, 3}});
    const VisibilityOrder result =
        sortWithHints(g, std::vector<uint32_t>{3, 2, 1, 0}, {{0, 1, 2, 3}},
                      {{{0, 1}, {1, 0}, {1, 2}, {2, 3}, {3, 0}}});
    expectExact(g, result);
    ASSERT_EQ(result.cycles.size(), 1u);
    EXPECT_EQ(result.cycles[0], (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(result.stats.hinted_cycles, 1u);
}

TEST(CycleHints, AWitnessThatDoesNotConnectItsMembersIsIgnored) {
    // 0 <-> 1 is a true cycle, 2 and 3 lie behind it. The hint names all four but its witness
    // connects only 0 and 1 (and names a primitive outside the hint and one out of range): only
    // {0, 1} can be confirmed.
    GraphOracle g(4, {{0, 1}, {1, 0}, {1, 2}, {2, 3}});
    const VisibilityOrder result =
        sortWithHints(g, identity(4), {{0, 1, 2, 3}}, {{{0, 1}, {1, 0}, {1, 2}, {3, 7}, {9, 2}}});
    expectExact(g, result);
    EXPECT_EQ(result.stats.hinted_cycles, 1u);
}

TEST(CycleHints, ACycleThatGrewIsFoundWholeFromItsHint) {
    // Last frame 0 <-> 1; now 2 joins them (1 -> 2 -> 0): the hint is a part of the component,
    // from which the search finds the rest.
    GraphOracle g(5, {{0, 1}, {1, 0}, {1, 2}, {2, 0}, {2, 3}, {3, 4}});
    const VisibilityOrder result = sortWithHints(g, identity(5), {{0, 1}}, {{{0, 1}, {1, 0}}});
    expectExact(g, result);
    ASSERT_EQ(result.cycles.size(), 1u);
    EXPECT_EQ(result.cycles[0], (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(result.stats.hinted_cycles, 0u); // it grew: found by the search, not confirmed
}

} // namespace
} // namespace vissort
