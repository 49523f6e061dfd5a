// `vissort view GRID` end to end under Xvfb: the window shows the volume renderer's picture (the
// screenshot equals `vissort volume` with the same camera and size, and is within 1/255 of the
// independent ray caster's); the keys change the method, the transfer function and the density
// to what `volume` draws with the same options; the error map is measured against raycast; a
// scene's options on a grid, and a grid's on a scene, are one-line errors.

#include <fstream>

#include "view_fixture.h"

namespace vissort {
namespace {

const std::string kGrid = "builtin:knot?n=10";

class ViewGrid : public View {
protected:
    // `volume` of kGrid's first frame at 160x120 with extra options.
    Png volume(std::vector<std::string> args) {
        const std::string output = path("volume.png");
        args.insert(args.begin(), {"volume", kGrid, "--size", "160x120", "-o", output});
        const RunResult r = run(args, 120);
        EXPECT_EQ(r.code, 0) << r;
        return readPng(output);
    }
    // The window on kGrid at 160x120 after the script's keys (none when empty).
    RunResult viewAfter(const std::string& keys, const std::string& shot,
                        std::vector<std::string> args = {}) {
        args.insert(args.begin(), {kGrid, "--size", "160x120"});
        if (!keys.empty()) {
            std::ofstream(path("keys.txt")) << keys;
            args.insert(args.end(), {"--script", path("keys.txt")});
        }
        return view(args, 1, path(shot));
    }
};

TEST_F(ViewGrid, ScreenshotIsTheVolumeRenderersPicture) {
    const RunResult r = viewAfter("", "vissort.png");
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("1 frame at 160x120, vissort, tf cool-warm, density 4"), std::string::npos)
        << r;
    const Png shown = readPng(path("vissort.png"));
    EXPECT_EQ(maxDifference(shown, volume({})), 0);
    EXPECT_LE(maxDifference(shown, volume({"--method", "raycast"})), 1);
}

TEST_F(ViewGrid, KeysChangeMethodTransferFunctionAndDensity) {
    const Png start = [&] {
        EXPECT_EQ(viewAfter("", "start.png").code, 0);
        return readPng(path("start.png"));
    }();
    // 2: centroid.
    ASSERT_EQ(viewAfter("0 key 2\n", "centroid.png").code, 0);
    EXPECT_EQ(maxDifference(readPng(path("centroid.png")), volume({"--method", "centroid"})), 0);
    // T: the preset after cool-warm.
    const RunResult fire = viewAfter("0 key T\n", "fire.png");
    ASSERT_EQ(fire.code, 0) << fire;
    EXPECT_NE(fire.out.find("tf fire"), std::string::npos) << fire;
    const Png fire_shot = readPng(path("fire.png"));
    EXPECT_GT(maxDifference(fire_shot, start), 8);
    EXPECT_EQ(maxDifference(fire_shot, volume({"--tf", "fire"})), 0);
    // ] ] [: density 4 * 1.5 = 6.
    const RunResult denser = viewAfter("0 key ]\n0 key ]\n0 key [\n", "denser.png");
    ASSERT_EQ(denser.code, 0) << denser;
    EXPECT_NE(denser.out.find("density 6"), std::string::npos) << denser;
    EXPECT_EQ(maxDifference(readPng(path("denser.png")), volume({"--density", "6"})), 0);
    // The command line's choices start the window.
    ASSERT_EQ(
        viewAfter("", "mpvo.png", {"--method", "mpvo", "--tf", "bands", "--density", "2"}).code, 0);
    EXPECT_EQ(maxDifference(readPng(path("mpvo.png")),
                            volume({"--method", "mpvo", "--tf", "bands", "--density", "2"})),
              0);
}

// A held ] (or [) stops at a density of 1e6 (1e-6), short of the infinity the renderer refuses.
TEST_F(ViewGrid, DensityKeysStopShortOfInfinity) {
    std::string keys;
    for (int i = 0; i < 2000; ++i)
        keys += "0 key ]\n";
    const RunResult r = viewAfter(keys, "dense.png");
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("density 1e+06"), std::string::npos) << r;
}

// X (and --show-errors): the map of `volume --reference raycast --error-map`, and the error
// reported against the ray caster: none for vissort.
TEST_F(ViewGrid, ErrorMapAgainstRaycast) {
    const RunResult r = viewAfter("0 key X\n", "errors.png");
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("against raycast: max abs 0/255"), std::string::npos) << r;
    const std::string map = path("map.png");
    volume({"--reference", "raycast", "--error-map", map});
    EXPECT_EQ(maxDifference(readPng(path("errors.png")), readPng(map)), 0);
}

TEST_F(ViewGrid, OptionsOfTheOtherKindAreOneLineErrors) {
    expectError({"view", kGrid, "--level", "triangle"}, kUsage, {"--level", "grid"});
    expectError({"view", kGrid, "--highlight-collisions"}, kUsage, {"--highlight-collisions"});
    expectError({"view", kGrid, "--method", "peel"}, kUsage, {"--method", "peel"});
    expectError({"view", kGrid, "--tf", "rainbow"}, kUsage, {"--tf", "rainbow"});
    expectError({"view", kGrid, "--density", "-1"}, kUsage, {"--density"});
    expectError({"view", "builtin:bunnies", "--tf", "fire"}, kUsage, {"--tf", "scene"});
    expectError({"view", "builtin:bunnies", "--density", "2"}, kUsage, {"--density", "scene"});
    // A grid that cannot be read: the loader's line (the display is checked first, as for
    // scenes, so this one runs under Xvfb).
    const RunResult missing = run({"view", path("missing.vtu")}, 60, kXvfb);
    EXPECT_EQ(missing.code, kInput) << missing;
    EXPECT_EQ(lines(missing.err).size(), 1u) << missing;
    EXPECT_NE(missing.err.find("missing.vtu"), std::string::npos) << missing;
}

} // namespace
} // namespace vissort
