// The viewer's camera controls against their documented geometry (camera_controls.h), computed
// here from first principles, the input script's format (input_script.h) and the panel's
// layout (panel_layout.h), and the panel's transfer function editing (transfer_editing.h).

#include <gtest/gtest.h>

#include <cmath>

#include "viewer/camera_controls.h"
#include "viewer/input_script.h"
#include "viewer/panel_layout.h"
#include "viewer/transfer_editing.h"

namespace vissort::viewer {
namespace {

constexpr double kPi = 3.14159265358979323846;

CameraSpec startCamera() {
    CameraSpec camera;
    camera.eye = {0, 0, 10};
    camera.target = {0, 0, 0};
    camera.up = {0, 1, 0};
    camera.fov_degrees = 45;
    return camera;
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(CameraControls, OrbitTurnsAboutUpThenTowardsIt) {
    const CameraSpec start = startCamera();
    // 50 pixels right: -0.5 rad about +y, the eye from +z towards -x.
    const CameraSpec yawed = orbit(start, 50, 0);
    expectNear(yawed.eye, {10 * std::sin(-0.5), 0, 10 * std::cos(-0.5)});
    expectNear(yawed.target, start.target);
    // 30 pixels down: 0.3 rad up, at the same distance.
    const CameraSpec raised = orbit(start, 0, 30);
    expectNear(raised.eye, {0, 10 * std::sin(0.3), 10 * std::cos(0.3)});
    // Never over the pole: 10 rad up stops within 0.01 rad of it.
    const CameraSpec top = orbit(start, 0, 1000);
    EXPECT_NEAR(std::acos(top.eye.y / 10), 0.01, 1e-9);
    EXPECT_GT(top.eye.z, 0);
    // Orthographic: the direction turns the same way.
    CameraSpec ortho = start;
    ortho.projection = Projection::orthographic;
    ortho.ortho_direction = {0, 0, -1};
    expectNear(orbit(ortho, 50, 0).ortho_direction, {-std::sin(-0.5), 0, -std::cos(-0.5)});
}

TEST(CameraControls, PanMovesEyeAndTargetWithTheCursor) {
    const CameraSpec start = startCamera();
    // At distance 10 and 45 degrees over 500 pixels: 2 * 10 * tan(22.5 deg) / 500 a pixel.
    const double per_pixel = 2 * 10 * std::tan(22.5 * kPi / 180) / 500;
    const CameraSpec moved = pan(start, 100, 50, 500);
    // Right drags the scene right: the camera moves left (-x); down: the camera moves up.
    expectNear(moved.eye, {-100 * per_pixel, 50 * per_pixel, 10});
    expectNear(moved.target, {-100 * per_pixel, 50 * per_pixel, 0});
}

TEST(CameraControls, ZoomScalesTheDistanceAndStops) {
    const CameraSpec start = startCamera();
    expectNear(zoom(start, 2, 0.1).eye, {0, 0, 10 * 0.9 * 0.9});
    expectNear(zoom(start, -1, 0.1).eye, {0, 0, 10 / 0.9});
    expectNear(zoom(start, 500, 0.1).eye, {0, 0, 0.1});
}

TEST(CameraControls, FlyMovesAlongViewRightAndUp) {
    const CameraSpec start = startCamera();
    const CameraSpec moved = fly(start, 1, 2, -3, 0.5);
    expectNear(moved.eye, {1.0, -1.5, 9.5});
    expectNear(moved.target, {1.0, -1.5, -0.5});
}

TEST(CameraControls, FrameBoundsFitsTheSphereFromTheSameDirection) {
    Bounds bounds;
    bounds.add({1, 1, 1});
    bounds.add({3, 5, 2});
    const CameraSpec framed = frameBounds(orbit(startCamera(), 20, 10), bounds);
    expectNear(framed.target, bounds.centre());
    const double distance = length(framed.eye - framed.target);
    EXPECT_NEAR(distance * std::sin(22.5 * kPi / 180), bounds.radius(), 1e-9);
    expectNear(normalized(framed.eye - framed.target),
               normalized(orbit(startCamera(), 20, 10).eye));
}

TEST(InputScript, ParsesEveryEventSortedByFrame) {
    const auto events = parseInputScript("# a comment\n"
                                         "3 key w\n"
                                         "0 drag left 10 20 30 40   # orbit\n"
                                         "\n"
                                         "1 wheel -2.5\n"
                                         "1 resize 200 150\n"
                                         "0 key 7\n");
    ASSERT_TRUE(events) << events.error;
    ASSERT_EQ(events.value->size(), 5u);
    const auto& e = *events.value;
    EXPECT_EQ(e[0].kind, ScriptEvent::Kind::drag);
    EXPECT_EQ(e[0].button, 0);
    EXPECT_EQ(e[0].x1 - e[0].x0, 20);
    EXPECT_EQ(e[1].key, "7"); // file order within frame 0
    EXPECT_EQ(e[2].kind, ScriptEvent::Kind::wheel);
    EXPECT_EQ(e[2].steps, -2.5);
    EXPECT_EQ(e[3].width, 200u);
    EXPECT_EQ(e[4].key, "W");
    EXPECT_EQ(e[4].frame, 3);
}

TEST(InputScript, RejectsBadLinesNamingThem) {
    const std::pair<const char*, const char*> cases[] = {
        {"x key W", "line 1: the frame"},      {"0 key W\n-1 key W", "line 2: the frame"},
        {"0 key 8", "unknown key '8'"},        {"0 press W", "unknown event 'press'"},
        {"0 drag left 1 2 3", "four numbers"}, {"0 drag top 1 2 3 4", "button"},
        {"0 wheel nan", "wheel needs"},        {"0 resize 0 10", "resize needs"},
        {"0 key W W", "unexpected 'W'"},       {"0", "an event"},
    };
    for (const auto& [text, needle] : cases) {
        const auto events = parseInputScript(text);
        EXPECT_FALSE(events) << text;
        EXPECT_NE(events.error.find(needle), std::string::npos) << text << ": " << events.error;
    }
    EXPECT_FALSE(loadInputScript("/nonexistent/script.txt"));
}

// The panel never covers more than 30% of the window (a fixed 345 pixels covered 44% of an
// 800x600 one), grows with the window, and leaves the rest to the scene; hidden, the scene has it
// all.
TEST(PanelLayout, ASidebarScaledWithTheWindow) {
    const PanelLayout small = panelLayout(800, 600), usual = panelLayout(1024, 768),
                      large = panelLayout(1920, 1200), hidden = panelLayout(800, 600, false);
    EXPECT_EQ(small.width, 240u); // 30% of 800: 340 * 0.75 would be 255
    EXPECT_FLOAT_EQ(small.scale, 0.75f);
    EXPECT_FLOAT_EQ(usual.scale, 0.8f); // 1024 / 1280
    EXPECT_EQ(usual.width, 272u);       // 340 * 0.8
    EXPECT_FLOAT_EQ(large.scale, 1.5f);
    EXPECT_EQ(large.width, 510u);
    EXPECT_LE(large.width, 1920u * 3 / 10);
    EXPECT_EQ(hidden.width, 0u);
    EXPECT_FLOAT_EQ(hidden.scale, 0.75f);
    EXPECT_EQ(sceneWidth(800, 600, true), 560u);
    EXPECT_EQ(sceneWidth(800, 600, false), 800u);
    EXPECT_EQ(sceneWidth(1, 1, true), 1u); // never an empty image
}

// The frame-time plot says its scale: 0 to the largest frame and a tenth more (at least 1 ms),
// and the last frame's time.
TEST(PanelLayout, ThePlotSaysItsScale) {
    const float frames[] = {40.0f, 132.7f, 77.42f};
    const PlotScale scale = frameTimePlotScale(frames);
    EXPECT_FLOAT_EQ(scale.top, 132.7f * 1.1f);
    EXPECT_EQ(scale.caption, "0 to 146 ms; last 77.4 ms");
    const float fast[] = {0.2f, 0.3f};
    EXPECT_FLOAT_EQ(frameTimePlotScale(fast).top, 1.0f);
    EXPECT_EQ(frameTimePlotScale(fast).caption, "0 to 1 ms; last 0.3 ms");
}

TEST(InputScript, TabTogglesThePanel) {
    const Result<std::vector<ScriptEvent>> script = parseInputScript("2 key tab\n");
    ASSERT_TRUE(script) << script.error;
    ASSERT_EQ(script.value->size(), 1u);
    EXPECT_EQ((*script.value)[0].key, "TAB");
}

// Three points at 0, 0.5 and 1 (normalized).
TransferFunction threePoints() {
    TransferFunction tf;
    tf.points = {{0.0, 0.1, 0.2, 0.3, 1.0}, {0.5, 0.9, 0.8, 0.7, 2.0}, {1.0, 0.0, 1.0, 0.0, 4.0}};
    return tf;
}

TEST(TransferEditing, APointMovesOnlyBetweenItsNeighbours) {
    TransferFunction tf = threePoints();
    moveTransferPoint(tf, 1, 0.25);
    EXPECT_EQ(tf.points[1].scalar, 0.25);
    moveTransferPoint(tf, 1, 7.0); // past the last: held just inside it
    EXPECT_LT(tf.points[1].scalar, 1.0);
    EXPECT_GT(tf.points[1].scalar, 0.999999);
    moveTransferPoint(tf, 1, -3.0);
    EXPECT_GT(tf.points[1].scalar, 0.0);
    EXPECT_LT(tf.points[1].scalar, 1e-6);
    moveTransferPoint(tf, 0, -2.0); // the ends move freely outwards
    EXPECT_EQ(tf.points[0].scalar, -2.0);
    moveTransferPoint(tf, 2, std::nan(""));
    EXPECT_EQ(tf.points[2].scalar, 1.0);
    EXPECT_TRUE(validateTransferFunction(tf)) << validateTransferFunction(tf).error;
}

TEST(TransferEditing, AnInsertedPointLeavesTheFunctionAsItWas) {
    TransferFunction tf = threePoints();
    const TransferFunction before = tf;
    EXPECT_EQ(insertTransferPoint(tf, 0), 1u);
    ASSERT_EQ(tf.points.size(), 4u);
    EXPECT_EQ(tf.points[1].scalar, 0.25);
    EXPECT_EQ(insertTransferPoint(tf, 3), 4u); // after the last (at 1): beyond it
    EXPECT_GT(tf.points[4].scalar, 1.0);
    EXPECT_TRUE(validateTransferFunction(tf)) << validateTransferFunction(tf).error;
    for (double s = -0.5; s <= 1.5; s += 0.01) {
        const TransferPoint a = before.at(s), b = tf.at(s);
        EXPECT_NEAR(a.r, b.r, 1e-12) << s;
        EXPECT_NEAR(a.g, b.g, 1e-12) << s;
        EXPECT_NEAR(a.b, b.b, 1e-12) << s;
        EXPECT_NEAR(a.extinction, b.extinction, 1e-12) << s;
    }
}

TEST(TransferEditing, RemovingKeepsTwoPoints) {
    TransferFunction tf = threePoints();
    EXPECT_TRUE(removeTransferPoint(tf, 1));
    EXPECT_EQ(tf.points.size(), 2u);
    EXPECT_EQ(tf.points[1].scalar, 1.0);
    EXPECT_FALSE(removeTransferPoint(tf, 0));
    EXPECT_FALSE(removeTransferPoint(tf, 5));
    EXPECT_EQ(tf.points.size(), 2u);
}

TEST(TransferEditing, ClampingAndPresets) {
    TransferPoint p{0.5, 1.5, -0.2, std::nan(""), -3.0};
    clampTransferPoint(p);
    EXPECT_EQ(p.r, 1.0);
    EXPECT_EQ(p.g, 0.0);
    EXPECT_EQ(p.b, 0.0);
    EXPECT_EQ(p.extinction, 0.0);
    // T walks every preset once and comes back.
    const std::vector<TransferPreset> presets = transferPresets();
    std::string name = presets.front().name;
    for (std::size_t i = 1; i <= presets.size(); ++i) {
        name = nextTransferPreset(name);
        EXPECT_EQ(name, presets[i % presets.size()].name);
    }
    EXPECT_EQ(nextTransferPreset("my-tf.json"), presets.front().name);
}

TEST(InputScript, AcceptsTheGridKeys) {
    const Result<std::vector<ScriptEvent>> script = parseInputScript("0 key t\n1 key [\n1 key ]\n");
    ASSERT_TRUE(script) << script.error;
    ASSERT_EQ(script.value->size(), 3u);
    EXPECT_EQ((*script.value)[0].key, "T");
    EXPECT_EQ((*script.value)[1].key, "[");
    EXPECT_EQ((*script.value)[2].key, "]");
}

} // namespace
} // namespace vissort::viewer
