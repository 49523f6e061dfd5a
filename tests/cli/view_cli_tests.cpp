// `vissort view` end to end, in a real window under Xvfb (xvfb-run, Debian's xvfb): the
// screenshot equals `vissort render` with the same camera and size; a scripted orbit moves the
// camera as documented (checked by rendering the camera it reports); method switches change the
// picture to that method's; a resized window renders the new size correctly; no display and a
// bad script are one-line errors.

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "cli_fixture.h"
#include "png_reading.h"

namespace vissort {
namespace {

// A server per run (-a), large enough for every window here, with 24-bit colour.
const std::string kXvfb = "xvfb-run -a -s '-screen 0 1280x1024x24'";

// The largest colour channel difference; -1 when the sizes differ.
int maxDifference(const Png& a, const Png& b) {
    if (a.width != b.width || a.height != b.height)
        return -1;
    int worst = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        if (i % 4 != 3)
            worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
    return worst;
}

class View : public Cli {
protected:
    void SetUp() override {
        Cli::SetUp();
        ASSERT_EQ(std::system("command -v xvfb-run >/dev/null"), 0)
            << "the viewer's tests need xvfb-run (Debian's xvfb, scripts/install-deps.sh)";
    }
    // `view` under Xvfb, --hide-ui, a screenshot of the last of `frames` frames.
    RunResult view(std::vector<std::string> args, int frames, const std::string& screenshot) {
        args.insert(args.begin(), "view");
        for (std::string a : {std::string("--hide-ui"), std::string("--frames"),
                              std::to_string(frames), std::string("--screenshot"), screenshot})
            args.push_back(a);
        return run(args, 120, kXvfb);
    }
    // `render` of the same frames; the last frame's picture.
    Png render(std::vector<std::string> args, int frames) {
        args.insert(args.begin(), "render");
        const std::string output = frames > 1 ? "render_%d.png" : "render.png";
        for (std::string a :
             {std::string("--frames"), std::to_string(frames), std::string("-o"), path(output)})
            args.push_back(a);
        const RunResult r = run(args, 120);
        EXPECT_EQ(r.code, 0) << r;
        return readPng(path(frames > 1 ? "render_" + std::to_string(frames - 1) + ".png" : output));
    }
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

TEST_F(View, ScreenshotEqualsRenderOfTheSameFrame) {
    // Moving bunnies, two frames: the second frame's time and camera.
    const RunResult r = view({"builtin:bunnies?n=6", "--size", "256x192"}, 2, path("view.png"));
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("2 frames at 256x192"), std::string::npos) << r;
    const Png shown = readPng(path("view.png"));
    EXPECT_EQ(maxDifference(shown, render({"builtin:bunnies?n=6", "--size", "256x192"}, 2)), 0);
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
    const std::vector<std::string> before = cameraOptions(start.out), after = cameraOptions(r.out);
    ASSERT_EQ(after.size(), 8u) << r;
    ASSERT_EQ(before.size(), 8u) << start;
    const auto vec = [](const std::string& text) {
        std::array<double, 3> v{};
        std::sscanf(text.c_str(), "%lf,%lf,%lf", &v[0], &v[1], &v[2]);
        return v;
    };
    const auto e0 = vec(before[1]), t0 = vec(before[3]), e1 = vec(after[1]), t1 = vec(after[3]);
    const auto offset = [](std::array<double, 3> e, std::array<double, 3> t) {
        return std::array<double, 3>{e[0] - t[0], e[1] - t[1], e[2] - t[2]};
    };
    const auto o0 = offset(e0, t0), o1 = offset(e1, t1);
    const double d0 = std::hypot(o0[0], o0[1], o0[2]), d1 = std::hypot(o1[0], o1[1], o1[2]);
    EXPECT_NEAR(d1, d0, 1e-6 * d0);
    EXPECT_EQ(t0, t1);
    const double yaw0 = std::atan2(o0[0], o0[2]), yaw1 = std::atan2(o1[0], o1[2]);
    EXPECT_NEAR(std::remainder(yaw1 - yaw0, 2 * M_PI), -0.5, 1e-6);
    EXPECT_NEAR(std::asin(o1[1] / d1) - std::asin(o0[1] / d0), 0.3, 1e-6);
    // And the window shows what render draws from that camera.
    std::vector<std::string> args{scene, "--size", "200x160"};
    args.insert(args.end(), after.begin(), after.end());
    EXPECT_LE(maxDifference(readPng(path("orbit.png")), render(args, 1)), 1);
    EXPECT_GT(maxDifference(readPng(path("orbit.png")), readPng(path("start.png"))), 1);
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
    expectError({"view", "builtin:bunnies", "--screenshot", path("x.png")}, kUsage,
                {"--screenshot", "--frames"});
}

} // namespace
} // namespace vissort
