#pragma once
// An occlusion oracle over an explicit graph (its "depth buffer" is the set of primitives drawn
// since the last clear) and the brute-force checks of an order against that graph: ground truth
// for the core's tests, independent of any geometry.

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "vissort/occlusion_oracle.h"
#include "vissort/vis_sort.h"

namespace vissort {

class GraphOracle : public OcclusionOracle {
public:
    explicit GraphOracle(uint32_t n) : occludes_(n, std::vector<uint8_t>(n, 0)), drawn_(n, 0) {}
    /// n primitives and the edges {front, back}.
    GraphOracle(uint32_t n, std::initializer_list<std::pair<uint32_t, uint32_t>> edges)
        : GraphOracle(n) {
        for (const auto& [front, back] : edges)
            addEdge(front, back);
    }
    void addEdge(uint32_t front, uint32_t back) { occludes_[front][back] = 1; }
    void removeEdge(uint32_t front, uint32_t back) { occludes_[front][back] = 0; }
    uint32_t primitiveCount() const override { return uint32_t(drawn_.size()); }
    void clear() override { std::fill(drawn_.begin(), drawn_.end(), 0); }
    void draw(uint32_t p) override { drawn_[p] = 1; }
    bool anyBehind(uint32_t p) override {
        ++queries;
        for (uint32_t q = 0; q < drawn_.size(); ++q)
            if (drawn_[q] && q != p && occludes_[q][p])
                return true;
        return false;
    }
    const std::vector<std::vector<uint8_t>>& edges() const { return occludes_; }
    uint64_t queries = 0;

private:
    std::vector<std::vector<uint8_t>> occludes_;
    std::vector<uint8_t> drawn_;
};

inline std::vector<uint32_t> identity(uint32_t n) {
    std::vector<uint32_t> v(n);
    std::iota(v.begin(), v.end(), 0u);
    return v;
}

// Nontrivial strongly connected components by transitive closure (Warshall).
inline std::set<std::vector<uint32_t>> referenceCycles(const GraphOracle& g) {
    const uint32_t n = g.primitiveCount();
    auto reach = g.edges();
    for (uint32_t k = 0; k < n; ++k)
        for (uint32_t i = 0; i < n; ++i)
            if (reach[i][k])
                for (uint32_t j = 0; j < n; ++j)
                    if (reach[k][j])
                        reach[i][j] = 1;
    std::set<std::vector<uint32_t>> cycles;
    for (uint32_t i = 0; i < n; ++i) {
        std::vector<uint32_t> component{i};
        for (uint32_t j = 0; j < n; ++j)
            if (j != i && reach[i][j] && reach[j][i])
                component.push_back(j);
        std::sort(component.begin(), component.end());
        if (component.size() > 1)
            cycles.insert(component);
    }
    return cycles;
}

// Every edge front -> back between different components has front first.
inline void expectRespectsEdges(const GraphOracle& g, const VisibilityOrder& r) {
    const uint32_t n = g.primitiveCount();
    ASSERT_EQ(r.order.size(), n);
    std::vector<uint32_t> position(n, UINT32_MAX), component(n);
    std::iota(component.begin(), component.end(), 0u);
    for (uint32_t i = 0; i < n; ++i) {
        ASSERT_LT(r.order[i], n);
        ASSERT_EQ(position[r.order[i]], UINT32_MAX) << "duplicate id " << r.order[i];
        position[r.order[i]] = i;
    }
    for (std::size_t c = 0; c < r.cycles.size(); ++c)
        for (uint32_t p : r.cycles[c])
            component[p] = n + uint32_t(c);
    for (uint32_t a = 0; a < n; ++a)
        for (uint32_t b = 0; b < n; ++b)
            if (a != b && g.edges()[a][b] && component[a] != component[b])
                EXPECT_LT(position[a], position[b]) << a << " occludes " << b;
}

} // namespace vissort
