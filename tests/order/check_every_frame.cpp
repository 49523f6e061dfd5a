// check_every_frame: the every-frame check of every_frame_tests.cpp on runs too long for the test
// suite (the power plant's whole walkthrough, large images): orders each frame of a scene's run
// with the oracles and levels asked, each orderer coherent across the frames, and checks every
// frame's order against that frame's exact ground truth (every_frame_check.h). One line per
// frame; exit status 1 on any failure. Used by scripts/check-every-frame.sh.
//
//   check_every_frame SCENE [--path static|orbit|flythrough|scene] [--frames FIRST:END[:STEP]]
//                     [--size WxH] [--oracles cpu,cpu-reference,exact,gl]
//                     [--levels object,triangle,multistage] [--eye X,Y,Z --target X,Y,Z]
//                     [--fov DEGREES]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "every_frame_check.h"
#include "scenes/scene_library.h"
#include "vissort/camera_path.h"
#include "vissort/frame_driver.h"
#include "vissort/scene.h"

namespace vissort {
namespace {

struct Settings {
    std::string scene;
    CameraPath path = CameraPath::fixed;
    int first = 0, end = 1, step = 1;
    uint32_t width = 160, height = 120;
    std::vector<OracleKind> oracles {
        OracleKind::cpu, OracleKind::cpu_reference, OracleKind::exact,
#if VISSORT_TEST_WITH_GL
            OracleKind::gl
#endif
    };
    std::vector<OrderLevel> levels{OrderLevel::object, OrderLevel::triangle,
                                   OrderLevel::multistage};
    std::optional<Vec3> eye, target;
    std::optional<double> fov;
};
Settings g_settings;

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');)
        parts.push_back(part);
    return parts;
}

// Fills g_settings from the arguments; a one-line message on a mistake.
std::string parse(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
        if (arg == "--path") {
            const Result<CameraPath> path = parseCameraPath(value());
            if (!path)
                return path.error;
            g_settings.path = *path.value;
        } else if (arg == "--frames") {
            const std::string range = value();
            if (std::sscanf(range.c_str(), "%d:%d:%d", &g_settings.first, &g_settings.end,
                            &g_settings.step) < 2 ||
                g_settings.first < 0 || g_settings.end <= g_settings.first || g_settings.step < 1)
                return "--frames wants FIRST:END[:STEP] with 0 <= FIRST < END, STEP >= 1";
        } else if (arg == "--size") {
            if (std::sscanf(value().c_str(), "%ux%u", &g_settings.width, &g_settings.height) != 2 ||
                g_settings.width == 0 || g_settings.height == 0 || g_settings.width > 8192 ||
                g_settings.height > 8192)
                return "--size wants WxH, each 1 to 8192";
        } else if (arg == "--oracles") {
            g_settings.oracles.clear();
            for (const std::string& name : split(value())) {
                const Result<OracleKind> kind = parseOracleKind(name);
                if (!kind)
                    return kind.error;
                g_settings.oracles.push_back(*kind.value);
            }
        } else if (arg == "--levels") {
            g_settings.levels.clear();
            for (const std::string& name : split(value())) {
                const Result<OrderLevel> level = parseOrderLevel(name);
                if (!level)
                    return level.error;
                g_settings.levels.push_back(*level.value);
            }
        } else if (arg == "--eye" || arg == "--target") {
            Vec3 v;
            if (std::sscanf(value().c_str(), "%lf,%lf,%lf", &v.x, &v.y, &v.z) != 3)
                return arg + " wants X,Y,Z";
            (arg == "--eye" ? g_settings.eye : g_settings.target) = v;
        } else if (arg == "--fov") {
            double degrees = 0;
            if (std::sscanf(value().c_str(), "%lf", &degrees) != 1 ||
                !(degrees > 0 && degrees < 180))
                return "--fov wants degrees between 0 and 180";
            g_settings.fov = degrees;
        } else if (arg.rfind("--", 0) == 0) {
            return "unknown option '" + arg + "'";
        } else {
            g_settings.scene = arg;
        }
    }
    return g_settings.scene.empty() ? "no scene given" : "";
}

TEST(CheckEveryFrame, EveryOrderMatchesItsFramesGroundTruth) {
    const Settings& s = g_settings;
    Result<Scene> loaded = samples::loadScene(s.scene);
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    CameraSpec camera =
        scene.camera.value_or(defaultCamera(scene.positions.bounds(), double(s.width) / s.height));
    camera.eye = s.eye.value_or(camera.eye);
    camera.target = s.target.value_or(camera.target);
    camera.fov_degrees = s.fov.value_or(camera.fov_degrees);
    FrameDriver driver(scene, camera, s.path, s.width, s.height);
    std::vector<test::OrderedPair> pairs;
    for (OracleKind oracle : s.oracles)
        for (OrderLevel level : s.levels)
            pairs.push_back({oracle, level});
    test::EveryFrameCheck check(scene.objectPrimitives(), uint32_t(scene.triangleCount()), pairs);
    const auto start = std::chrono::steady_clock::now();
    const int total = (s.end - s.first + s.step - 1) / s.step;
    int done = 0;
    for (int frame = s.first; frame < s.end; frame += s.step) {
        driver.seek(frame);
        check.checkFrame(driver.positions(), driver.view(), "frame " + std::to_string(frame));
        ++done;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("[%d/%d] frame %d: %llu occlusions checked so far, %llu out of order, %.0f s "
                    "(about %.0f s left)\n",
                    done, total, frame, (unsigned long long)check.tally().pairs_checked,
                    (unsigned long long)check.tally().violations, seconds,
                    seconds / done * (total - done));
        std::fflush(stdout);
    }
    std::printf("%s: %s\nordering: %s\n", s.scene.c_str(), check.tally().describe().c_str(),
                check.timings().c_str());
}

} // namespace
} // namespace vissort

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv); // takes its own --gtest_ flags
    if (const std::string problem = vissort::parse(argc, argv); !problem.empty()) {
        std::fprintf(stderr, "check_every_frame: %s\n", problem.c_str());
        return 2;
    }
    return RUN_ALL_TESTS();
}
