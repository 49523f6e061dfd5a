// JSON scenes: the format (transforms, shapes, colours, cameras, animation), every rejection,
// and the fixture scenes the ordering tests rely on, checked by brute-force ray casting.

#include "scene/json_scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

namespace vissort {
namespace {

namespace fs = std::filesystem;
using detail::loadJsonScene;

const std::string kSource = VISSORT_SOURCE_DIR;
const std::string kScenes = kSource + "/tests/data/scenes/";
const std::string kMeshes = kSource + "/tests/data/meshes/";

class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("vissort_json_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() { fs::remove_all(path_); }
    std::string write(const std::string& name, const std::string& text) const {
        const fs::path file = path_ / name;
        fs::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file.string();
    }

private:
    fs::path path_;
};

// --- a brute-force ray caster (the independent reference) ---

/// Möller-Trumbore, both sides; the distance along the ray, if hit.
std::optional<double> hitTriangle(Vec3 origin, Vec3 direction, Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 e1 = b - a, e2 = c - a, p = cross(direction, e2);
    const double det = dot(e1, p);
    if (std::abs(det) < 1e-14)
        return std::nullopt;
    const Vec3 s = origin - a;
    const double u = dot(s, p) / det;
    if (u < 0 || u > 1)
        return std::nullopt;
    const Vec3 q = cross(s, e1);
    const double v = dot(direction, q) / det;
    if (v < 0 || u + v > 1)
        return std::nullopt;
    const double t = dot(e2, q) / det;
    return t > 0 ? std::optional<double>(t) : std::nullopt;
}

Bounds objectBounds(const Scene& scene, const SceneObject& object) {
    Bounds bounds;
    for (std::size_t c = object.first_triangle * 3u;
         c < (object.first_triangle + object.triangle_count) * 3u; ++c)
        bounds.add(scene.positions.corner(c));
    return bounds;
}

bool rayMissesBox(Vec3 origin, Vec3 direction, const Bounds& box) {
    double near = 0, far = 1e300;
    const double o[] = {origin.x, origin.y, origin.z},
                 d[] = {direction.x, direction.y, direction.z};
    const double lo[] = {box.min.x, box.min.y, box.min.z}, hi[] = {box.max.x, box.max.y, box.max.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(d[axis]) < 1e-300) {
            if (o[axis] < lo[axis] || o[axis] > hi[axis])
                return true;
            continue;
        }
        double t0 = (lo[axis] - o[axis]) / d[axis], t1 = (hi[axis] - o[axis]) / d[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        near = std::max(near, t0 - 1e-9);
        far = std::min(far, t1 + 1e-9);
    }
    return near > far;
}

/// Per object: the nearest and farthest hit along the ray (empty when the ray misses it).
struct Interval {
    double near = 1e300, far = -1e300;
    bool hit() const { return near <= far; }
};

std::vector<Interval> castRay(const Scene& scene, const std::vector<Bounds>& bounds, Vec3 origin,
                              Vec3 direction) {
    std::vector<Interval> intervals(scene.objects.size());
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        if (rayMissesBox(origin, direction, bounds[o]))
            continue;
        const SceneObject& object = scene.objects[o];
        for (uint32_t t = object.first_triangle; t < object.first_triangle + object.triangle_count;
             ++t) {
            const auto& p = scene.positions;
            if (auto d = hitTriangle(origin, direction, p.corner(3 * t), p.corner(3 * t + 1),
                                     p.corner(3 * t + 2))) {
                intervals[o].near = std::min(intervals[o].near, *d);
                intervals[o].far = std::max(intervals[o].far, *d);
            }
        }
    }
    return intervals;
}

std::vector<Bounds> allBounds(const Scene& scene) {
    std::vector<Bounds> bounds;
    for (const SceneObject& object : scene.objects)
        bounds.push_back(objectBounds(scene, object));
    return bounds;
}

/// Rays from the camera's eye through an n x n grid covering its field of view.
template <class Visit> void castCameraGrid(const Scene& scene, int n, Visit visit) {
    ASSERT_TRUE(scene.camera.has_value());
    const CameraSpec& camera = *scene.camera;
    const Vec3 forward = normalized(camera.target - camera.eye);
    const Vec3 right = normalized(cross(forward, camera.up));
    const Vec3 up = cross(right, forward);
    const double half = std::tan(camera.fov_degrees * std::numbers::pi / 360);
    const std::vector<Bounds> bounds = allBounds(scene);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double sx = ((i + 0.5) / n * 2 - 1) * half, sy = ((j + 0.5) / n * 2 - 1) * half;
            const Vec3 direction = normalized(forward + (right * sx + up * sy));
            visit(castRay(scene, bounds, camera.eye, direction));
        }
}

bool boundsOverlap(const Bounds& a, const Bounds& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
           a.min.z <= b.max.z && b.min.z <= a.max.z;
}

int objectIndex(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].name == name)
            return static_cast<int>(i);
    ADD_FAILURE() << "no object named " << name;
    return 0;
}

/// Signed volume by the divergence theorem: positive for closed, outward-wound surfaces.
double signedVolume(const Scene& scene, const SceneObject& object) {
    double volume = 0;
    for (uint32_t t = object.first_triangle; t < object.first_triangle + object.triangle_count;
         ++t) {
        const auto& p = scene.positions;
        volume += dot(p.corner(3 * t), cross(p.corner(3 * t + 1), p.corner(3 * t + 2))) / 6;
    }
    return volume;
}

Scene loadOrFail(const std::string& path) {
    Result<Scene> loaded = loadJsonScene(path);
    EXPECT_TRUE(loaded) << loaded.error;
    return loaded ? std::move(*loaded.value) : Scene{};
}

void expectError(const Result<Scene>& loaded, const std::string& path,
                 const std::string& contains) {
    ASSERT_FALSE(loaded) << "expected an error containing '" << contains << "'";
    EXPECT_EQ(loaded.error.rfind(path, 0), 0u) << "must name the JSON file first: " << loaded.error;
    EXPECT_EQ(loaded.error.find('\n'), std::string::npos) << "must be one line: " << loaded.error;
    EXPECT_NE(loaded.error.find(contains), std::string::npos) << loaded.error;
}

// --- the format ---

TEST(JsonScene, BoxIsAUnitCubeWoundOutwards) {
    TempDir dir;
    const Scene scene = loadOrFail(dir.write("box.json", R"({"objects": [{"shape": "box"}]})"));
    ASSERT_EQ(scene.triangleCount(), 12u);
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].name, "box_0");
    EXPECT_EQ(scene.name, "box");
    EXPECT_FALSE(scene.camera.has_value());
    EXPECT_FALSE(scene.isDynamic());
    for (std::size_t c = 0; c < 36; ++c) {
        const Vec3 p = scene.positions.corner(c);
        EXPECT_EQ(std::abs(p.x), 0.5);
        EXPECT_EQ(std::abs(p.y), 0.5);
        EXPECT_EQ(std::abs(p.z), 0.5);
    }
    EXPECT_NEAR(signedVolume(scene, scene.objects[0]), 1.0, 1e-9);
}

TEST(JsonScene, ScaleThenRotateThenTranslate) {
    TempDir dir;
    // Scaled to 2 x 1 x 1 along x, turned 90 degrees about z (x -> y), moved to x = 10.
    const Scene scene = loadOrFail(dir.write("t.json", R"({"objects": [
        {"shape": "box", "scale": [2, 1, 1], "rotate": {"axis": [0, 0, 1], "degrees": 90}, "translate": [10, 0, 0]},
        {"shape": "box", "scale": 3, "translate": [0, 0, -5]}]})"));
    ASSERT_EQ(scene.objects.size(), 2u);
    const Bounds first = objectBounds(scene, scene.objects[0]);
    EXPECT_NEAR(first.min.x, 9.5, 1e-6);
    EXPECT_NEAR(first.max.x, 10.5, 1e-6);
    EXPECT_NEAR(first.min.y, -1.0, 1e-6);
    EXPECT_NEAR(first.max.y, 1.0, 1e-6);
    EXPECT_NEAR(first.max.z, 0.5, 1e-6);
    // Counter-clockwise about +z: the corner (+1, +0.5, z) of the scaled box goes to (-0.5, +1, z).
    bool found = false;
    for (std::size_t c = 0; c < 36; ++c) {
        const Vec3 p = scene.positions.corner(c);
        found |= std::abs(p.x - 9.5) < 1e-6 && std::abs(p.y - 1.0) < 1e-6;
    }
    EXPECT_TRUE(found);
    const Bounds second = objectBounds(scene, scene.objects[1]);
    EXPECT_NEAR(second.min.z, -6.5, 1e-6);
    EXPECT_NEAR(second.max.x, 1.5, 1e-6);
    EXPECT_NEAR(signedVolume(scene, scene.objects[1]), 27.0, 1e-6);
}

TEST(JsonScene, EulerAnglesApplyXThenYThenZ) {
    TempDir dir;
    // Half extents (0.5, 1, 2). Rx(90): (0.5, 2, 1); then Rz(90): (2, 0.5, 1).
    // The other order would give (1, 2, 0.5).
    const Scene scene = loadOrFail(dir.write("e.json", R"({"objects": [
        {"shape": "box", "scale": [1, 2, 4], "rotate": [90, 0, 90]}]})"));
    const Bounds b = objectBounds(scene, scene.objects[0]);
    EXPECT_NEAR(b.max.x, 2.0, 1e-6);
    EXPECT_NEAR(b.max.y, 0.5, 1e-6);
    EXPECT_NEAR(b.max.z, 1.0, 1e-6);
}

TEST(JsonScene, MeshPathsAreRelativeToTheJsonFileAndEachEntryIsOneObject) {
    TempDir dir;
    dir.write("models/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string groups = kMeshes + "groups.obj";
    const Scene scene = loadOrFail(dir.write("scene.json", R"({"name": "mixed", "objects": [
        {"mesh": "models/tri.obj", "translate": [0, 0, 1]},
        {"name": "glass", "mesh": ")" + groups + R"("},
        {"name": "each", "mesh": ")" + groups + R"(", "objects": "mesh"},
        {"mesh": "models/tri.obj", "colour": [1, 0, 0, 0.25], "transparent": false}]})"));
    EXPECT_EQ(scene.name, "mixed");
    ASSERT_EQ(scene.objects.size(), 6u);
    EXPECT_EQ(scene.objects[0].name, "tri");
    // groups.obj's three meshes: one object by default, its meshes parts of it.
    EXPECT_EQ(scene.objects[1].name, "glass");
    EXPECT_EQ(scene.objects[2].name, "each/red");
    EXPECT_EQ(scene.objects[3].name, "each/green");
    EXPECT_EQ(scene.objects[4].name, "each/blue");
    EXPECT_EQ(scene.objects[5].name, "tri");
    const uint32_t firsts[] = {0, 1, 5, 6, 7, 9};
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(scene.objects[i].first_triangle, firsts[i]);
    EXPECT_EQ(scene.triangleCount(), 10u);
    EXPECT_EQ(scene.positions.corner(0).z, 1.0);
    const SceneObject& glass = scene.objects[1];
    ASSERT_EQ(glass.parts.size(), 3u);
    EXPECT_EQ(glass.parts[0].name, "red");
    EXPECT_EQ(glass.parts[2].first_triangle, 3u); // placed in the scene's triangle ids
    EXPECT_EQ(glass.parts[2].triangle_count, 2u);
    // The file's materials stay unless overridden: red_glass has d 0.5.
    EXPECT_TRUE(glass.transparent);
    EXPECT_FLOAT_EQ(glass.parts[1].colour.g, 1.0f);
    EXPECT_TRUE(scene.objects[2].transparent);
    EXPECT_FALSE(scene.objects[3].transparent);
    // An explicit colour replaces it; an explicit "transparent" wins over the colour's alpha.
    EXPECT_FLOAT_EQ(scene.objects[5].colour.r, 1.0f);
    EXPECT_FLOAT_EQ(scene.objects[5].colour.a, 0.25f);
    EXPECT_FALSE(scene.objects[5].transparent);
}

TEST(JsonScene, AnEntryColourRecoloursEveryPart) {
    TempDir dir;
    const Scene scene =
        loadOrFail(dir.write("c.json", R"({"objects": [{"mesh": ")" + kMeshes +
                                           R"(crabs.obj", "colour": [0, 0, 1]}]})"));
    ASSERT_EQ(scene.objects.size(), 1u);
    ASSERT_EQ(scene.objects[0].parts.size(), 4u);
    for (const ObjectPart& part : scene.objects[0].parts) {
        EXPECT_FLOAT_EQ(part.colour.b, 1.0f);
        EXPECT_FLOAT_EQ(part.colour.r, 0.0f);
        EXPECT_FLOAT_EQ(part.colour.a, 1.0f);
    }
    EXPECT_FALSE(scene.objects[0].transparent);
}

TEST(JsonScene, ColourAlphaBelowOneMeansTransparent) {
    TempDir dir;
    const Scene scene = loadOrFail(dir.write("c.json", R"({"objects": [
        {"shape": "box", "colour": [0.1, 0.2, 0.3, 0.5]}, {"shape": "box", "colour": [0.1, 0.2, 0.3]},
        {"shape": "box", "transparent": true}]})"));
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_TRUE(scene.objects[0].transparent);
    EXPECT_FLOAT_EQ(scene.objects[1].colour.b, 0.3f);
    EXPECT_FLOAT_EQ(scene.objects[1].colour.a, 1.0f);
    EXPECT_FALSE(scene.objects[1].transparent);
    EXPECT_TRUE(scene.objects[2].transparent);
}

TEST(JsonScene, CamerasAreStored) {
    TempDir dir;
    const Scene perspective = loadOrFail(
        dir.write("p.json", R"({"camera": {"eye": [1, 2, 3], "target": [0, 0, -1], "fov": 30},
        "objects": [{"shape": "box"}]})"));
    ASSERT_TRUE(perspective.camera.has_value());
    EXPECT_EQ(perspective.camera->projection, Projection::perspective);
    EXPECT_EQ(perspective.camera->eye.y, 2.0);
    EXPECT_EQ(perspective.camera->target.z, -1.0);
    EXPECT_EQ(perspective.camera->up.y, 1.0); // default
    EXPECT_EQ(perspective.camera->fov_degrees, 30.0);
    const Scene ortho = loadOrFail(dir.write(
        "o.json", R"({"camera": {"ortho_dir": [0, 0, -2]}, "objects": [{"shape": "box"}]})"));
    ASSERT_TRUE(ortho.camera.has_value());
    EXPECT_EQ(ortho.camera->projection, Projection::orthographic);
    EXPECT_NEAR(ortho.camera->ortho_direction.z, -1.0, 1e-12);
}

TEST(JsonScene, CameraPathsAreStored) {
    TempDir dir;
    const Scene scene = loadOrFail(dir.write("path.json", R"({"camera_path": [
        {"time": 0, "eye": [0, 1, 8], "target": [0, 1, 0]},
        {"time": 2.5, "eye": [3, 1, 8], "target": [0, 0, 0], "up": [0, 0, 1], "fov": 60}],
        "objects": [{"shape": "box"}]})"));
    ASSERT_EQ(scene.camera_path.size(), 2u);
    EXPECT_EQ(scene.camera_path[0].time, 0.0);
    EXPECT_EQ(scene.camera_path[0].camera.eye.z, 8.0);
    EXPECT_EQ(scene.camera_path[0].camera.fov_degrees, 45.0); // default
    EXPECT_EQ(scene.camera_path[1].time, 2.5);
    EXPECT_EQ(scene.camera_path[1].camera.eye.x, 3.0);
    EXPECT_EQ(scene.camera_path[1].camera.up.z, 1.0);
    EXPECT_EQ(scene.camera_path[1].camera.fov_degrees, 60.0);
    // Without a "camera", the first key frame is the scene's camera.
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->eye.z, 8.0);
    EXPECT_EQ(scene.camera->target.y, 1.0);
    // With one, it stays.
    const Scene both = loadOrFail(dir.write("both.json", R"({"camera": {"ortho_dir": [0, 0, -1]},
        "camera_path": [{"time": 0, "eye": [0, 1, 8], "target": [0, 1, 0]}],
        "objects": [{"shape": "box"}]})"));
    ASSERT_TRUE(both.camera.has_value());
    EXPECT_EQ(both.camera->projection, Projection::orthographic);
    EXPECT_EQ(both.camera_path.size(), 1u);
    // A scene without a path has none.
    EXPECT_TRUE(loadOrFail(dir.write("none.json", R"({"objects": [{"shape": "box"}]})"))
                    .camera_path.empty());
}

TEST(JsonScene, AnimationMovesAndSpinsObjectsRigidly) {
    const Scene scene = loadOrFail(kScenes + "animated.json");
    ASSERT_EQ(scene.objects.size(), 2u);
    ASSERT_TRUE(scene.isDynamic());
    const SceneObject& slider = scene.objects[objectIndex(scene, "slider")];
    const SceneObject& spinner = scene.objects[objectIndex(scene, "spinner")];
    const Vec3 centre = objectBounds(scene, spinner).centre();

    const TrianglePositions at0 = scene.frame(0.0);
    ASSERT_EQ(at0.x.size(), scene.positions.x.size());
    for (std::size_t c = 0; c < at0.x.size(); ++c)
        EXPECT_NEAR(at0.x[c], scene.positions.x[c], 1e-6);

    // Slider: velocity (1, 0, 0). Spinner: 90 degrees/s about +y through its box centre, so at
    // t = 1 an offset (dx, dy, dz) becomes (dz, dy, -dx), at t = 2 it becomes (-dx, dy, -dz).
    const TrianglePositions at1 = scene.frame(1.0), at2 = scene.frame(2.0);
    for (std::size_t c = slider.first_triangle * 3u;
         c < (slider.first_triangle + slider.triangle_count) * 3u; ++c) {
        EXPECT_NEAR(at2.x[c], scene.positions.x[c] + 2.0, 1e-5);
        EXPECT_NEAR(at2.y[c], scene.positions.y[c], 1e-6);
        EXPECT_NEAR(at2.z[c], scene.positions.z[c], 1e-6);
    }
    for (std::size_t c = spinner.first_triangle * 3u;
         c < (spinner.first_triangle + spinner.triangle_count) * 3u; ++c) {
        const Vec3 d = scene.positions.corner(c) - centre;
        EXPECT_NEAR(at1.x[c], centre.x + d.z, 1e-5);
        EXPECT_NEAR(at1.y[c], centre.y + d.y, 1e-5);
        EXPECT_NEAR(at1.z[c], centre.z - d.x, 1e-5);
        EXPECT_NEAR(at2.x[c], centre.x - d.x, 1e-5);
        EXPECT_NEAR(at2.z[c], centre.z - d.z, 1e-5);
    }
}

TEST(JsonScene, StaticScenesIgnoreTime) {
    TempDir dir;
    const Scene scene = loadOrFail(dir.write("s.json", R"({"objects": [{"shape": "box"}]})"));
    EXPECT_FALSE(scene.isDynamic());
    const TrianglePositions later = scene.frame(7.5);
    EXPECT_EQ(later.x, scene.positions.x);
    EXPECT_EQ(later.z, scene.positions.z);
}

TEST(JsonScene, TheDocumentedExampleLoads) {
    std::ifstream doc(kSource + "/docs/scene-format.md");
    std::string line, example;
    bool in_example = false, in_block = false;
    while (std::getline(doc, line)) {
        if (line == "### Example")
            in_example = true;
        else if (in_example && line == "```json")
            in_block = true;
        else if (in_block && line == "```")
            break;
        else if (in_block)
            example += line + "\n";
    }
    ASSERT_FALSE(example.empty());
    // The documented example ships as examples/scenes/cow_on_slab.json, as written there.
    const std::string shipped = kSource + "/examples/scenes/cow_on_slab.json";
    std::ifstream file(shipped);
    const nlohmann::json documented = nlohmann::json::parse(example),
                         copy = nlohmann::json::parse(file);
    EXPECT_EQ(documented, copy);
    const Scene scene = loadOrFail(shipped);
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_EQ(scene.objects[2].name, "box_2");
    EXPECT_EQ(scene.objects[3].name, "suzanne");
    EXPECT_TRUE(scene.objects[1].transparent);
    EXPECT_TRUE(scene.isDynamic());
}

// --- rejections: each names the file and the problem ---

TEST(JsonScene, RejectsMissingAndMalformedFiles) {
    TempDir dir;
    const std::string missing = (fs::temp_directory_path() / "vissort_no_such_scene.json").string();
    expectError(loadJsonScene(missing), missing, "not found");
    const std::string syntax =
        dir.write("syntax.json", "{\n  \"objects\": [\n    {\"shape\": \"box\"},\n  ]\n}\n");
    expectError(loadJsonScene(syntax), syntax, "line 4");
    const std::string empty = dir.write("empty.json", "");
    expectError(loadJsonScene(empty), empty, "invalid JSON");
    const std::string garbage = dir.write("garbage.json", std::string("\x01\xff\xfe{{", 5));
    expectError(loadJsonScene(garbage), garbage, "invalid JSON");
    const std::string overflow = dir.write(
        "overflow.json", R"({"objects": [{"shape": "box", "translate": [1e400, 0, 0]}]})");
    expectError(loadJsonScene(overflow), overflow, "1e400");
}

TEST(JsonScene, RejectsStructuralMistakes) {
    TempDir dir;
    const std::pair<const char*, const char*> cases[] = {
        {R"([1, 2])", "expected an object"},
        {R"({})", "missing 'objects'"},
        {R"({"objects": []})", "no objects"},
        {R"({"objects": {"shape": "box"}})", "expected an array"},
        {R"({"objets": []})", "unknown key 'objets'"},
        {R"({"objects": [{"shape": "box", "translte": [1, 2, 3]}]})", "unknown key 'translte'"},
        // The spelling of another English: the key the scene format has.
        {R"({"objects": [{"shape": "box", "color": [1, 0, 0]}]})",
         "unknown key 'color' (did you mean 'colour'?"},
        {R"({"objects": [{"shape": "box", "translte": [1, 2, 3]}]})", "did you mean 'translate'?"},
        {R"({"objects": [{"shape": "box", "scale": 2, "scale": 3}]})", "duplicate key 'scale'"},
        {R"({"objects": [{"shape": "box", "rotate": {"axis": [0, 0, 1], "degree": 3}}]})",
         "unknown key 'degree'"},
        {R"({"objects": [{"translate": [1, 2, 3]}]})", "exactly one of 'mesh' or 'shape'"},
        {R"({"objects": [{"shape": "box", "mesh": "a.obj"}]})", "exactly one of 'mesh' or 'shape'"},
        {R"({"objects": [{"shape": "sphere"}]})", "unknown shape 'sphere'"},
        {R"({"objects": [{"shape": 3}]})", "objects[0].shape: expected a string"},
        {R"({"objects": [{"shape": "box", "scale": "big"}]})", "objects[0].scale"},
        {R"({"objects": [{"shape": "box", "scale": 0}]})", "zero"},
        {R"({"objects": [{"shape": "box", "scale": [1, 0, 1]}]})", "zero"},
        {R"({"objects": [{"shape": "box", "translate": [1, 2]}]})", "array of 3 numbers"},
        {R"({"objects": [{"shape": "box", "translate": [1, "2", 3]}]})",
         "objects[0].translate[1]: expected a number"},
        {R"({"objects": [{"shape": "box", "transparent": 1}]})", "true or false"},
        {R"({"objects": [{"shape": "box", "colour": [1, 0]}]})", "[r, g, b]"},
        {R"({"objects": [{"shape": "box", "colour": [1, 0, 2]}]})", "[0, 1]"},
        {R"({"objects": [{"shape": "box", "rotate": {"axis": [0, 0, 0], "degrees": 3}}]})", "zero"},
        {R"({"objects": [{"shape": "box", "rotate": {"axis": [0, 0, 1]}}]})", "axis and degrees"},
        {R"({"objects": [{"shape": "box", "animation": {"velocity": [1, 0]}}]})",
         "animation.velocity"},
        {R"({"objects": [{"shape": "box", "animation": {"spin": {"axis": [0, 1, 0]}}}]})",
         "degrees_per_second"},
        {R"({"objects": [{"shape": "box", "animation": {"speed": 1}}]})", "unknown key 'speed'"},
        {R"({"camera": {"eye": [0, 0, 5]}, "objects": [{"shape": "box"}]})", "eye and target"},
        {R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 5]}, "objects": [{"shape": "box"}]})",
         "camera"},
        {R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov": 180}, "objects": [{"shape": "box"}]})",
         "camera"},
        {R"({"camera": {"ortho_dir": [0, 0, -1], "fov": 40}, "objects": [{"shape": "box"}]})",
         "ortho_dir cannot be combined"},
        {R"({"camera": {"ortho_dir": [0, 0, 0]}, "objects": [{"shape": "box"}]})", "zero"},
        {R"({"objects": [{"shape": "box", "scale": 1e38, "translate": [3e38, 0, 0]}]})",
         "overflow"},
        {R"({"camera_path": [], "objects": [{"shape": "box"}]})", "non-empty array"},
        {R"({"camera_path": {"time": 0}, "objects": [{"shape": "box"}]})", "non-empty array"},
        {R"({"camera_path": [3], "objects": [{"shape": "box"}]})",
         "camera_path[0]: expected an object"},
        {R"({"camera_path": [{"eye": [0, 0, 5], "target": [0, 0, 0]}], "objects": [{"shape": "box"}]})",
         "camera_path[0]: missing 'time'"},
        {R"({"camera_path": [{"time": -1, "eye": [0, 0, 5], "target": [0, 0, 0]}], "objects": [{"shape": "box"}]})",
         "camera_path[0].time: must not be negative"},
        {R"({"camera_path": [{"time": 1, "eye": [0, 0, 5], "target": [0, 0, 0]}, {"time": 1, "eye": [0, 0, 4], "target": [0, 0, 0]}], "objects": [{"shape": "box"}]})",
         "camera_path[1].time: must be later"},
        {R"({"camera_path": [{"time": 0, "eye": [0, 0, 5], "target": [0, 0, 5]}], "objects": [{"shape": "box"}]})",
         "camera_path[0]"},
        {R"({"camera_path": [{"time": 0, "ortho_dir": [0, 0, -1]}], "objects": [{"shape": "box"}]})",
         "unknown key 'ortho_dir'"},
        {R"({"camera_path": [{"time": 0, "eye": [0, 0, 5], "target": [0, 0, 0], "speed": 2}], "objects": [{"shape": "box"}]})",
         "unknown key 'speed'"},
    };
    int index = 0;
    for (const auto& [text, contains] : cases) {
        SCOPED_TRACE(text);
        const std::string path = dir.write("case" + std::to_string(index++) + ".json", text);
        expectError(loadJsonScene(path), path, contains);
    }
}

TEST(JsonScene, RejectsObjectGroupingsItDoesNotKnowAndOnShapes) {
    TempDir dir;
    const std::string crabs = kMeshes + "crabs.obj";
    const std::string misspelt =
        dir.write("a.json", R"({"objects": [{"mesh": ")" + crabs + R"(", "objects": "meshes"}]})");
    expectError(loadJsonScene(misspelt), misspelt,
                "objects[0].objects: unknown grouping 'meshes' (did you mean 'mesh'?");
    const std::string not_text =
        dir.write("b.json", R"({"objects": [{"mesh": ")" + crabs + R"(", "objects": 1}]})");
    expectError(loadJsonScene(not_text), not_text, "objects[0].objects: expected a string");
    const std::string shape =
        dir.write("c.json", R"({"objects": [{"shape": "box", "objects": "file"}]})");
    expectError(loadJsonScene(shape), shape,
                "objects[0].objects: says how a mesh file becomes objects");
}

TEST(JsonScene, RejectsMissingAndBrokenMeshFilesNamingThem) {
    TempDir dir;
    const std::string path =
        dir.write("m.json", R"({"objects": [{"shape": "box"}, {"mesh": "models/absent.obj"}]})");
    expectError(loadJsonScene(path), path, "absent.obj");
    expectError(loadJsonScene(path), path, "objects[1].mesh");
    dir.write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string broken = dir.write("b.json", R"({"objects": [{"mesh": "nan.obj"}]})");
    expectError(loadJsonScene(broken), broken, "non-finite");
}

// --- the fixture scenes used by the ordering tests ---

TEST(JsonSceneFixtures, LoadWithTheExpectedObjectCounts) {
    const std::pair<const char*, std::size_t> fixtures[] = {{"disjoint.json", 6},
                                                            {"stack.json", 36},
                                                            {"interpenetrating.json", 6},
                                                            {"three_sticks.json", 3},
                                                            {"animated.json", 2}};
    for (const auto& [file, objects] : fixtures) {
        SCOPED_TRACE(file);
        const Scene scene = loadOrFail(kScenes + file);
        EXPECT_EQ(scene.objects.size(), objects);
        EXPECT_TRUE(scene.camera.has_value());
        EXPECT_EQ(validateScene(scene).error, "");
        EXPECT_EQ(scene.isDynamic(), std::string(file) == "animated.json");
    }
}

TEST(JsonSceneFixtures, DisjointObjectsOverlapOnScreen) {
    const Scene scene = loadOrFail(kScenes + "disjoint.json");
    ASSERT_EQ(scene.objects.size(), 6u);
    const std::vector<Bounds> bounds = allBounds(scene);
    for (std::size_t a = 0; a < bounds.size(); ++a)
        for (std::size_t b = a + 1; b < bounds.size(); ++b)
            EXPECT_FALSE(boundsOverlap(bounds[a], bounds[b])) << a << " " << b;
    // Every object is in front of or behind another along some ray from the default camera.
    std::vector<bool> overlapped(scene.objects.size(), false);
    std::size_t deepest = 0;
    castCameraGrid(scene, 48, [&](const std::vector<Interval>& hits) {
        std::size_t count = 0;
        for (const Interval& hit : hits)
            count += hit.hit();
        deepest = std::max(deepest, count);
        if (count >= 2)
            for (std::size_t o = 0; o < hits.size(); ++o)
                overlapped[o] = overlapped[o] || hits[o].hit();
    });
    for (std::size_t o = 0; o < overlapped.size(); ++o)
        EXPECT_TRUE(overlapped[o]) << scene.objects[o].name;
    EXPECT_GE(deepest, 3u);
}

TEST(JsonSceneFixtures, StackIsThirtySixDisjointSlightlyTiltedSlabs) {
    const Scene scene = loadOrFail(kScenes + "stack.json");
    ASSERT_EQ(scene.objects.size(), 36u);
    const std::vector<Bounds> bounds = allBounds(scene);
    // Disjoint boxes cannot intersect.
    for (std::size_t a = 0; a < bounds.size(); ++a)
        for (std::size_t b = a + 1; b < bounds.size(); ++b)
            EXPECT_FALSE(boundsOverlap(bounds[a], bounds[b])) << a << " " << b;
    // The big faces are tilted less than 4 degrees from the z axis.
    for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
        const auto& p = scene.positions;
        const Vec3 n =
            cross(p.corner(3 * t + 1) - p.corner(3 * t), p.corner(3 * t + 2) - p.corner(3 * t));
        const double area = std::sqrt(dot(n, n)) / 2;
        if (area > 1) {
            EXPECT_GT(std::abs(n.z) / (2 * area), std::cos(4 * std::numbers::pi / 180))
                << "triangle " << t;
        }
    }
    // Looking down the stack from the default camera, the centre ray crosses every slab.
    const CameraSpec& camera = *scene.camera;
    const std::vector<Interval> hits =
        castRay(scene, bounds, camera.eye, normalized(camera.target - camera.eye));
    std::size_t crossed = 0;
    for (const Interval& hit : hits)
        crossed += hit.hit() && hit.far > hit.near;
    EXPECT_EQ(crossed, 36u);
}

TEST(JsonSceneFixtures, ThreeSticksOverlapCyclicallyWithoutIntersecting) {
    const Scene scene = loadOrFail(kScenes + "three_sticks.json");
    ASSERT_EQ(scene.objects.size(), 3u);
    // in_front[a][b]: some camera ray meets a before b. Along every ray the two sticks' hit
    // intervals are disjoint (an overlap would mean the boxes intersect).
    bool in_front[3][3] = {};
    std::size_t interval_overlaps = 0;
    castCameraGrid(scene, 160, [&](const std::vector<Interval>& hits) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                if (a == b || !hits[a].hit() || !hits[b].hit())
                    continue;
                if (hits[a].far < hits[b].near)
                    in_front[a][b] = true;
                else if (a < b && hits[b].far >= hits[a].near)
                    ++interval_overlaps;
            }
    });
    EXPECT_EQ(interval_overlaps, 0u);
    EXPECT_TRUE(in_front[0][1] && in_front[1][2] && in_front[2][0]);
    EXPECT_FALSE(in_front[1][0] || in_front[2][1] || in_front[0][2]);
}

TEST(JsonSceneFixtures, InterpenetratingObjectsOccludeEachOther) {
    const Scene scene = loadOrFail(kScenes + "interpenetrating.json");
    ASSERT_EQ(scene.objects.size(), 6u);
    // For each intersecting pair, rays from the camera where each one's nearest hit is in front
    // of the other's: a two-object occlusion cycle that disjoint convex objects cannot form.
    const std::pair<const char*, const char*> pairs[] = {
        {"spot", "bunny"}, {"box", "suzanne"}, {"bar_x", "bar_y"}};
    std::vector<std::array<bool, 2>> seen(3, {false, false});
    castCameraGrid(scene, 120, [&](const std::vector<Interval>& hits) {
        for (std::size_t k = 0; k < 3; ++k) {
            const Interval& a = hits[objectIndex(scene, pairs[k].first)];
            const Interval& b = hits[objectIndex(scene, pairs[k].second)];
            if (!a.hit() || !b.hit())
                continue;
            seen[k][a.near < b.near ? 0 : 1] = true;
        }
    });
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_TRUE(seen[k][0] && seen[k][1]) << pairs[k].first << " / " << pairs[k].second;
    }
}

} // namespace
} // namespace vissort
