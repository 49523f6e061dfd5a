// Multi-frame runs, every frame's order checked against that frame's own exact ground truth
// (every_frame_check.h), with every oracle at every level, each orderer coherent across the
// frames (it starts each frame from its last order): the power plant's walkthrough (its own
// key-framed camera path) and an orbit around it, the deforming bunnies from a moving camera and
// from the camera of issue 32, the plant, an animated scene of moving objects, and random
// interpenetrating triangles (cycles at every level) orbited. Small images: the ground truth
// decides every triangle at every pixel centre exactly. The full walkthrough (900 frames) and
// larger images run with `scripts/check-every-frame.sh`, outside the test suite.
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "every_frame_check.h"
#include "test_scene_loading.h"
#include "vissort/camera_path.h"
#include "vissort/frame_driver.h"

namespace vissort {
namespace {

struct FrameRun {
    std::string name;
    std::string scene;
    CameraPath path;
    std::vector<int> frames; // in this order, one orderer per pair throughout
    uint32_t width, height;
    std::optional<CameraSpec> camera; // else the scene's (or the default one)
};

void PrintTo(const FrameRun& run, std::ostream* os) {
    *os << run.name;
}

// Random triangles of 0.3 to 0.9 a side in [-1, 1]^3, one object per `per_object` of them:
// they interpenetrate, so every level has cycles.
Scene interpenetratingSoup(uint32_t seed, uint32_t triangles, uint32_t per_object) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), leg(0.3, 0.9);
    Scene scene;
    scene.name = "interpenetrating soup";
    for (uint32_t t = 0; t < triangles; ++t) {
        const Vec3 a{unit(rng), unit(rng), unit(rng)};
        for (const Vec3& v : {a, a + Vec3{leg(rng), unit(rng) * 0.3, unit(rng) * 0.5},
                              a + Vec3{unit(rng) * 0.3, leg(rng), unit(rng) * 0.5}}) {
            scene.positions.x.push_back(float(v.x));
            scene.positions.y.push_back(float(v.y));
            scene.positions.z.push_back(float(v.z));
        }
        if (t % per_object == 0)
            scene.objects.push_back({"part " + std::to_string(t / per_object), {}, false, t, 0});
        ++scene.objects.back().triangle_count;
    }
    return scene;
}

class EveryFrame : public testing::TestWithParam<FrameRun> {};

TEST_P(EveryFrame, EveryOrderMatchesItsFramesGroundTruth) {
    const FrameRun& run = GetParam();
    const Scene scene =
        run.scene == "soup" ? interpenetratingSoup(7, 60, 3) : test::loadTestScene(run.scene);
    ASSERT_FALSE(scene.objects.empty());
    const CameraSpec camera =
        run.camera.value_or(scene.camera.value_or(defaultCamera(scene.positions.bounds())));
    FrameDriver driver(scene, camera, run.path, run.width, run.height);
    test::EveryFrameCheck check(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                test::everyOracleAndLevel());
    for (int frame : run.frames) {
        driver.seek(frame);
        check.checkFrame(driver.positions(), driver.view(),
                         run.name + " frame " + std::to_string(frame));
        if (HasFatalFailure())
            return;
    }
    std::printf("[ checked  ] %s: %s\n[ ordering ] %s\n", run.name.c_str(),
                check.tally().describe().c_str(), check.timings().c_str());
    EXPECT_GT(check.tally().pairs_checked, 0u) << "no occlusion seen: the run proves nothing";
    // Every run has consecutive frames: where they have cycles, some must have been confirmed
    // from the last frame's, or the orders above never went through the hints.
    if (check.tally().true_cycles > 0)
        EXPECT_GT(check.tally().hinted_cycles, 0u);
}

CameraSpec issueCamera() {
    CameraSpec camera;
    camera.eye = {6, 4.5, 10.5};
    camera.target = {0, 0, 0};
    camera.up = {0, 1, 0};
    camera.fov_degrees = 45;
    return camera;
}

const FrameRun kRuns[] = {
    // The walkthrough: three consecutive frames at its start, then on along it (each frame
    // ordered from the last one's order however far the camera moved).
    {"powerplant_walkthrough",
     "builtin:powerplant?scale=0.05",
     CameraPath::scene,
     {0, 1, 2, 150, 300, 301, 450, 600, 750, 899},
     64,
     48,
     std::nullopt},
    {"powerplant_orbit",
     "builtin:powerplant?scale=0.05",
     CameraPath::orbit,
     {0, 1, 2, 3},
     64,
     48,
     std::nullopt},
    {"bunnies_orbit",
     "builtin:bunnies?n=6&seed=3",
     CameraPath::orbit,
     {0, 1, 2, 3, 4, 5},
     64,
     64,
     std::nullopt},
    {"bunnies_issue_camera",
     "builtin:bunnies?n=6",
     CameraPath::fixed,
     {0, 1, 2, 3, 4, 5},
     64,
     64,
     issueCamera()},
    {"plant_orbit",
     "builtin:plant?layers=2",
     CameraPath::orbit,
     {0, 1, 2, 3},
     80,
     60,
     std::nullopt},
    // The box slides past the spinning head, in front of it from about frame 80.
    {"animated",
     "tests/data/scenes/animated.json",
     CameraPath::fixed,
     {70, 80, 90, 91, 100, 110},
     64,
     48,
     std::nullopt},
    {"interpenetrating_soup_orbit",
     "soup",
     CameraPath::orbit,
     {0, 1, 2, 3, 4, 5},
     64,
     64,
     std::nullopt},
};

INSTANTIATE_TEST_SUITE_P(Runs, EveryFrame, testing::ValuesIn(kRuns),
                         [](const testing::TestParamInfo<FrameRun>& info) {
                             return info.param.name;
                         });

} // namespace
} // namespace vissort
