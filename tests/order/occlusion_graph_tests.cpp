// CpuOracle's occlusion graph in one pass (OcclusionOracle::occlusionGraph) against the exact
// ray-cast ground truth (ground_truth.h): every edge it gives is a true occlusion, and its edges
// connect exactly the members the true graph among them connects, on touching, coplanar, copied
// and interpenetrating objects, in both projections and at grazing angles.
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ground_truth.h"
#include "touching_models.h"
#include "vissort/cpu_oracle.h"

namespace vissort {
namespace {

using test::Model;

// Objects of a few random triangles each, crossing one another: cycles of many members.
Model crossingSoup(uint32_t seed, int objects) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> at(-1, 1), offset(-0.6, 0.6);
    Model m;
    for (int o = 0; o < objects; ++o) {
        const uint32_t first = uint32_t(m.positions.triangleCount());
        const Vec3 centre{at(rng), at(rng) * 0.5, at(rng)};
        const int triangles = 1 + int(rng() % 3);
        for (int t = 0; t < triangles; ++t) {
            const auto corner = [&] {
                return Vec3{centre.x + offset(rng), centre.y + offset(rng), centre.z + offset(rng)};
            };
            test::addTriangle(m.positions, corner(), corner(), corner());
        }
        m.objects.push_back({first, uint32_t(triangles)});
    }
    return m;
}

// The box grid with every box also copied as its own object: copies tie everywhere.
Model copiedBoxes() {
    Model m = test::boxGrid();
    const std::size_t boxes = m.objects.size();
    for (std::size_t b = 0; b < boxes; ++b) {
        const uint32_t first = uint32_t(m.positions.triangleCount());
        const PrimitiveRange r = m.objects[b];
        for (uint32_t t = r.first_triangle; t < r.first_triangle + r.triangle_count; ++t)
            for (int c = 0; c < 3; ++c) {
                m.positions.x.push_back(m.positions.x[3 * t + c]);
                m.positions.y.push_back(m.positions.y[3 * t + c]);
                m.positions.z.push_back(m.positions.z[3 * t + c]);
            }
        m.objects.push_back({first, r.triangle_count});
    }
    return m;
}

// reach[a][b]: b reachable from a by one or more edges (Warshall).
std::vector<std::vector<uint8_t>> closure(std::vector<std::vector<uint8_t>> reach) {
    const std::size_t n = reach.size();
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t i = 0; i < n; ++i)
            if (reach[i][k])
                for (std::size_t j = 0; j < n; ++j)
                    reach[i][j] |= reach[k][j];
    return reach;
}

// Checks the oracle's graph of `members` against the truth; returns how many true edges there
// were among them (so that a caller knows the case was not empty).
std::size_t expectTrueGraph(const Model& m, const ViewProjection& view,
                            const std::vector<std::vector<uint32_t>>& truth,
                            const std::vector<uint32_t>& members) {
    CpuOracle oracle;
    oracle.bind(m.positions, view, m.objects);
    std::vector<Occlusion> edges{{7, 7}}; // kept: the oracle appends
    EXPECT_TRUE(oracle.occlusionGraph(members, edges));
    EXPECT_EQ(edges.front(), (Occlusion{7, 7}));
    edges.erase(edges.begin());
    const std::size_t k = members.size();
    std::vector<std::vector<uint8_t>> given(k, std::vector<uint8_t>(k, 0)), real = given;
    std::size_t true_edges = 0;
    for (std::size_t a = 0; a < k; ++a)
        for (std::size_t b = 0; b < k; ++b)
            if (a != b && std::binary_search(truth[members[a]].begin(), truth[members[a]].end(),
                                             members[b])) {
                real[a][b] = 1;
                ++true_edges;
            }
    for (const Occlusion& e : edges) {
        EXPECT_LT(e.front, k);
        EXPECT_LT(e.back, k);
        if (e.front >= k || e.back >= k)
            return true_edges;
        EXPECT_TRUE(real[e.front][e.back])
            << "not an occlusion: " << members[e.front] << " -> " << members[e.back];
        given[e.front][e.back] = 1;
    }
    EXPECT_EQ(closure(given), closure(real)) << "reachability differs";
    return true_edges;
}

TEST(OcclusionGraph, ConnectsWhatTheExactGraphConnects) {
    std::vector<std::pair<std::string, Model>> models{{"box grid", test::boxGrid()},
                                                      {"house", test::house()},
                                                      {"coplanar quads", test::coplanarQuads()},
                                                      {"stick ring", test::stickRing()},
                                                      {"copied boxes", copiedBoxes()},
                                                      {"soup 1", crossingSoup(1, 30)},
                                                      {"soup 2", crossingSoup(2, 60)}};
    std::mt19937 rng(9);
    std::size_t true_edges = 0;
    for (const auto& [name, m] : models)
        for (const test::View& v : test::grazingViews())
            for (uint32_t size : {64u, 200u}) {
                SCOPED_TRACE(name + " " + v.name + " " + std::to_string(size));
                const ViewProjection view =
                    frameCamera(v.camera, m.positions.bounds(), size, size * 3 / 4);
                const auto truth = test::occlusionGraph(m.positions, view, m.objects);
                std::vector<uint32_t> members(m.objects.size());
                for (uint32_t i = 0; i < members.size(); ++i)
                    members[i] = i;
                std::shuffle(members.begin(), members.end(), rng);
                true_edges += expectTrueGraph(m, view, truth, members);
                // A part of them: paths through the others do not count.
                members.resize((members.size() + 1) / 2);
                true_edges += expectTrueGraph(m, view, truth, members);
            }
    EXPECT_GT(true_edges, 1000u);
}

// Ties stacked at every pixel (200 copies of one square, each its own object: 19,900 tied pairs a
// pixel) pass the pair budget: the oracle declines, leaving the edges as they were, rather than
// square its work; the orderer's group tests take the set (vis_sort_tests).
TEST(OcclusionGraph, StackedTiesPastThePairBudgetAreDeclined) {
    Model m;
    const uint32_t copies = 200;
    for (uint32_t c = 0; c < copies; ++c) {
        const uint32_t first = uint32_t(m.positions.triangleCount());
        test::addTriangle(m.positions, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0});
        test::addTriangle(m.positions, {-1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
        m.objects.push_back({first, 2});
    }
    const ViewProjection view = frameCamera({}, m.positions.bounds(), 64, 64);
    CpuOracle oracle;
    oracle.bind(m.positions, view, m.objects);
    std::vector<uint32_t> members(copies);
    for (uint32_t i = 0; i < copies; ++i)
        members[i] = i;
    std::vector<Occlusion> edges{{7, 7}};
    EXPECT_FALSE(oracle.occlusionGraph(members, edges));
    EXPECT_EQ(edges, (std::vector<Occlusion>{{7, 7}}));
    // A few of them are within the budget, and copies occlude nothing.
    members.resize(20);
    EXPECT_TRUE(oracle.occlusionGraph(members, edges));
    EXPECT_EQ(edges, (std::vector<Occlusion>{{7, 7}}));
}

TEST(OcclusionGraph, OnlyUnderTheExactRule) {
    const Model m = crossingSoup(3, 20);
    const ViewProjection view = frameCamera({}, m.positions.bounds(), 64, 48);
    CpuOracle oracle;
    oracle.setDepthTolerance(1e-3f);
    oracle.bind(m.positions, view, m.objects);
    std::vector<Occlusion> edges;
    EXPECT_FALSE(oracle.occlusionGraph(std::vector<uint32_t>{0, 1, 2}, edges));
    EXPECT_TRUE(edges.empty());
}

} // namespace
} // namespace vissort
