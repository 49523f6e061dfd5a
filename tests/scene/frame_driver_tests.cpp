// FrameDriver: the positions, camera and view of frame f, checked against the pieces it is
// documented to combine (Scene::frame at f * kFrameInterval, cameraOnPath about the first frame's
// bounds, frameCamera over the frame's own bounds), computed here independently.

#include "vissort/frame_driver.h"

#include <gtest/gtest.h>

#include <string>

#include "scenes/scene_library.h"
#include "vissort/camera.h"
#include "vissort/camera_path.h"
#include "vissort/scene.h"

namespace vissort {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;

Scene load(const std::string& specification) {
    Result<Scene> loaded = samples::loadScene(specification);
    EXPECT_TRUE(loaded) << specification << ": " << loaded.error;
    return loaded ? std::move(*loaded.value) : Scene{};
}

void expectPositionsEqual(PositionsView actual, const TrianglePositions& expected, int frame) {
    ASSERT_EQ(actual.x.size(), expected.x.size()) << "frame " << frame;
    ASSERT_EQ(actual.y.size(), expected.y.size()) << "frame " << frame;
    ASSERT_EQ(actual.z.size(), expected.z.size()) << "frame " << frame;
    for (std::size_t i = 0; i < expected.x.size(); ++i) {
        ASSERT_EQ(actual.x[i], expected.x[i]) << "frame " << frame << " corner " << i;
        ASSERT_EQ(actual.y[i], expected.y[i]) << "frame " << frame << " corner " << i;
        ASSERT_EQ(actual.z[i], expected.z[i]) << "frame " << frame << " corner " << i;
    }
}

void expectCameraEqual(const CameraSpec& actual, const CameraSpec& expected, int frame) {
    EXPECT_EQ(actual.projection, expected.projection) << "frame " << frame;
    EXPECT_EQ(actual.eye, expected.eye) << "frame " << frame;
    EXPECT_EQ(actual.target, expected.target) << "frame " << frame;
    EXPECT_EQ(actual.up, expected.up) << "frame " << frame;
    EXPECT_EQ(actual.fov_degrees, expected.fov_degrees) << "frame " << frame;
    EXPECT_EQ(actual.ortho_direction, expected.ortho_direction) << "frame " << frame;
}

void expectViewEqual(const ViewProjection& actual, const ViewProjection& expected, int frame) {
    EXPECT_EQ(actual.projection, expected.projection) << "frame " << frame;
    EXPECT_EQ(actual.width, expected.width) << "frame " << frame;
    EXPECT_EQ(actual.height, expected.height) << "frame " << frame;
    EXPECT_EQ(actual.view, expected.view) << "frame " << frame;
    EXPECT_EQ(actual.projection_matrix, expected.projection_matrix) << "frame " << frame;
    EXPECT_EQ(actual.near, expected.near) << "frame " << frame;
    EXPECT_EQ(actual.far, expected.far) << "frame " << frame;
    EXPECT_EQ(actual.eye_position, expected.eye_position) << "frame " << frame;
    EXPECT_EQ(actual.forward, expected.forward) << "frame " << frame;
}

bool samePositions(const TrianglePositions& a, const TrianglePositions& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

TEST(FrameDriver, BeforeTheFirstSeekFrameIsMinusOneAndTimeZero) {
    const Scene scene = load("builtin:bunnies?n=3");
    const FrameDriver positions_only(scene);
    EXPECT_EQ(positions_only.frame(), -1);
    EXPECT_EQ(positions_only.time(), 0.0);
    const FrameDriver with_view(scene, defaultCamera(scene.positions.bounds()), CameraPath::orbit,
                                kWidth, kHeight);
    EXPECT_EQ(with_view.frame(), -1);
    EXPECT_EQ(with_view.time(), 0.0);
    EXPECT_TRUE(with_view.hasView());
    EXPECT_EQ(with_view.width(), kWidth);
    EXPECT_EQ(with_view.height(), kHeight);
}

TEST(FrameDriver, DynamicScenePositionsAreTheSceneFramesInAnyOrder) {
    const Scene scene = load("builtin:bunnies?n=3");
    ASSERT_TRUE(scene.isDynamic());
    ASSERT_GT(scene.triangleCount(), 0u);
    // The scene really moves between the frames visited, so a stale buffer would be caught.
    ASSERT_FALSE(samePositions(scene.frame(5 * kFrameInterval), scene.frame(0.0)));
    ASSERT_FALSE(samePositions(scene.frame(3 * kFrameInterval), scene.frame(5 * kFrameInterval)));

    FrameDriver driver(scene);
    EXPECT_FALSE(driver.hasView());
    for (int frame : {5, 0, 3, 5}) {
        driver.seek(frame);
        EXPECT_EQ(driver.frame(), frame);
        EXPECT_DOUBLE_EQ(driver.time(), frame * kFrameInterval);
        expectPositionsEqual(driver.positions(), scene.frame(frame * kFrameInterval), frame);
    }
}

TEST(FrameDriver, DynamicSceneCameraAndViewFollowThePathAndTheFrameBounds) {
    const Scene scene = load("builtin:bunnies?n=3");
    ASSERT_TRUE(scene.isDynamic());
    const Bounds first_bounds = scene.frame(0.0).bounds();
    const CameraSpec base = defaultCamera(first_bounds, double(kWidth) / kHeight);
    // Framing to frame 5's bounds differs from framing to the first frame's, so a view framed to
    // the wrong bounds would be caught.
    const ViewProjection framed_first = frameCamera(base, first_bounds, kWidth, kHeight);
    const ViewProjection framed_five =
        frameCamera(base, scene.frame(5 * kFrameInterval).bounds(), kWidth, kHeight);
    ASSERT_NE(framed_first.near, framed_five.near);
    for (CameraPath path : {CameraPath::fixed, CameraPath::orbit, CameraPath::flythrough}) {
        SCOPED_TRACE(cameraPathName(path));
        FrameDriver driver(scene, base, path, kWidth, kHeight);
        ASSERT_TRUE(driver.hasView());
        for (int frame : {5, 0, 3}) {
            driver.seek(frame);
            EXPECT_EQ(driver.frame(), frame);
            EXPECT_DOUBLE_EQ(driver.time(), frame * kFrameInterval);
            const TrianglePositions expected_positions = scene.frame(frame * kFrameInterval);
            expectPositionsEqual(driver.positions(), expected_positions, frame);
            // The path turns about the first frame's bounds, whatever frame is current.
            const CameraSpec expected_camera = cameraOnPath(base, path, frame, first_bounds);
            expectCameraEqual(driver.camera(), expected_camera, frame);
            // The view is framed to this frame's own bounds.
            const ViewProjection expected_view =
                frameCamera(expected_camera, expected_positions.bounds(), kWidth, kHeight);
            expectViewEqual(driver.view(), expected_view, frame);
            EXPECT_EQ(driver.view().width, kWidth);
            EXPECT_EQ(driver.view().height, kHeight);
        }
    }
}

// --path scene: every frame's camera from the scene's key frames at frame / 30 s, the base
// camera ignored.
TEST(FrameDriver, ScenePathFollowsTheKeyFrames) {
    Scene scene = load("builtin:bunnies?n=3");
    CameraSpec start, end;
    start.eye = {0, 1, 12};
    start.target = {0, 0, 0};
    end.eye = {6, 2, 6};
    end.target = {1, 0, 0};
    end.fov_degrees = 60;
    scene.camera_path = {{0.0, start}, {0.5, end}};
    const CameraSpec base = defaultCamera(scene.positions.bounds());
    FrameDriver driver(scene, base, CameraPath::scene, kWidth, kHeight);
    for (int frame : {0, 6, 15, 40}) {
        driver.seek(frame);
        const CameraSpec expected = cameraAtTime(scene.camera_path, frame * kFrameInterval);
        expectCameraEqual(driver.camera(), expected, frame);
        expectViewEqual(driver.view(),
                        frameCamera(expected, driver.positions().bounds(), kWidth, kHeight), frame);
    }
    driver.seek(15); // exactly the last key
    EXPECT_EQ(driver.camera().fov_degrees, 60.0);
    EXPECT_EQ(driver.camera().eye.x, 6.0);
    driver.seek(6); // 0.2 s: 40% of the way
    EXPECT_NEAR(driver.camera().eye.x, 2.4, 1e-12);
    EXPECT_NEAR(driver.camera().fov_degrees, 51.0, 1e-12);
}

TEST(FrameDriver, OrbitMovesTheCameraAndReframingFollowsTheBounds) {
    // Sanity of the ground truth above: on this scene the orbit camera and the framing really
    // change from frame to frame, so matching them is not trivially the base camera.
    const Scene scene = load("builtin:bunnies?n=3");
    const Bounds first_bounds = scene.positions.bounds();
    const CameraSpec base = defaultCamera(first_bounds, double(kWidth) / kHeight);
    FrameDriver driver(scene, base, CameraPath::orbit, kWidth, kHeight);
    driver.seek(0);
    const CameraSpec camera0 = driver.camera();
    const ViewProjection view0 = driver.view();
    expectCameraEqual(camera0, base, 0); // frame 0 of an orbit is the base camera itself
    driver.seek(5);
    EXPECT_FALSE(driver.camera().eye == camera0.eye);
    EXPECT_NE(driver.view().view, view0.view);
}

TEST(FrameDriver, StaticSceneAliasesTheSceneArraysWithoutACopy) {
    const Scene scene = load("builtin:slabs?layers=3&seed=2");
    ASSERT_FALSE(scene.isDynamic());
    ASSERT_GT(scene.triangleCount(), 0u);
    const Bounds bounds = scene.positions.bounds();
    const CameraSpec base = defaultCamera(bounds, double(kWidth) / kHeight);

    FrameDriver positions_only(scene);
    EXPECT_FALSE(positions_only.hasView());
    FrameDriver driver(scene, base, CameraPath::orbit, kWidth, kHeight);
    for (int frame : {7, 0, 2}) {
        for (FrameDriver* d : {&positions_only, &driver}) {
            d->seek(frame);
            EXPECT_EQ(d->frame(), frame);
            EXPECT_DOUBLE_EQ(d->time(), frame * kFrameInterval);
            const PositionsView positions = d->positions();
            EXPECT_EQ(positions.x.data(), scene.positions.x.data()) << "frame " << frame;
            EXPECT_EQ(positions.y.data(), scene.positions.y.data()) << "frame " << frame;
            EXPECT_EQ(positions.z.data(), scene.positions.z.data()) << "frame " << frame;
            EXPECT_EQ(positions.x.size(), scene.positions.x.size());
            EXPECT_EQ(positions.y.size(), scene.positions.y.size());
            EXPECT_EQ(positions.z.size(), scene.positions.z.size());
        }
        const CameraSpec expected_camera = cameraOnPath(base, CameraPath::orbit, frame, bounds);
        expectCameraEqual(driver.camera(), expected_camera, frame);
        expectViewEqual(driver.view(), frameCamera(expected_camera, bounds, kWidth, kHeight),
                        frame);
    }
}

TEST(FrameDriver, OrthographicBaseCameraOnAnOrbit) {
    const Scene scene = load("builtin:bunnies?n=3");
    const Bounds first_bounds = scene.positions.bounds();
    CameraSpec base;
    base.projection = Projection::orthographic;
    base.ortho_direction = {0.3, -0.2, -1.0};
    FrameDriver driver(scene, base, CameraPath::orbit, 40, 30);
    for (int frame : {4, 1}) {
        driver.seek(frame);
        const CameraSpec expected_camera =
            cameraOnPath(base, CameraPath::orbit, frame, first_bounds);
        expectCameraEqual(driver.camera(), expected_camera, frame);
        expectViewEqual(
            driver.view(),
            frameCamera(expected_camera, scene.frame(frame * kFrameInterval).bounds(), 40, 30),
            frame);
        EXPECT_EQ(driver.view().projection, Projection::orthographic);
    }
}

} // namespace
} // namespace vissort
