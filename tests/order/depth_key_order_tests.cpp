#include <gtest/gtest.h>

#include "vissort/scene_orderer.h"

namespace vissort {
namespace {

// Three single-triangle primitives at view distances 3, 1, 2, one crossing the near plane.
TEST(DepthKeyOrder, SortsByNearestCornerAndPutsInvisibleLast) {
    TrianglePositions p;
    p.resize(4);
    const double zs[4] = {-3, -1, -2, 10}; // camera at the origin looking down -z
    for (int t = 0; t < 4; ++t)
        for (int c = 0; c < 3; ++c) {
            p.x[t * 3 + c] = float(c == 1);
            p.y[t * 3 + c] = float(c == 2);
            p.z[t * 3 + c] = float(zs[t]);
        }
    CameraSpec camera;
    camera.eye = {0, 0, 0};
    camera.target = {0, 0, -1};
    Bounds b;
    b.add({-1, -1, -3});
    b.add({1, 1, -1});
    const ViewProjection view = frameCamera(camera, b, 8, 8);
    std::vector<PrimitiveRange> primitives{{0, 1}, {1, 1}, {2, 1}, {3, 1}};
    EXPECT_EQ(depthKeyOrder(p, view, primitives), (std::vector<uint32_t>{1, 2, 0, 3}));
}

} // namespace
} // namespace vissort
