// What vissort's cell order is made of, each against a reference independent of it:
// faceConsistentOrder against the shared faces' planes (every face's two cells in the order the
// eye sees them, computed here from the cells' centres), ConvexFacingOracle against the same
// oracle drawing and querying every face of every cell (the same answers on random passes,
// cameras outside the grid and inside it), and the queries a cell vissort asks on coherent
// frames (the bound of 3; the pictures' exactness is volume_renderer_tests.cpp's).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "volume/cell_orders.h"
#include "volume/convex_facing_oracle.h"
#include "volume_test_support.h"

namespace vissort {
namespace {

Vec3 centreOf(const TetGrid& grid, const Tet& tet) {
    Vec3 sum{0, 0, 0};
    for (const uint32_t p : tet)
        sum = sum + grid.points[p];
    return sum * 0.25;
}

// For every shared face, whether the order puts first the cell on the eye's side of its plane
// (the side the cell's centre is on); the number of faces that disagree.
std::size_t facesDisagreeing(const TetGrid& grid, const std::vector<TetNeighbours>& neighbours,
                             const ViewProjection& view, const std::vector<uint32_t>& order) {
    std::vector<uint32_t> position(grid.tets.size());
    for (uint32_t i = 0; i < order.size(); ++i)
        position[order[i]] = i;
    std::size_t wrong = 0;
    for (uint32_t t = 0; t < grid.tets.size(); ++t)
        for (int f = 0; f < 4; ++f) {
            const uint32_t u = neighbours[t][f];
            if (u == kNoNeighbour || u < t)
                continue;
            const Tet& tet = grid.tets[t];
            const Vec3& a = grid.points[tet[kTetFaceCorners[f][0]]];
            const Vec3 normal = cross(grid.points[tet[kTetFaceCorners[f][1]]] - a,
                                      grid.points[tet[kTetFaceCorners[f][2]]] - a);
            const double eye = view.projection == Projection::perspective
                                   ? dot(normal, view.eye_position - a)
                                   : -dot(normal, view.forward);
            const double t_side = dot(normal, centreOf(grid, tet) - a);
            if (eye == 0)
                continue;
            const bool t_first = (eye > 0) == (t_side > 0);
            wrong += t_first != (position[t] < position[u]);
        }
    return wrong;
}

TEST(FaceConsistentOrder, EveryFaceAgreesAndThePreferenceIsKeptWhereAllowed) {
    for (const char* spec : {"builtin:knot?n=14", "builtin:cube?n=5", "builtin:torus?n=10"}) {
        for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
            SCOPED_TRACE(std::string(spec) + (projection == Projection::perspective ? " p" : " o"));
            const TetGrid grid = *loadGrid(spec).value;
            const std::vector<TetNeighbours> neighbours = *faceNeighbours(grid).value;
            const ViewProjection view = test::gridView(grid, projection, 64, 40, 25);
            // A preference the faces mostly disagree with: the centres' order reversed.
            std::vector<uint32_t> preferred = detail::centroidOrder(grid, view);
            std::reverse(preferred.begin(), preferred.end());
            const detail::MpvoOrder order =
                detail::faceConsistentOrder(grid, neighbours, view, preferred);
            ASSERT_EQ(order.order.size(), grid.tets.size());
            std::vector<uint32_t> sorted = order.order;
            std::sort(sorted.begin(), sorted.end());
            for (uint32_t i = 0; i < sorted.size(); ++i)
                ASSERT_EQ(sorted[i], i) << "not a permutation";
            EXPECT_GT(facesDisagreeing(grid, neighbours, view, preferred), 0u);
            EXPECT_EQ(order.broken_cycles, 0u); // these grids' faces order them without a cycle
            EXPECT_EQ(facesDisagreeing(grid, neighbours, view, order.order), 0u);
            // A preference the faces agree with comes back unchanged.
            EXPECT_EQ(detail::faceConsistentOrder(grid, neighbours, view, order.order).order,
                      order.order);
        }
    }
}

// The oracle over whole cells and the facing one over its own inner oracle, bound to the same
// cells: random draws, then every cell queried, several times.
void expectSameAnswers(const TetGrid& grid, const ViewProjection& view) {
    const TrianglePositions faces = detail::cellFaces(grid);
    const std::vector<PrimitiveRange> cells = detail::cellRanges(grid.tets.size());
    std::unique_ptr<GeometryOracle> whole = *makeOracle(OracleKind::cpu).value;
    std::unique_ptr<GeometryOracle> inner = *makeOracle(OracleKind::cpu).value;
    whole->setDepthTolerance(1e-6f);
    inner->setDepthTolerance(1e-6f);
    detail::ConvexFacingOracle facing(*inner);
    whole->bind(faces, view, cells);
    facing.bind(faces, view, cells);
    EXPECT_LT(facing.frontFaces() + facing.backFaces(), 8 * grid.tets.size());
    std::mt19937 random(7);
    std::size_t behind = 0;
    for (int round = 0; round < 6; ++round) {
        whole->clear();
        facing.clear();
        for (uint32_t c = 0; c < cells.size(); ++c)
            if (random() % 4 == 0) {
                whole->draw(c);
                facing.draw(c);
            }
        for (uint32_t c = 0; c < cells.size(); ++c) {
            const bool expected = whole->anyBehind(c);
            ASSERT_EQ(facing.anyBehind(c), expected) << "cell " << c << ", round " << round;
            behind += expected;
        }
    }
    EXPECT_GT(behind, 0u); // the passes found cells behind others: the test can fail
}

TEST(ConvexFacingOracle, AnswersAsEveryFaceWould) {
    for (const char* spec : {"builtin:knot?n=12", "builtin:cube?n=5"}) {
        for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
            SCOPED_TRACE(std::string(spec) + (projection == Projection::perspective ? " p" : " o"));
            const TetGrid grid = *loadGrid(spec).value;
            expectSameAnswers(grid, test::gridView(grid, projection, 96, 30, 20));
        }
    }
}

// The eye inside the grid: the cells around it reach the near plane and keep every face.
TEST(ConvexFacingOracle, CellsAtTheNearPlaneKeepEveryFace) {
    const TetGrid grid = *loadGrid("builtin:cube?n=6").value;
    Bounds bounds;
    for (const Vec3& p : grid.points)
        bounds.add(p);
    CameraSpec camera;
    camera.eye = bounds.centre() + Vec3{0.01, 0.02, 0.03};
    camera.target = bounds.centre() + Vec3{1, 0.3, 0.2};
    const ViewProjection view = frameCamera(camera, bounds, 96, 96);
    expectSameAnswers(grid, view);
}

// The bound: at most 3 queries a cell on every coherent frame of a 3-degree orbit.
TEST(VisibilityCellOrder, CoherentFramesAskAtMostThreeQueriesACell) {
    for (const char* spec : {"builtin:knot?n=20", "builtin:cube?n=8"}) {
        SCOPED_TRACE(spec);
        const TetGrid grid = *loadGrid(spec).value;
        VolumeRenderer renderer(grid, VolumeMethod::vissort, OracleKind::cpu, 2);
        const VolumeSettings settings = test::settingsWith("bands");
        for (int frame = 0; frame < 6; ++frame) {
            const ViewProjection view =
                test::gridView(grid, Projection::perspective, 96, 30 + 3.0 * frame, 20);
            ASSERT_TRUE(renderer.render(settings, view));
            const double per_cell =
                double(renderer.stats().queries) / double(renderer.stats().cells);
            if (frame > 0) {
                EXPECT_LE(per_cell, 3.0) << "frame " << frame;
            }
        }
    }
}

} // namespace
} // namespace vissort
