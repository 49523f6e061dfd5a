#include "tarjan_scc.h"

#include <gtest/gtest.h>

namespace vissort {
namespace {

using Graph = std::vector<std::vector<uint32_t>>;

TEST(TarjanScc, HandMadeGraph) {
    // 0 -> 1 -> 2 -> 0 is a cycle feeding 3 <-> 4; 5 stands alone; 6 has a self loop only.
    const Graph graph = {{1}, {2}, {0, 3}, {4}, {3}, {}, {6}};
    EXPECT_EQ(test::stronglyConnectedComponents(graph), (Graph{{0, 1, 2}, {3, 4}, {5}, {6}}));
    EXPECT_EQ(test::cyclicComponents(graph), (Graph{{0, 1, 2}, {3, 4}}));
}

TEST(TarjanScc, EmptyAndAcyclic) {
    EXPECT_TRUE(test::stronglyConnectedComponents({}).empty());
    const Graph chain = {{1, 2}, {2}, {}};
    EXPECT_EQ(test::stronglyConnectedComponents(chain), (Graph{{0}, {1}, {2}}));
    EXPECT_TRUE(test::cyclicComponents(chain).empty());
}

TEST(TarjanScc, NestedCyclesMerge) {
    // Two cycles 0-1-2 and 2-3-4 sharing vertex 2 form one component; 5 -> 0 stays outside.
    const Graph graph = {{1}, {2}, {0, 3}, {4}, {2}, {0}};
    EXPECT_EQ(test::cyclicComponents(graph), (Graph{{0, 1, 2, 3, 4}}));
}

TEST(TarjanScc, LongChainDoesNotOverflowTheStack) {
    const uint32_t n = 200000;
    Graph ring(n);
    for (uint32_t i = 0; i < n; ++i)
        ring[i] = {(i + 1) % n};
    const Graph components = test::cyclicComponents(ring);
    ASSERT_EQ(components.size(), 1u);
    EXPECT_EQ(components[0].size(), n);
}

} // namespace
} // namespace vissort
