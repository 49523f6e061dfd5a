// Duplicated faces and triangles with a repeated corner, as real files have them (assimp's
// OBJ/box_longline.obj triangulates a polygon that visits its four corners 236 times: 944
// triangles, most of them copies of two, the rest with two equal corners). The exact model
// decides both without exact arithmetic (a repeated corner has no fragment; the same corners tie
// at every ray), and the orders stay exact against the ground truth at every level.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "every_frame_check.h"
#include "geometry/exact_fragments.h"
#include "vissort/camera.h"
#include "vissort/camera_path.h"
#include "vissort/frame_driver.h"
#include "vissort/scene.h"

namespace vissort {
namespace {

void addTriangle(TrianglePositions& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    for (const Vec3& v : {a, b, c}) {
        p.x.push_back(float(v.x));
        p.y.push_back(float(v.y));
        p.z.push_back(float(v.z));
    }
}

// A fan over a polygon that goes round the square's corners `turns` times: per turn two real
// triangles (copies of the first turn's) and two with a repeated corner.
void addRevisitingFan(Scene& scene, const std::string& name, const Vec3 (&square)[4], int turns) {
    SceneObject object;
    object.name = name;
    object.first_triangle = uint32_t(scene.triangleCount());
    std::vector<Vec3> polygon;
    for (int turn = 0; turn < turns; ++turn)
        polygon.insert(polygon.end(), std::begin(square), std::end(square));
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
        addTriangle(scene.positions, polygon[0], polygon[i], polygon[i + 1]);
    object.triangle_count = uint32_t(scene.triangleCount()) - object.first_triangle;
    scene.objects.push_back(object);
}

Scene revisitingScene(int turns) {
    Scene scene;
    scene.name = "revisiting fans";
    // Two overlapping squares, one tilted behind the other, and a third crossing both.
    addRevisitingFan(scene, "front", {{-1, -1, 0.5}, {1, -1, 0.5}, {1, 1, 0.5}, {-1, 1, 0.5}},
                     turns);
    addRevisitingFan(scene, "back",
                     {{-0.5, -1.5, -0.5}, {1.5, -1.5, -0.2}, {1.5, 0.5, -0.2}, {-0.5, 0.5, -0.5}},
                     turns);
    addRevisitingFan(scene, "crossing",
                     {{-1.2, 0, -1}, {1.2, 0, -1}, {1.2, 0.2, 1}, {-1.2, 0.2, 1}}, turns);
    CameraSpec camera;
    camera.eye = {0.4, 0.7, 4};
    scene.camera = camera;
    return scene;
}

TEST(DuplicateFaces, TheModelDecidesThemWithoutExactArithmetic) {
    const Scene scene = revisitingScene(3);
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.view().bounds(), 64, 48);
    const detail::ExactFragments model(view);
    const PositionsView positions = scene.positions.view();
    // Triangle 0 is (c0, c1, c2); 4 is its copy a turn later, 2 is (c0, c3, c0).
    const detail::TriangleCorners first = detail::TriangleCorners::of(positions, 0),
                                  copy = detail::TriangleCorners::of(positions, 4),
                                  repeated = detail::TriangleCorners::of(positions, 2);
    ASSERT_TRUE(first.sameCornersAs(copy));
    ASSERT_FALSE(first.sameCornersAs(repeated));
    detail::TriangleCorners turned; // the same corners, starting at another and turning back
    for (int k = 0; k < 3; ++k)
        for (int axis = 0; axis < 3; ++axis)
            turned.p[k][axis] = first.p[(4 - k) % 3][axis];
    ASSERT_TRUE(first.sameCornersAs(turned));
    int covered = 0;
    for (uint32_t py = 0; py < view.height; ++py)
        for (uint32_t px = 0; px < view.width; ++px) {
            const detail::PixelRay ray = model.rays().centre(px, py);
            EXPECT_FALSE(model.covers(ray, repeated));
            if (!model.covers(ray, first))
                continue;
            ++covered;
            EXPECT_EQ(model.compare(ray, first, copy), 0);
            EXPECT_EQ(model.compare(ray, turned, first), 0);
        }
    EXPECT_GT(covered, 100);
    EXPECT_EQ(model.exactEvaluations(), 0u);
}

TEST(DuplicateFaces, OrdersAreExactAtEveryLevel) {
    const Scene scene = revisitingScene(12); // 46 triangles an object, 22 of them with a repeat
    test::EveryFrameCheck check(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                test::everyOracleAndLevel());
    FrameDriver driver(scene, *scene.camera, CameraPath::orbit, 96, 72);
    for (int frame : {0, 1, 2}) {
        driver.seek(frame);
        check.checkFrame(driver.positions(), driver.view(), "frame " + std::to_string(frame));
    }
    const test::EveryFrameTally& t = check.tally();
    EXPECT_EQ(t.violations, 0u);
    EXPECT_GT(t.pairs_checked, 0u); // the squares do occlude each other
    test::PairAnswerTally answers;
    driver.seek(0);
    test::checkPairAnswers(OracleKind::cpu, driver.positions(), driver.view(),
                           scene.trianglePrimitives(), "triangles", answers);
    test::checkPairAnswers(OracleKind::cpu_reference, driver.positions(), driver.view(),
                           scene.trianglePrimitives(), "triangles", answers);
    test::checkPairAnswers(OracleKind::exact, driver.positions(), driver.view(),
                           scene.trianglePrimitives(), "triangles", answers);
    EXPECT_GT(answers.occluding, 0u);
}

} // namespace
} // namespace vissort
