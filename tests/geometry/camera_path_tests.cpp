// Camera paths: names, the static path, the orbit (3 degrees per frame about the vertical axis
// through the scene's centre) and the flythrough (inside the scene, 0.6 r from the centre),
// with angles and distances computed in the test.

#include "vissort/camera_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace vissort {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Bounds boxBounds(const Vec3& lo, const Vec3& hi) {
    Bounds b;
    b.add(lo);
    b.add(hi);
    return b;
}

Vec3 horizontal(const Vec3& a) {
    return {a.x, 0, a.z};
}

// Unsigned angle between two vectors, in degrees.
double angleDegrees(const Vec3& a, const Vec3& b) {
    const double c = dot(a, b) / (length(a) * length(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) / kDegree;
}

// Signed angle of the horizontal turn from a to b about +y (right-handed), in degrees.
double signedTurnDegrees(const Vec3& a, const Vec3& b) {
    // Cross product's y component: a.z * b.x - a.x * b.z.
    return std::atan2(a.z * b.x - a.x * b.z, a.x * b.x + a.z * b.z) / kDegree;
}

// a - b as an angle in (-180, 180].
double angleDifference(double a, double b) {
    double d = std::fmod(a - b, 360.0);
    if (d > 180)
        d -= 360;
    if (d <= -180)
        d += 360;
    return d;
}

void expectSameVec(const Vec3& a, const Vec3& b, double tolerance, const std::string& what) {
    EXPECT_NEAR(a.x, b.x, tolerance) << what;
    EXPECT_NEAR(a.y, b.y, tolerance) << what;
    EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

void expectSameCamera(const CameraSpec& a, const CameraSpec& b, double tolerance) {
    EXPECT_EQ(a.projection, b.projection);
    expectSameVec(a.eye, b.eye, tolerance, "eye");
    expectSameVec(a.target, b.target, tolerance, "target");
    expectSameVec(a.up, b.up, tolerance, "up");
    expectSameVec(a.ortho_direction, b.ortho_direction, tolerance, "ortho_direction");
    EXPECT_EQ(a.fov_degrees, b.fov_degrees);
}

CameraSpec perspectiveBase() {
    CameraSpec camera;
    camera.projection = Projection::perspective;
    camera.eye = {7, 4, -1};
    camera.target = {1.5, 0.5, 2.5}; // near the centre, not on it
    camera.up = {0, 1, 0};
    camera.fov_degrees = 35;
    return camera;
}

CameraSpec orthographicBase() {
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.ortho_direction = {1, -0.5, -2};
    return camera;
}

// Centre (1, 1, 2), radius 2.5: a flat box with diagonal (3, 4, 0).
const Bounds kBounds = boxBounds({-0.5, -1, 2}, {2.5, 3, 2});

TEST(CameraPathNames, RoundTrip) {
    for (CameraPath path :
         {CameraPath::fixed, CameraPath::orbit, CameraPath::flythrough, CameraPath::scene}) {
        const Result<CameraPath> parsed = parseCameraPath(cameraPathName(path));
        ASSERT_TRUE(parsed) << cameraPathName(path) << ": " << parsed.error;
        EXPECT_EQ(parsed.error, "");
        EXPECT_EQ(*parsed.value, path);
    }
    EXPECT_STREQ(cameraPathName(CameraPath::fixed), "static");
    EXPECT_STREQ(cameraPathName(CameraPath::orbit), "orbit");
    EXPECT_STREQ(cameraPathName(CameraPath::flythrough), "flythrough");
    EXPECT_STREQ(cameraPathName(CameraPath::scene), "scene");
    const Result<CameraPath> path = parseCameraPath("static");
    ASSERT_TRUE(path);
    EXPECT_EQ(*path.value, CameraPath::fixed);
}

TEST(CameraPathNames, RejectsUnknownNames) {
    for (const char* name : {"", "fixed", "Orbit", "orbit ", "fly", "flythrough2", "STATIC"}) {
        const Result<CameraPath> path = parseCameraPath(name);
        EXPECT_FALSE(path) << '"' << name << '"';
        EXPECT_NE(path.error, "") << '"' << name << '"';
    }
}

TEST(CameraPathStatic, ReturnsTheBaseCamera) {
    for (const CameraSpec& base : {perspectiveBase(), orthographicBase()})
        for (int frame : {0, 1, 7, 119, 1000}) {
            const CameraSpec camera = cameraOnPath(base, CameraPath::fixed, frame, kBounds);
            expectSameCamera(camera, base, 0.0);
        }
}

TEST(CameraPathOrbit, FrameZeroIsTheBase) {
    expectSameCamera(cameraOnPath(perspectiveBase(), CameraPath::orbit, 0, kBounds),
                     perspectiveBase(), 1e-15);
    expectSameCamera(cameraOnPath(orthographicBase(), CameraPath::orbit, 0, kBounds),
                     orthographicBase(), 1e-15);
}

TEST(CameraPathOrbit, TurnsThreeDegreesPerFrameKeepingDistanceAndHeight) {
    const Vec3 centre = kBounds.centre();
    const CameraSpec base = perspectiveBase();
    const Vec3 base_offset = base.eye - centre;
    const Vec3 base_view = base.target - base.eye;
    double first_sign = 0;
    for (int frame = 1; frame <= 119; ++frame) {
        const CameraSpec camera = cameraOnPath(base, CameraPath::orbit, frame, kBounds);
        const std::string where = "frame " + std::to_string(frame);
        EXPECT_EQ(validateCamera(camera).error, "") << where;
        const Vec3 offset = camera.eye - centre;
        EXPECT_NEAR(length(offset), length(base_offset), 1e-12) << where;
        EXPECT_NEAR(camera.eye.y, base.eye.y, 1e-12) << where;
        EXPECT_NEAR(length(horizontal(offset)), length(horizontal(base_offset)), 1e-12) << where;
        // The turn about the vertical axis, from the base and from the previous frame.
        const double turn = signedTurnDegrees(horizontal(base_offset), horizontal(offset));
        if (frame == 1)
            first_sign = turn > 0 ? 1 : -1;
        const double expected = first_sign * 3.0 * frame;
        EXPECT_NEAR(angleDifference(turn, expected), 0.0, 1e-9) << where;
        const CameraSpec previous = cameraOnPath(base, CameraPath::orbit, frame - 1, kBounds);
        EXPECT_NEAR(angleDegrees(horizontal(previous.eye - centre), horizontal(offset)), 3.0, 1e-9)
            << where;
        // The target turns with the eye: the view direction turns by the same angle and keeps
        // its elevation, so the scene is seen the same way from every frame.
        const Vec3 view = camera.target - camera.eye;
        EXPECT_NEAR(length(view), length(base_view), 1e-12) << where;
        EXPECT_NEAR(view.y, base_view.y, 1e-12) << where;
        EXPECT_NEAR(
            angleDifference(signedTurnDegrees(horizontal(base_view), horizontal(view)), expected),
            0.0, 1e-9)
            << where;
        EXPECT_NEAR(camera.target.y, base.target.y, 1e-12) << where;
        // Everything else is kept.
        EXPECT_EQ(camera.fov_degrees, base.fov_degrees);
        EXPECT_EQ(camera.projection, base.projection);
    }
    // A quarter turn by hand: 30 frames = 90 degrees, so the horizontal offset (6, 0, -3) of the
    // eye from the centre becomes perpendicular to itself.
    const CameraSpec quarter = cameraOnPath(base, CameraPath::orbit, 30, kBounds);
    EXPECT_NEAR(dot(horizontal(quarter.eye - centre), horizontal(base_offset)), 0.0, 1e-12);
    // 120 frames = 360 degrees: back to the start.
    expectSameCamera(cameraOnPath(base, CameraPath::orbit, 120, kBounds), base, 1e-12);
    expectSameCamera(cameraOnPath(base, CameraPath::orbit, 240, kBounds), base, 1e-12);
}

TEST(CameraPathOrbit, OrthographicDirectionTurns) {
    const CameraSpec base = orthographicBase();
    for (int frame = 1; frame <= 120; ++frame) {
        const CameraSpec camera = cameraOnPath(base, CameraPath::orbit, frame, kBounds);
        const std::string where = "frame " + std::to_string(frame);
        EXPECT_EQ(camera.projection, Projection::orthographic);
        EXPECT_EQ(validateCamera(camera).error, "") << where;
        const Vec3 dir = camera.ortho_direction;
        EXPECT_NEAR(dir.y, base.ortho_direction.y, 1e-12) << where;
        EXPECT_NEAR(length(dir), length(base.ortho_direction), 1e-12) << where;
        double expected = 3.0 * frame;
        if (expected > 180)
            expected = 360 - expected;
        EXPECT_NEAR(angleDegrees(horizontal(base.ortho_direction), horizontal(dir)), expected, 1e-5)
            << where;
    }
    expectSameCamera(cameraOnPath(base, CameraPath::orbit, 120, kBounds), base, 1e-12);
}

TEST(CameraPathFlythrough, StaysInsideAndLooksAhead) {
    const Vec3 centre = kBounds.centre();
    const double r = kBounds.radius();
    const CameraSpec base = perspectiveBase();
    for (int frame = 0; frame <= 200; ++frame) {
        const CameraSpec camera = cameraOnPath(base, CameraPath::flythrough, frame, kBounds);
        const CameraSpec next = cameraOnPath(base, CameraPath::flythrough, frame + 1, kBounds);
        const std::string where = "frame " + std::to_string(frame);
        EXPECT_EQ(validateCamera(camera).error, "") << where;
        EXPECT_EQ(camera.projection, Projection::perspective);
        EXPECT_EQ(camera.fov_degrees, base.fov_degrees);
        // On a horizontal circle of radius 0.6 r about the centre: inside the bounding sphere.
        const Vec3 offset = camera.eye - centre;
        EXPECT_NEAR(offset.y, 0.0, 1e-12) << where;
        EXPECT_NEAR(length(offset), 0.6 * r, 1e-12) << where;
        EXPECT_LT(length(offset), r);
        // 2 degrees per frame.
        EXPECT_NEAR(angleDegrees(offset, next.eye - centre), 2.0, 1e-9) << where;
        // Looking (roughly) along the direction of travel, horizontally.
        const Vec3 travel = next.eye - camera.eye;
        const Vec3 view = camera.target - camera.eye;
        EXPECT_NEAR(view.y, 0.0, 1e-12) << where;
        EXPECT_LT(angleDegrees(travel, view), 10.0) << where;
        // A usable frame: the eye is inside, so near is the small r * 1e-3 * 0.99.
        const ViewProjection vp = frameCamera(camera, kBounds, 16, 12);
        EXPECT_NEAR(vp.near, r * 1e-3 * 0.99, 1e-12) << where;
        EXPECT_GT(vp.depthOf(camera.target), 0.0) << where;
    }
}

TEST(CameraPathFlythrough, DegenerateBoundsStillGiveValidCameras) {
    const Bounds point = boxBounds({1, 2, 3}, {1, 2, 3});
    for (int frame : {0, 1, 45, 180}) {
        const CameraSpec camera =
            cameraOnPath(perspectiveBase(), CameraPath::flythrough, frame, point);
        EXPECT_EQ(validateCamera(camera).error, "") << frame;
        // With radius 0 the path uses radius 1: the circle has radius 0.6.
        EXPECT_NEAR(length(camera.eye - point.centre()), 0.6, 1e-12) << frame;
    }
}

TEST(CameraPathBounds, FixtureBoundsAreAsIntended) {
    // Centre (1, 1, 2); diagonal (3, 4, 0) of length 5.
    expectSameVec(kBounds.centre(), {1, 1, 2}, 0.0, "centre");
    EXPECT_DOUBLE_EQ(kBounds.radius(), 2.5);
}

} // namespace
} // namespace vissort

namespace vissort {
namespace {

// A tilted up vector turns with the eye, so no frame's up becomes parallel to its view.
TEST(CameraPathOrbit, TiltedUpStaysValidAllTheWayRound) {
    Bounds bounds;
    bounds.add({-1, -1, -1});
    bounds.add({1, 1, 1});
    CameraSpec base;
    base.eye = {0, 0, 5};
    base.target = {0, 0, 0};
    base.up = {1, 0, 0};
    for (int frame = 0; frame <= 120; ++frame) {
        const CameraSpec camera = cameraOnPath(base, CameraPath::orbit, frame, bounds);
        EXPECT_EQ(validateCamera(camera).error, "") << "frame " << frame;
        // up stays perpendicular to the view direction, as in the base camera.
        EXPECT_NEAR(dot(camera.target - camera.eye, camera.up), 0.0, 1e-9);
    }
}

CameraSpec lookingFrom(const Vec3& eye, const Vec3& target, double fov) {
    CameraSpec camera;
    camera.eye = eye;
    camera.target = target;
    camera.fov_degrees = fov;
    return camera;
}

// Key frames at 0, 1 and 3 s: before the first the first, after the last the last, between two
// the straight-line mix by time (worked out by hand), at a key the key itself.
TEST(CameraPathScene, InterpolatesKeyFramesLinearlyByTime) {
    const std::vector<CameraKey> keys = {
        {0.0, lookingFrom({0, 1, 10}, {0, 1, 0}, 40)},
        {1.0, lookingFrom({4, 1, 10}, {0, 1, -4}, 60)},
        {3.0, lookingFrom({4, 5, 2}, {0, 1, -4}, 60)},
    };
    expectSameCamera(cameraAtTime(keys, -1.0), keys[0].camera, 0.0);
    expectSameCamera(cameraAtTime(keys, 0.0), keys[0].camera, 0.0);
    expectSameCamera(cameraAtTime(keys, 1.0), keys[1].camera, 0.0);
    expectSameCamera(cameraAtTime(keys, 9.0), keys[2].camera, 0.0);
    expectSameCamera(cameraAtTime(keys, 0.25), lookingFrom({1, 1, 10}, {0, 1, -1}, 45), 1e-12);
    expectSameCamera(cameraAtTime(keys, 2.5), lookingFrom({4, 4, 4}, {0, 1, -4}, 60), 1e-12);
    // Along a path: frame f at f / 30 s; with no keys the base camera stays.
    expectSameCamera(cameraOnPath(perspectiveBase(), CameraPath::scene, 15, kBounds, keys),
                     lookingFrom({2, 1, 10}, {0, 1, -2}, 50), 1e-12);
    expectSameCamera(cameraOnPath(perspectiveBase(), CameraPath::scene, 15, kBounds),
                     perspectiveBase(), 0.0);
}

} // namespace
} // namespace vissort
