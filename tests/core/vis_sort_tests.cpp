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
                                                     {"hinted_cycles", 8}}));
    // The size: a field added to the struct without a line in the table shows here too.
    EXPECT_EQ(sizeof(VisSortStats), 5 * sizeof(uint64_t) + 3 * sizeof(uint32_t) + 4); // + padding
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
