// chooseView (view_choice.h), the camera policy of the command line, the viewer and Python:
// what nothing asked gives (the file's camera, else the geometry framed: every corner checked
// in the image), where the orbit options put the eye (computed here from the angles), and the
// errors, named as each caller names its options.

#include "vissort/view_choice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "scenes/scene_library.h"

namespace vissort {
namespace {

Scene load(const std::string& specification) {
    const std::string path = specification.rfind("builtin:", 0) == 0
                                 ? specification
                                 : std::string(VISSORT_SOURCE_DIR) + "/" + specification;
    Result<Scene> loaded = samples::loadScene(path);
    EXPECT_TRUE(loaded) << specification << ": " << loaded.error;
    return loaded ? std::move(*loaded.value) : Scene{};
}

const char* kCameras = "tests/data/meshes/cameras.gltf"; // cameras 'front' and 'top'
const char* kNoCamera = "tests/data/meshes/groups.obj";  // an OBJ: no camera

std::string errorOf(const ViewDef& def, const Scene& scene) {
    const Result<ChosenView> chosen = chooseView(def, scene);
    EXPECT_FALSE(chosen) << "no error";
    return chosen.error;
}

void expectNear(Vec3 a, Vec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-9);
    EXPECT_NEAR(a.y, b.y, 1e-9);
    EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(ChooseView, NothingAskedIsTheFilesFirstCamera) {
    const Scene scene = load(kCameras);
    ASSERT_TRUE(scene.camera);
    const Result<ChosenView> chosen = chooseView({}, scene);
    ASSERT_TRUE(chosen) << chosen.error;
    expectNear(chosen.value->camera.eye, scene.camera->eye);
    expectNear(chosen.value->camera.target, scene.camera->target);
    EXPECT_EQ(chosen.value->source, "the file's camera 0 'front'");
}

TEST(ChooseView, NothingAskedOfASceneWithoutACameraFramesEveryCorner) {
    const Scene scene = load(kNoCamera);
    ASSERT_FALSE(scene.camera);
    ViewDef def;
    def.width = 64;
    def.height = 48;
    const Result<ChosenView> chosen = chooseView(def, scene);
    ASSERT_TRUE(chosen) << chosen.error;
    EXPECT_EQ(chosen.value->source, "framed to the geometry");
    const ViewProjection view =
        frameCamera(chosen.value->camera, scene.positions.bounds(), def.width, def.height);
    for (std::size_t i = 0; i < scene.positions.x.size(); ++i) {
        const auto c = view.toClip(scene.positions.corner(i));
        ASSERT_GT(c[3], 0.0) << "corner " << i << " behind the eye";
        EXPECT_LE(std::abs(c[0]), c[3]) << "corner " << i;
        EXPECT_LE(std::abs(c[1]), c[3]) << "corner " << i;
    }
}

// A dynamic scene is framed over the frames that will be run: two boxes approaching each other
// for 30 frames fill the picture (some corner beyond 80% of the half-width), every corner of
// every frame inside it. Framed over 300 frames (the old least), they covered under a tenth.
TEST(ChooseView, ADynamicSceneIsFramedOverTheFramesRun) {
    const Scene scene = load("tests/data/scenes/approaching.json");
    ASSERT_TRUE(scene.isDynamic());
    for (int frames : {1, 30}) {
        SCOPED_TRACE(frames);
        ViewDef def;
        def.width = 64;
        def.height = 48;
        def.frames = frames;
        const Result<ChosenView> chosen = chooseView(def, scene);
        ASSERT_TRUE(chosen) << chosen.error;
        const ViewProjection view =
            frameCamera(chosen.value->camera, scene.positions.bounds(), def.width, def.height);
        double widest = 0;
        TrianglePositions positions;
        for (int frame = 0; frame < frames; ++frame) {
            scene.frame(frame * kFrameInterval, positions);
            for (std::size_t i = 0; i < positions.x.size(); ++i) {
                const auto c = view.toClip(positions.view().corner(i));
                ASSERT_GT(c[3], 0.0);
                const double extent = std::max(std::abs(c[0]), std::abs(c[1])) / c[3];
                ASSERT_LE(extent, 1.0) << "frame " << frame << " corner " << i;
                widest = std::max(widest, extent);
            }
        }
        EXPECT_GT(widest, 0.8);
    }
}

TEST(ChooseView, AzimuthElevationAndDistancePlaceTheEyeAroundTheCentre) {
    const Scene scene = load(kNoCamera);
    const Vec3 centre = scene.positions.bounds().centre();
    ViewDef def;
    def.azimuth_degrees = 90; // looks along -x: the eye on +x
    def.elevation_degrees = 30;
    def.distance = 10;
    const Result<ChosenView> chosen = chooseView(def, scene);
    ASSERT_TRUE(chosen) << chosen.error;
    const double rad = 30 * std::acos(-1.0) / 180;
    expectNear(chosen.value->camera.eye, centre + Vec3{10 * std::cos(rad), 10 * std::sin(rad), 0});
    expectNear(chosen.value->camera.target, centre);
    EXPECT_EQ(chosen.value->source, "--azimuth/--elevation/--distance");
}

TEST(ChooseView, ConflictsAreNamedAsTheCallerNamesItsOptions) {
    const Scene scene = load(kNoCamera);
    ViewDef def;
    def.eye = Vec3{0, 0, 5};
    def.azimuth_degrees = 10;
    EXPECT_EQ(errorOf(def, scene),
              "--azimuth, --elevation and --distance place the eye around the scene's centre: "
              "they cannot be combined with --eye, --target, --up, --ortho-dir or --camera");
    def.names = OptionNames::python;
    EXPECT_EQ(errorOf(def, scene),
              "azimuth, elevation and distance place the eye around the scene's centre: "
              "they cannot be combined with eye, target, up, ortho_dir or camera");

    ViewDef ortho;
    ortho.names = OptionNames::python;
    ortho.ortho_direction = Vec3{0, 0, -1};
    ortho.fov_degrees = 30;
    EXPECT_EQ(errorOf(ortho, scene),
              "ortho_dir cannot be combined with eye, target, up or fov_deg");
    ortho.names = OptionNames::command_line;
    EXPECT_EQ(errorOf(ortho, scene), "--ortho-dir cannot be combined with --eye, --target, "
                                     "--up or --fov");
}

TEST(ChooseView, ValuesOutOfRangeAreRefused) {
    const Scene scene = load(kNoCamera);
    ViewDef def;
    def.frames = 0;
    EXPECT_EQ(errorOf(def, scene), "--frames must be between 1 and 100000");
    def.frames = kMaxFrames + 1;
    def.names = OptionNames::python;
    EXPECT_EQ(errorOf(def, scene), "frames must be between 1 and 100000");
    def = {};
    def.elevation_degrees = 91;
    EXPECT_EQ(errorOf(def, scene), "--elevation must be between -90 and 90 degrees");
    def = {};
    def.distance = -1;
    EXPECT_EQ(errorOf(def, scene), "--distance must be positive and below 1e30");
    def = {};
    def.eye = def.target = Vec3{1, 2, 3}; // the eye on its target
    EXPECT_NE(errorOf(def, scene).find("--eye/--target/--up/--fov: "), std::string::npos);
    def = {};
    def.path = CameraPath::scene;
    EXPECT_NE(errorOf(def, scene).find("--path scene: the scene has no camera path"),
              std::string::npos);
}

// "framed" sets the file's cameras aside; the file's camera used as stored is named, not one an
// option changed.
TEST(ChooseView, FramedAndTheStoredCameraUsed) {
    const Scene scene = load(kCameras);
    const Result<ChosenView> own = chooseView({}, scene);
    ASSERT_TRUE(own) << own.error;
    EXPECT_EQ(own.value->stored_camera, std::optional<std::size_t>(0));
    ViewDef def;
    def.fov_degrees = 60;
    EXPECT_FALSE(chooseView(def, scene).value->stored_camera); // changed by an option
    def = {};
    def.stored_camera = "framed";
    const Result<ChosenView> framed = chooseView(def, scene);
    ASSERT_TRUE(framed) << framed.error;
    EXPECT_EQ(framed.value->source, "framed to the geometry");
    EXPECT_FALSE(framed.value->stored_camera);
    def.azimuth_degrees = 45; // framed goes with the orbit options
    EXPECT_TRUE(chooseView(def, scene));
}

// The share of the surface in view, against the geometry worked out by hand: the glTF's quad
// [-1, 1]^2 at z = 0 seen from (0.5, 0, 3) with a vertical field of view of 0.6 radians in a
// square image shows x in [0.5 - h, 1] and y in [-h, h], h = 3 tan(0.3): 2.65 of its 4
// square units. A framed camera shows all of a scene, one looking away none.
TEST(ChooseView, ShareOfTheSurfaceInView) {
    const Scene scene = load(kCameras);
    ASSERT_TRUE(scene.camera);
    const double h = 3 * std::tan(0.6 / 2); // the file's yfov: 0.6 radians
    const double expected = (1 - (0.5 - h)) * (2 * h) / 4;
    EXPECT_NEAR(shareOfSurfaceInView(scene, *scene.camera, 1024, 1024), expected, 0.02);
    ViewDef def;
    def.stored_camera = "framed";
    EXPECT_DOUBLE_EQ(shareOfSurfaceInView(scene, chooseView(def, scene).value->camera, 1024, 1024),
                     1.0);
    const Scene other = load(kNoCamera);
    const Vec3 centre = other.positions.bounds().centre();
    CameraSpec backwards;
    backwards.eye = centre + Vec3{0, 0, 10};
    backwards.target = centre + Vec3{0, 0, 20}; // the scene behind the eye
    EXPECT_DOUBLE_EQ(shareOfSurfaceInView(other, backwards, 64, 48), 0.0);
}

TEST(ChooseView, StoredCamerasByNameOrIndexAndTheirNamesAsWritten) {
    const Scene scene = load(kCameras);
    ViewDef def;
    def.stored_camera = "1";
    const Result<ChosenView> top = chooseView(def, scene);
    ASSERT_TRUE(top) << top.error;
    EXPECT_EQ(top.value->source, "the file's camera 1 'top'");
    EXPECT_EQ(top.value->camera.projection, scene.cameras[1].camera.projection);
    // A name the file does not have is quoted as given, braces and all.
    def.stored_camera = "{eye}";
    const std::string error = errorOf(def, scene);
    EXPECT_EQ(error.rfind("--camera: ", 0), 0u) << error;
    EXPECT_NE(error.find("{eye}"), std::string::npos) << error;
    EXPECT_EQ(error.find("--eye"), std::string::npos) << error;
}

} // namespace
} // namespace vissort
