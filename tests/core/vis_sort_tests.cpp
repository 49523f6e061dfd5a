// Vis-sort over an oracle whose "depth buffer" is a set and whose occlusion relation is an
// explicit graph (graph_oracle.h): the algorithm's output is checked against the graph itself
// (brute-force reachability for the strongly connected components), independently of any
// geometry.
#include "vissort/vis_sort.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "graph_oracle.h"

namespace vissort {
namespace {

// The field table that every writer (JSON, CSV, Python) lists from: each field once, under its
// own name, with its own value (each set to a different number here).
TEST(VisSortStats, FieldTableNamesEveryFieldOnce) {
    VisSortStats s;
    s.queries = 1;
    s.draws = 2;
    s.clears = 3;
    s.iterations = 4;
    s.stuck_iterations = 5;
    s.cycle_queries = 6;
    s.cycle_draws = 7;
    s.hinted_cycles = 8;
    s.graph_passes = 9;
    std::map<std::string, uint64_t> seen;
    forEachStat(s, [&](std::string_view name, auto value) {
        EXPECT_TRUE(seen.emplace(std::string(name), uint64_t(value)).second) << name;
    });
    EXPECT_EQ(seen, (std::map<std::string, uint64_t>{{"queries", 1},
                                                     {"draws", 2},
                                                     {"clears", 3},
                                                     {"iterations", 4},
                                                     {"stuck_iterations", 5},
                                                     {"cycle_queries", 6},
                                                     {"cycle_draws", 7},
                                                     {"hinted_cycles", 8},
                                                     {"graph_passes", 9}}));
    // The size: a field added to the struct without a line in the table shows here too.
    EXPECT_EQ(sizeof(VisSortStats), 5 * sizeof(uint64_t) + 4 * sizeof(uint32_t));
}

TEST(VisSort, EmptyAndSingle) {
    GraphOracle none(0);
    EXPECT_TRUE(visSort(none, {}).order.empty());
    GraphOracle one(1);
    const auto order = identity(1);
    const auto r = visSort(one, order);
    EXPECT_EQ(r.order, order);
    EXPECT_EQ(r.stats.queries, 0u);
}

TEST(VisSort, ChainGivenBackToFrontIsReversed) {
    GraphOracle g(5);
    for (uint32_t i = 0; i + 1 < 5; ++i)
        g.addEdge(i, i + 1); // 0 in front of 1 in front of ...
    const std::vector<uint32_t> reversed{4, 3, 2, 1, 0};
    const auto r = visSort(g, reversed);
    EXPECT_EQ(r.order, identity(5));
    EXPECT_TRUE(r.cycles.empty());
}

TEST(VisSort, AlreadyOrderedInputCostsOneIterationAndLinearQueries) {
    const uint32_t n = 200;
    GraphOracle g(n);
    std::mt19937 rng(3);
    for (int e = 0; e < 600; ++e) {
        uint32_t a = rng() % n, b = rng() % n;
        if (a > b)
            std::swap(a, b);
        if (a != b)
            g.addEdge(a, b);
    }
    const auto r = visSort(g, identity(n));
    EXPECT_EQ(r.order, identity(n));
    EXPECT_EQ(r.stats.iterations, 1u);
    EXPECT_LE(r.stats.queries, 2u * n);
}

TEST(VisSort, TwoCycleIsReportedAndTheRestOrdered) {
    GraphOracle g(4);
    g.addEdge(0, 1);
    g.addEdge(1, 2);
    g.addEdge(2, 1); // 1 and 2 overlap each other
    g.addEdge(2, 3);
    const auto r = visSort(g, identity(4));
    ASSERT_EQ(r.cycles.size(), 1u);
    EXPECT_EQ(r.cycles[0], (std::vector<uint32_t>{1, 2}));
    EXPECT_EQ(r.order.front(), 0u);
    EXPECT_EQ(r.order.back(), 3u);
    EXPECT_GE(r.stats.stuck_iterations, 1u);
}

TEST(VisSort, ThreeSticksCycleIsOneComponentNotTheWholeRemainder) {
    // Sticks 0 -> 1 -> 2 -> 0 and two primitives behind them that are not in the cycle.
    GraphOracle g(5);
    g.addEdge(0, 1);
    g.addEdge(1, 2);
    g.addEdge(2, 0);
    g.addEdge(2, 3);
    g.addEdge(3, 4);
    const auto r = visSort(g, std::vector<uint32_t>{4, 3, 2, 1, 0});
    ASSERT_EQ(r.cycles.size(), 1u);
    EXPECT_EQ(r.cycles[0], (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(r.order[3], 3u);
    EXPECT_EQ(r.order[4], 4u);
}

TEST(VisSort, RandomGraphsMatchBruteForceComponents) {
    std::mt19937 rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        const uint32_t n = 1 + rng() % 40;
        GraphOracle g(n);
        const double density = (rng() % 100) / 100.0 * 0.15;
        const bool acyclic = trial % 3 == 0;
        for (uint32_t a = 0; a < n; ++a)
            for (uint32_t b = 0; b < n; ++b)
                if (a != b && (rng() % 10000) < density * 10000 && (!acyclic || a < b))
                    g.addEdge(a, b);
        std::vector<uint32_t> start = identity(n);
        std::shuffle(start.begin(), start.end(), rng);
        const auto r = visSort(g, start);
        expectRespectsEdges(g, r);
        const auto expected = referenceCycles(g);
        const std::set<std::vector<uint32_t>> reported(r.cycles.begin(), r.cycles.end());
        EXPECT_EQ(reported.size(), r.cycles.size()) << "a cycle was reported twice";
        EXPECT_EQ(reported, expected) << "trial " << trial;
        if (acyclic)
            EXPECT_TRUE(r.cycles.empty());
    }
}

// A graph oracle that can also give its graph in one pass (OcclusionOracle::occlusionGraph):
// every edge among the members, or, thinned, only those that keep the reachability (each edge
// dropped when another path still connects its ends), as an oracle may.
class OnePassGraphOracle : public GraphOracle {
public:
    OnePassGraphOracle(uint32_t n, bool thinned) : GraphOracle(n), thinned_(thinned) {}
    bool occlusionGraph(std::span<const uint32_t> members, std::vector<Occlusion>& out) override {
        ++graph_calls;
        const uint32_t k = uint32_t(members.size());
        std::vector<Occlusion> edges;
        for (uint32_t a = 0; a < k; ++a)
            for (uint32_t b = 0; b < k; ++b)
                if (a != b && this->edges()[members[a]][members[b]])
                    edges.push_back({a, b});
        if (thinned_) {
            for (std::size_t i = 0; i < edges.size();) {
                const Occlusion dropped = edges[i];
                edges.erase(edges.begin() + std::ptrdiff_t(i));
                if (!reaches(k, edges, dropped.front, dropped.back))
                    edges.insert(edges.begin() + std::ptrdiff_t(i++), dropped);
            }
        }
        out.insert(out.end(), edges.begin(), edges.end());
        return true;
    }
    int graph_calls = 0;

private:
    static bool reaches(uint32_t k, const std::vector<Occlusion>& edges, uint32_t from,
                        uint32_t to) {
        std::vector<uint8_t> seen(k, 0);
        std::vector<uint32_t> stack{from};
        seen[from] = 1;
        while (!stack.empty()) {
            const uint32_t u = stack.back();
            stack.pop_back();
            for (const Occlusion& e : edges)
                if (e.front == u && !seen[e.back]) {
                    seen[e.back] = 1;
                    stack.push_back(e.back);
                }
        }
        return seen[to] != 0;
    }
    bool thinned_;
};

// Stuck sets of 16 or more are ordered from the graph in one pass: the same components as brute
// force, every edge respected, witnesses that the oracle's graph confirms, with whole or thinned
// graphs; small stuck sets still go to the group-test search.
TEST(VisSort, LargeStuckSetsOrderedFromTheOraclesGraphMatchBruteForce) {
    std::mt19937 rng(23);
    int passes = 0;
    for (int trial = 0; trial < 120; ++trial) {
        const uint32_t n = 16 + rng() % 50;
        OnePassGraphOracle g(n, trial % 2 == 1);
        const double density = 0.02 + (rng() % 100) / 100.0 * 0.12;
        for (uint32_t a = 0; a < n; ++a)
            for (uint32_t b = 0; b < n; ++b)
                if (a != b && (rng() % 10000) < density * 10000)
                    g.addEdge(a, b);
        std::vector<uint32_t> start = identity(n);
        std::shuffle(start.begin(), start.end(), rng);
        const auto r = visSort(g, start);
        SCOPED_TRACE("trial " + std::to_string(trial));
        expectRespectsEdges(g, r);
        const std::set<std::vector<uint32_t>> reported(r.cycles.begin(), r.cycles.end());
        EXPECT_EQ(reported.size(), r.cycles.size());
        EXPECT_EQ(reported, referenceCycles(g));
        ASSERT_EQ(r.cycle_witnesses.size(), r.cycles.size());
        for (std::size_t c = 0; c < r.cycles.size(); ++c)
            for (const Occlusion& o : r.cycle_witnesses[c]) {
                EXPECT_TRUE(g.edges()[o.front][o.back]) << o.front << " -> " << o.back;
                EXPECT_TRUE(std::binary_search(r.cycles[c].begin(), r.cycles[c].end(), o.front));
                EXPECT_TRUE(std::binary_search(r.cycles[c].begin(), r.cycles[c].end(), o.back));
            }
        EXPECT_EQ(r.stats.graph_passes, uint32_t(g.graph_calls));
        passes += g.graph_calls;
    }
    EXPECT_GT(passes, 20); // the one-pass path was taken
}

// With the last order's cycles as hints, a contracted stuck set of 16 or more goes to the graph
// of the groups' members (GroupedOracle::occlusionGraph): a ring of 10 found in one frame grows
// into a ring of 30 in the next, whose contracted order is stuck on the old ring's group and 20
// more. Checked against brute force.
TEST(VisSort, HintedOrdersTakeTheGraphOfTheGroupsMembers) {
    std::mt19937 rng(31);
    for (int trial = 0; trial < 10; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const uint32_t n = 40;
        OnePassGraphOracle g(n, trial % 2 == 1);
        for (uint32_t p = 0; p < 10; ++p)
            g.addEdge(p, (p + 1) % 10);
        for (uint32_t p = 30; p + 1 < n; ++p)
            g.addEdge(p, p + 1);
        std::vector<uint32_t> start = identity(n);
        std::shuffle(start.begin(), start.end(), rng);
        const VisibilityOrder first = visSort(g, start);
        ASSERT_EQ(first.cycles.size(), 1u);
        for (uint32_t p = 9; p < 30; ++p)
            g.addEdge(p, (p + 1) % 30); // the ring grows to 0..29
        g.graph_calls = 0;
        VisibilityOrder next;
        VisSortWorkspace workspace;
        visSort(g, first.order, next, workspace, {first.cycles, first.cycle_witnesses});
        expectRespectsEdges(g, next);
        const std::set<std::vector<uint32_t>> reported(next.cycles.begin(), next.cycles.end());
        EXPECT_EQ(reported, referenceCycles(g));
        EXPECT_EQ(g.graph_calls, 1);
        ASSERT_EQ(next.cycle_witnesses.size(), 1u);
        for (const Occlusion& o : next.cycle_witnesses[0])
            EXPECT_TRUE(g.edges()[o.front][o.back]) << o.front << " -> " << o.back;
    }
}

// An oracle that declines the one-pass graph (as CpuOracle does past its pair budget or member
// limit): the stuck sets are then searched by group tests, with the same components.
class DecliningGraphOracle : public GraphOracle {
public:
    using GraphOracle::GraphOracle;
    bool occlusionGraph(std::span<const uint32_t>, std::vector<Occlusion>&) override {
        ++graph_calls;
        return false;
    }
    int graph_calls = 0;
};

TEST(VisSort, ADeclinedGraphLeavesLargeStuckSetsToGroupTests) {
    std::mt19937 rng(41);
    for (int trial = 0; trial < 20; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const uint32_t n = 20 + rng() % 30;
        DecliningGraphOracle g(n);
        for (uint32_t p = 0; p < 18; ++p) // a ring of 18: stuck on at least 18 members
            g.addEdge(p, (p + 1) % 18);
        for (uint32_t a = 0; a < n; ++a)
            for (uint32_t b = 0; b < n; ++b)
                if (a != b && rng() % 100 < 4)
                    g.addEdge(a, b);
        std::vector<uint32_t> start = identity(n);
        std::shuffle(start.begin(), start.end(), rng);
        const auto r = visSort(g, start);
        expectRespectsEdges(g, r);
        const std::set<std::vector<uint32_t>> reported(r.cycles.begin(), r.cycles.end());
        EXPECT_EQ(reported, referenceCycles(g));
        EXPECT_GT(g.graph_calls, 0); // asked, declined
        EXPECT_EQ(r.stats.graph_passes, 0u);
    }
}

TEST(VisSort, SmallStuckSetsAreSearchedByGroupTests) {
    OnePassGraphOracle g(3, false);
    g.addEdge(0, 1);
    g.addEdge(1, 2);
    g.addEdge(2, 0);
    const auto r = visSort(g, identity(3));
    EXPECT_EQ(g.graph_calls, 0);
    EXPECT_EQ(r.cycles, (std::vector<std::vector<uint32_t>>{{0, 1, 2}}));
}

TEST(VisSort, CoherentRestartFromTheLastOrderIsCheap) {
    const uint32_t n = 300;
    GraphOracle g(n);
    std::mt19937 rng(23);
    for (int e = 0; e < 2000; ++e) {
        uint32_t a = rng() % n, b = rng() % n;
        if (a > b)
            std::swap(a, b);
        if (a != b)
            g.addEdge(a, b);
    }
    std::vector<uint32_t> start = identity(n);
    std::shuffle(start.begin(), start.end(), rng);
    const auto first = visSort(g, start);
    const auto second = visSort(g, first.order);
    EXPECT_EQ(second.order, first.order);
    EXPECT_EQ(second.stats.iterations, 1u);
    EXPECT_LT(second.stats.queries, first.stats.queries);
    EXPECT_LE(second.stats.queries, 2u * n);
}

} // namespace
} // namespace vissort
