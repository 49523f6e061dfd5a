// `vissort view` end to end, in a real window under Xvfb (xvfb-run, Debian's xvfb): the
// screenshot equals `vissort render` with the same camera and size; a scripted orbit moves the
// camera as documented (checked by rendering the camera it reports); method switches change the
// picture to that method's; cycles, collisions and the error map are render's pictures with the
// same options; a resized window renders the new size correctly; no display and a
// bad script are one-line errors.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "png_reading.h"
#include "view_fixture.h"
#include "vissort/geometry.h"
#include "vissort/image.h"

namespace vissort {
namespace {

// The eye and target of the camera line view prints.
struct Reported {
    Vec3 eye, target;
    double distance() const { return length(eye - target); }
    Vec3 direction() const { return normalized(target - eye); }
};

// The camera line view prints: "camera: eye X,Y,Z target X,Y,Z up X,Y,Z fov F".
std::vector<std::string> cameraOptions(const std::string& out) {
    const std::size_t at = out.find("camera: eye ");
    if (at == std::string::npos)
        return {};
    std::istringstream in(out.substr(at + 8));
    std::string word, eye, target, up, fov;
    in >> word >> eye >> word >> target >> word >> up >> word >> fov;
    return {"--eye", eye, "--target", target, "--up", up, "--fov", fov};
}

Reported reportedCamera(const RunResult& r) {
    const std::vector<std::string> options = cameraOptions(r.out);
    Reported camera;
    EXPECT_EQ(options.size(), 8u) << r;
    if (options.size() != 8u)
        return camera;
    const auto vec = [](const std::string& text) {
        Vec3 v;
        std::sscanf(text.c_str(), "%lf,%lf,%lf", &v.x, &v.y, &v.z);
        return v;
    };
    camera.eye = vec(options[1]);
    camera.target = vec(options[3]);
    return camera;
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST_F(View, ScreenshotEqualsRenderOfTheSameFrame) {
    // Moving bunnies, two frames: the second frame's time and camera.
    const RunResult r = view({"builtin:bunnies?n=6", "--size", "256x192"}, 2, path("view.png"));
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("2 frames at 256x192"), std::string::npos) << r;
    const Png shown = readPng(path("view.png"));
    EXPECT_EQ(maxDifference(shown, render({"builtin:bunnies?n=6", "--size", "256x192"}, 2)), 0);
}

// Levels of detail in the window: the levels chosen by render for the same frames.
TEST_F(View, LevelsOfDetailShowWhatRenderDraws) {
    const std::vector<std::string> args = {"builtin:powerplant?scale=0.05",
                                           "--path",
                                           "scene",
                                           "--size",
                                           "200x150",
                                           "--lod-error",
                                           "3"};
    const RunResult r = view(args, 2, path("lod.png"));
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_EQ(maxDifference(readPng(path("lod.png")), render(args, 2)), 0);
    std::vector<std::string> full = args;
    full.back() = "0";
    EXPECT_GT(maxDifference(readPng(path("lod.png")), render(full, 2)), 0)
        << "3 pixels of error should show somewhere";
}

// With its panel, the window draws the scene right of it (panel_layout.h: 240 of 800 pixels
// at 800x600), framed for that part: the screenshot's right 560 columns are render's picture at
// 560x600; Tab (scripted) hides the panel and the scene takes the whole window.
TEST_F(View, ThePanelLeavesTheSceneItsOwnPartOfTheWindow) {
    const RunResult r = run({"view", "builtin:bunnies?n=2", "--size", "800x600", "--frames", "1",
                             "--screenshot", path("panel.png")},
                            120, kXvfb);
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("1 frame at 560x600"), std::string::npos) << r;
    const Png shown = readPng(path("panel.png"));
    const Png rendered = render({"builtin:bunnies?n=2", "--size", "560x600"}, 1);
    ASSERT_EQ(shown.width, 800);
    ASSERT_EQ(rendered.width, 560);
    Png right = rendered;
    for (int y = 0; y < shown.height; ++y)
        std::copy_n(&shown.rgba[(std::size_t(y) * 800 + 240) * 4], 560 * 4,
                    &right.rgba[std::size_t(y) * 560 * 4]);
    EXPECT_EQ(maxDifference(right, rendered), 0);

    std::ofstream(path("tab.txt")) << "0 key TAB\n";
    const RunResult hidden =
        run({"view", "builtin:bunnies?n=2", "--size", "800x600", "--frames", "1", "--script",
             path("tab.txt"), "--screenshot", path("hidden.png")},
            120, kXvfb);
    ASSERT_EQ(hidden.code, 0) << hidden;
    EXPECT_NE(hidden.out.find("1 frame at 800x600"), std::string::npos) << hidden;
}

// The renderer's options reach the window: membrane shading at 4 samples a pixel.
TEST_F(View, SamplesAndMembraneShadingReachTheWindow) {
    const std::vector<std::string> options = {
        "builtin:bunnies?n=6", "--size", "128x96", "--shading", "membrane", "--samples", "4"};
    const RunResult r = view(options, 1, path("view.png"));
    ASSERT_EQ(r.code, 0) << r;
    const Png shown = readPng(path("view.png"));
    EXPECT_EQ(maxDifference(shown, render(options, 1)), 0);
    EXPECT_GT(maxDifference(shown, render({"builtin:bunnies?n=6", "--size", "128x96"}, 1)), 1);
}

TEST_F(View, ScriptedOrbitMovesTheCameraAsDocumented) {
    const std::string scene = "builtin:plant?layers=3";
    std::ofstream(path("orbit.txt")) << "0 drag left 100 80 150 80  # 50 px right: -0.5 rad\n"
                                        "1 drag left 10 10 10 40    # 30 px down: 0.3 rad up\n";
    const RunResult start = view({scene, "--size", "200x160"}, 1, path("start.png"));
    ASSERT_EQ(start.code, 0) << start;
    const RunResult r =
        view({scene, "--size", "200x160", "--script", path("orbit.txt")}, 2, path("orbit.png"));
    ASSERT_EQ(r.code, 0) << r;
    // The eye turned about the target: same distance, about up by -0.5 rad, then 0.3 rad up.
    const Reported before = reportedCamera(start), after = reportedCamera(r);
    const Vec3 o0 = before.eye - before.target, o1 = after.eye - after.target;
    EXPECT_NEAR(length(o1), length(o0), 1e-6 * length(o0));
    EXPECT_EQ(after.target, before.target);
    const double yaw0 = std::atan2(o0.x, o0.z), yaw1 = std::atan2(o1.x, o1.z);
    EXPECT_NEAR(std::remainder(yaw1 - yaw0, 2 * M_PI), -0.5, 1e-6);
    EXPECT_NEAR(std::asin(o1.y / length(o1)) - std::asin(o0.y / length(o0)), 0.3, 1e-6);
    // And the window shows what render draws from that camera.
    std::vector<std::string> args{scene, "--size", "200x160"};
    const std::vector<std::string> camera = cameraOptions(r.out);
    args.insert(args.end(), camera.begin(), camera.end());
    EXPECT_LE(maxDifference(readPng(path("orbit.png")), render(args, 1)), 1);
    EXPECT_GT(maxDifference(readPng(path("orbit.png")), readPng(path("start.png"))), 1);
}

// The other controls through the window, each against docs/viewer.md's geometry: the wheel,
// flying, panning, framing, reset; Space pauses; P saves what the window shows.
TEST_F(View, ScriptedControlsMoveTheCameraAsDocumented) {
    const std::string scene = "builtin:plant?layers=3";
    const json info = [&] {
        const RunResult r = run({"info", scene, "--json", path("info.json")});
        EXPECT_EQ(r.code, 0) << r;
        return json::parse(readFile(path("info.json")));
    }();
    const auto corner = [&](const char* key) {
        const json& c = info["bounds"][key];
        return Vec3{c[0].get<double>(), c[1].get<double>(), c[2].get<double>()};
    };
    const Vec3 centre = (corner("min") + corner("max")) * 0.5;
    const double radius = length(corner("max") - corner("min")) * 0.5;
    const auto scripted = [&](const std::string& name, const std::string& script) {
        std::ofstream(path(name + ".txt")) << script;
        const RunResult r = view({scene, "--size", "200x160", "--script", path(name + ".txt")}, 1,
                                 path(name + ".png"));
        EXPECT_EQ(r.code, 0) << r;
        return reportedCamera(r);
    };
    const Reported start = scripted("start", "");
    const double d = start.distance(), tolerance = 1e-6 * d;
    // Two wheel steps: 0.9 x 0.9 of the distance, the target kept.
    const Reported zoomed = scripted("zoom", "0 wheel 2\n");
    EXPECT_NEAR(zoomed.distance(), 0.81 * d, tolerance);
    expectNear(zoomed.target, start.target, tolerance);
    // W: eye and target 5% of the scene's radius along the view.
    const Reported flown = scripted("fly", "0 key W\n");
    expectNear(flown.target, start.target + start.direction() * (0.05 * radius), tolerance);
    expectNear(flown.eye - flown.target, start.eye - start.target, tolerance);
    // A right drag of 40 pixels: across the view by 40 pixels' worth at the target's distance
    // (45 degrees over 160 pixels).
    const Reported panned = scripted("pan", "0 drag right 0 0 40 0\n");
    const Vec3 moved = panned.target - start.target;
    EXPECT_NEAR(length(moved), 40 * 2 * d * std::tan(22.5 * M_PI / 180) / 160, tolerance);
    EXPECT_NEAR(dot(moved, start.direction()), 0, tolerance);
    expectNear(panned.eye - panned.target, start.eye - start.target, tolerance);
    // R after several moves: the start camera again.
    const Reported reset = scripted("reset", "0 wheel 3\n0 key D\n0 drag left 0 0 25 9\n0 key R\n");
    expectNear(reset.eye, start.eye, tolerance);
    expectNear(reset.target, start.target, tolerance);
    // F after an orbit: the scene's centre, its sphere filling the 45-degree view.
    const Reported framed = scripted("frame", "0 drag left 0 0 30 0\n0 key F\n");
    expectNear(framed.target, centre, tolerance);
    EXPECT_NEAR(framed.distance(), radius / std::sin(22.5 * M_PI / 180), tolerance);

    // Space at the start: three frames of the moving bunnies all show frame 0.
    const std::string bunnies = "builtin:bunnies?n=6";
    std::ofstream(path("pause.txt")) << "0 key SPACE\n";
    const RunResult paused =
        view({bunnies, "--size", "160x120", "--script", path("pause.txt")}, 3, path("paused.png"));
    ASSERT_EQ(paused.code, 0) << paused;
    EXPECT_EQ(maxDifference(readPng(path("paused.png")), render({bunnies, "--size", "160x120"}, 1)),
              0);
    // P before the second frame: the window as shown, the same picture as --screenshot's.
    std::ofstream(path("p.txt")) << "1 key P\n";
    const RunResult shot =
        view({bunnies, "--size", "160x120", "--script", path("p.txt")}, 2, path("last.png"));
    ASSERT_EQ(shot.code, 0) << shot;
    EXPECT_NE(shot.out.find("vissort-view-1.png: screenshot"), std::string::npos) << shot;
    EXPECT_EQ(maxDifference(readPng(path("vissort-view-1.png")), readPng(path("last.png"))), 0);
}

TEST_F(View, MethodAndLevelSwitchesChangeThePicture) {
    const std::string scene = "builtin:bunnies?n=8";
    std::ofstream(path("keys.txt")) << "0 key 2\n"; // unsorted
    const RunResult vissort = view({scene, "--size", "160x120"}, 1, path("vissort.png"));
    ASSERT_EQ(vissort.code, 0) << vissort;
    const RunResult r =
        view({scene, "--size", "160x120", "--script", path("keys.txt")}, 1, path("unsorted.png"));
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("unsorted"), std::string::npos) << r;
    const Png unsorted = readPng(path("unsorted.png"));
    EXPECT_GT(maxDifference(unsorted, readPng(path("vissort.png"))), 8);
    EXPECT_EQ(
        maxDifference(unsorted, render({scene, "--size", "160x120", "--method", "unsorted"}, 1)),
        0);
    // centroid at triangle level from the command line, as render draws it.
    const RunResult centroid =
        view({scene, "--size", "160x120", "--method", "centroid", "--level", "triangle"}, 1,
             path("centroid.png"));
    ASSERT_EQ(centroid.code, 0) << centroid;
    EXPECT_EQ(
        maxDifference(
            readPng(path("centroid.png")),
            render({scene, "--size", "160x120", "--method", "centroid", "--level", "triangle"}, 1)),
        0);
}

// The panel's "Show" items from the command line and from their keys: cycles coloured,
// colliding triangles highlighted and the error map against linked-list, each the picture
// `render` draws with the same option (--colour-cycles, --highlight-collisions, --reference
// linked-list --error-map).
TEST_F(View, CyclesCollisionsAndErrorMapAreRendersPictures) {
    const std::string sticks = dataPath("scenes/three_sticks_and_box.json");
    const RunResult cycles =
        view({sticks, "--size", "200x150", "--all-transparent", "--colour-cycles"}, 1,
             path("cycles.png"));
    ASSERT_EQ(cycles.code, 0) << cycles;
    const Png plain = render({sticks, "--size", "200x150", "--all-transparent"}, 1);
    const Png painted =
        render({sticks, "--size", "200x150", "--all-transparent", "--colour-cycles"}, 1);
    EXPECT_EQ(maxDifference(readPng(path("cycles.png")), painted), 0);
    EXPECT_GT(maxDifference(painted, plain), 8);

    const std::string crossing = dataPath("scenes/interpenetrating.json");
    std::ofstream(path("k.txt")) << "0 key K\n";
    const RunResult collisions =
        view({crossing, "--size", "200x150", "--script", path("k.txt")}, 1, path("k.png"));
    ASSERT_EQ(collisions.code, 0) << collisions;
    EXPECT_NE(collisions.out.find("collisions: "), std::string::npos) << collisions;
    EXPECT_EQ(collisions.out.find("collisions: 0 "), std::string::npos) << collisions;
    EXPECT_EQ(maxDifference(readPng(path("k.png")),
                            render({crossing, "--size", "200x150", "--highlight-collisions"}, 1)),
              0);

    // Unsorted bunnies differ from linked-list's: the map shows it, as render's does.
    const std::string bunnies = "builtin:bunnies?n=6";
    const RunResult errors =
        view({bunnies, "--size", "160x120", "--method", "unsorted", "--show-errors"}, 1,
             path("errors.png"));
    ASSERT_EQ(errors.code, 0) << errors;
    EXPECT_NE(errors.out.find("against linked-list: max abs "), std::string::npos) << errors;
    render({bunnies, "--size", "160x120", "--method", "unsorted", "--reference", "linked-list",
            "--error-map", path("map.png")},
           1);
    const Png map = readPng(path("map.png"));
    EXPECT_EQ(maxDifference(readPng(path("errors.png")), map), 0);
    // vissort, X pressed: the map of an exact picture (nothing over 1/255).
    std::ofstream(path("x.txt")) << "0 key X\n";
    const RunResult exact =
        view({bunnies, "--size", "160x120", "--script", path("x.txt")}, 1, path("exact.png"));
    ASSERT_EQ(exact.code, 0) << exact;
    EXPECT_NE(exact.out.find("0 pixels off by more than 1"), std::string::npos) << exact;
    EXPECT_GT(maxDifference(readPng(path("exact.png")), map), 8);
    render({bunnies, "--size", "160x120", "--reference", "linked-list", "--error-map",
            path("exact_map.png")},
           1);
    EXPECT_EQ(maxDifference(readPng(path("exact.png")), readPng(path("exact_map.png"))), 0);
}

TEST_F(View, AResizedWindowRendersTheNewSize) {
    const std::string scene = "builtin:plant?layers=3";
    std::ofstream(path("resize.txt")) << "1 resize 150 210\n";
    const RunResult r =
        view({scene, "--size", "200x160", "--script", path("resize.txt")}, 2, path("resized.png"));
    ASSERT_EQ(r.code, 0) << r;
    const Png resized = readPng(path("resized.png"));
    EXPECT_EQ(resized.width, 150);
    EXPECT_EQ(resized.height, 210);
    EXPECT_EQ(maxDifference(resized, render({scene, "--size", "150x210"}, 1)), 0);
}

TEST_F(View, NoDisplayIsOneLineError) {
    const RunResult r = run({"view", "builtin:bunnies"}, 60, "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_EQ(r.code, kFailure) << r;
    EXPECT_EQ(lines(r.err).size(), 1u) << r;
    EXPECT_NE(r.err.find("needs a display"), std::string::npos) << r;
    EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r;
    EXPECT_NE(r.err.find("vissort render"), std::string::npos) << r;
}

TEST_F(View, BadScriptsAndOptionsAreOneLineErrors) {
    std::ofstream(path("bad.txt")) << "0 key W\n2 jump\n";
    expectError({"view", "builtin:bunnies", "--script", path("bad.txt")}, kUsage,
                {"--script", "bad.txt", "line 2", "jump"});
    expectError({"view", "builtin:bunnies", "--script", path("missing.txt")}, kUsage,
                {"missing.txt"});
    expectError({"view", "builtin:bunnies", "--method", "magic"}, kUsage, {"--method", "magic"});
    expectError({"view", "builtin:bunnies", "--screenshot", path("x.bmp")}, kUsage,
                {"--screenshot", "x.bmp"});
}

// --screenshot without --frames takes its default one frame, as the help says; -q is accepted
// as by every other command and keeps standard output empty.
TEST_F(View, ScreenshotWithoutFramesAndQuiet) {
    const RunResult r = run({"view", "builtin:bunnies?n=2", "--size", "96x72", "--hide-ui",
                             "--screenshot", path("one.png"), "-q"},
                            120, kXvfb);
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_TRUE(r.out.empty()) << r;
    const Png shot = readPng(path("one.png"));
    EXPECT_EQ(shot.width, 96);
    EXPECT_EQ(shot.height, 72);
    EXPECT_EQ(maxDifference(shot, render({"builtin:bunnies?n=2", "--size", "96x72"}, 1)), 0);
}

} // namespace
} // namespace vissort
