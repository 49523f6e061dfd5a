// The one-pass ordering's components (src/core/graph_components.h) against brute force: the
// strongly connected components by transitive closure (graph_oracle.h), the topological order
// checked edge by edge, the witnesses by reachability over their own edges.
#include "core/graph_components.h"

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "graph_oracle.h"

namespace vissort {
namespace {

// Whether `edges` make every member reach every other (members ascending).
bool stronglyConnects(const std::vector<uint32_t>& members, const std::vector<Occlusion>& edges) {
    for (uint32_t from : members) {
        std::set<uint32_t> reached{from};
        std::vector<uint32_t> stack{from};
        while (!stack.empty()) {
            const uint32_t u = stack.back();
            stack.pop_back();
            for (const Occlusion& e : edges)
                if (e.front == u && reached.insert(e.back).second)
                    stack.push_back(e.back);
        }
        for (uint32_t to : members)
            if (!reached.count(to))
                return false;
    }
    return true;
}

TEST(GraphComponents, RandomGraphsMatchBruteForceInTopologicalOrder) {
    std::mt19937 rng(5);
    for (int trial = 0; trial < 200; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const uint32_t n = 1 + rng() % 60;
        GraphOracle g(n);
        std::vector<Occlusion> edges;
        const uint32_t density = rng() % 800; // per 10,000
        for (uint32_t a = 0; a < n; ++a)
            for (uint32_t b = 0; b < n; ++b)
                if (rng() % 10000 < density) {
                    edges.push_back({a, b}); // self-edges too: allowed, ignored
                    if (a != b)
                        g.addEdge(a, b);
                    if (rng() % 4 == 0)
                        edges.push_back({a, b}); // and repeats
                }
        std::shuffle(edges.begin(), edges.end(), rng);
        const std::vector<detail::SourceComponent> components = detail::graphComponents(n, edges);
        // Every node once; components ascending; the cyclic ones brute force's.
        std::vector<uint32_t> component_of(n, UINT32_MAX);
        std::set<std::vector<uint32_t>> cyclic;
        for (uint32_t c = 0; c < components.size(); ++c) {
            const auto& members = components[c].members;
            ASSERT_FALSE(members.empty());
            EXPECT_TRUE(std::is_sorted(members.begin(), members.end()));
            for (uint32_t u : members) {
                ASSERT_LT(u, n);
                EXPECT_EQ(component_of[u], UINT32_MAX) << u << " in two components";
                component_of[u] = c;
            }
            if (members.size() > 1)
                cyclic.insert(members);
        }
        EXPECT_EQ(std::count(component_of.begin(), component_of.end(), UINT32_MAX), 0);
        EXPECT_EQ(cyclic, referenceCycles(g));
        // Topological: an edge never leads to an earlier component.
        for (const Occlusion& e : edges)
            EXPECT_LE(component_of[e.front], component_of[e.back]) << e.front << " -> " << e.back;
        // Witnesses: 2 (k - 1) edges of the graph, within the component, connecting it.
        for (const detail::SourceComponent& c : components) {
            if (c.members.size() < 2) {
                EXPECT_TRUE(c.witness.empty());
                continue;
            }
            EXPECT_EQ(c.witness.size(), 2 * (c.members.size() - 1));
            for (const Occlusion& o : c.witness) {
                EXPECT_TRUE(g.edges()[o.front][o.back]);
                EXPECT_EQ(component_of[o.front], component_of[o.back]);
            }
            EXPECT_TRUE(stronglyConnects(c.members, c.witness));
        }
    }
}

// A ring of 200,000: as deep as a depth-first search goes, without recursion.
TEST(GraphComponents, ALongRingIsOneComponentWithoutRecursion) {
    const uint32_t n = 200000;
    std::vector<Occlusion> edges;
    for (uint32_t u = 0; u < n; ++u)
        edges.push_back({u, (u + 1) % n});
    const auto components = detail::graphComponents(n, edges);
    ASSERT_EQ(components.size(), 1u);
    EXPECT_EQ(components[0].members.size(), n);
    EXPECT_EQ(components[0].witness.size(), 2 * (n - 1));
}

TEST(GraphComponents, AChainComesOutFrontToBack) {
    const std::vector<Occlusion> edges{{2, 0}, {0, 1}, {3, 2}};
    const auto components = detail::graphComponents(4, edges);
    std::vector<uint32_t> order;
    for (const auto& c : components)
        order.push_back(c.members.at(0));
    EXPECT_EQ(order, (std::vector<uint32_t>{3, 2, 0, 1}));
}

} // namespace
} // namespace vissort
