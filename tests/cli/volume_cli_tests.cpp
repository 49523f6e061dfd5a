// vissort volume and vissort info on grids, end to end: every frame of an orbit written by the
// tool against the tests' brute force (tests/volume/brute_force_volume.h) with the camera the
// tool reports, the comparison of every method, and the errors.
#include <string>

#include "../volume/brute_force_volume.h"
#include "cli_fixture.h"
#include "png_reading.h"

namespace vissort {
namespace {

CameraSpec cameraFromJson(const json& j) {
    CameraSpec camera;
    const auto vec = [](const json& v) {
        return Vec3{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
    };
    camera.eye = vec(j["eye"]);
    camera.target = vec(j["target"]);
    camera.up = vec(j["up"]);
    camera.fov_degrees = j["fov_degrees"].get<double>();
    return camera;
}

TEST_F(Cli, VolumeFramesOfAnOrbitMatchBruteForce) {
    const RunResult r =
        run({"volume", "builtin:knot?n=14", "-o", path("frame_%02d.png"), "--size", "40x40",
             "--frames", "3", "--path", "orbit", "--tf", "bands", "--json", path("run.json")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("3 frames written"), std::string::npos) << r;
    const json run_json = json::parse(readFile(path("run.json")));
    ASSERT_EQ(run_json["frames"].size(), 3u);
    EXPECT_EQ(run_json["method"], "vissort");
    const TetGrid grid = *loadGrid("builtin:knot?n=14").value;
    const Bounds bounds = boundaryScene(grid).positions.bounds();
    VolumeSettings settings;
    settings.transfer = *loadTransferFunction("bands").value;
    const CameraSpec base = cameraFromJson(run_json["camera"]);
    for (int f = 0; f < 3; ++f) {
        SCOPED_TRACE(f);
        const ViewProjection view =
            frameCamera(cameraOnPath(base, CameraPath::orbit, f, bounds), bounds, 40, 40);
        const std::vector<uint8_t> truth = test::bruteForceVolume(grid, settings, view).toRgba8();
        const Png png = readPng(path("frame_0" + std::to_string(f) + ".png"));
        ASSERT_EQ(png.rgba.size(), truth.size());
        EXPECT_LE(compareImages(png.rgba, truth).max_abs, 1);
        EXPECT_GT(run_json["frames"][f]["segments"].get<uint64_t>(), 0u);
        EXPECT_GT(run_json["frames"][f]["queries"].get<uint64_t>(), 0u);
    }
}

TEST_F(Cli, VolumeReportsItsErrorAgainstAReference) {
    const RunResult r =
        run({"volume", "builtin:torus?n=8", "-o", path("mpvo.png"), "--size", "40x40", "--method",
             "mpvo", "--reference", "raycast", "--error-map", path("map.png"), "--elevation", "10",
             "--tf", "bands", "--json", path("run.json")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("against raycast"), std::string::npos) << r;
    const json frame = json::parse(readFile(path("run.json")))["frames"][0];
    EXPECT_EQ(frame["error"]["reference"], "raycast");
    EXPECT_EQ(readPng(path("map.png")).width, 40);
}

TEST_F(Cli, VolumeMethodAllComparesEveryMethod) {
    const RunResult r = run({"volume", "builtin:cube?n=3", "-o", path("all.png"), "--size", "32x32",
                             "--method", "all", "--json", path("all.json")});
    ASSERT_EQ(r.code, 0) << r;
    const json all = json::parse(readFile(path("all.json")));
    ASSERT_EQ(all["methods"].size(), 5u);
    for (const json& m : all["methods"]) {
        // On a convex grid every method but centroid is exact; centroid is near it.
        if (m["method"] != "centroid") {
            EXPECT_LE(m["error"]["max_abs"].get<int>(), 1) << m;
        }
    }
    const Png strip = readPng(path("all.png"));
    EXPECT_GT(strip.width, 5 * 32);
}

TEST_F(Cli, VolumeErrors) {
    expectError({"volume", "missing.vtu", "-o", path("x.png")}, kInput,
                {"missing.vtu: file not found"});
    expectError({"volume", "builtin:cube", "-o", path("x.png"), "--method", "raytrace"}, kUsage,
                {"--method", "raytrace", "raycast"});
    expectError({"volume", "builtin:cube", "-o", path("x.png"), "--error-map", path("m.png")},
                kUsage, {"--error-map needs --reference"});
    expectError({"volume", "builtin:cube", "-o", path("x.png"), "--tf", "fier"}, kUsage,
                {"did you mean 'fire'?"});
    expectError({"volume", "builtin:cube", "-o", path("x.png"), "--density", "-2"}, kUsage,
                {"--density"});
    expectError({"volume", "builtin:cube", "-o", path("x.png"), "--frames", "2"}, kUsage,
                {"needs one %d"});
    expectError({"volume", "builtin:cube", "-o", path("x.png"), "--method", "all", "--frames", "2"},
                kUsage, {"--method all draws one frame"});
    expectError({"volume", "builtin:cube?n=0", "-o", path("x.png")}, kInput,
                {"n must be a whole number"});
    // A tetgen pair without point attributes has no scalars.
    std::ofstream(path("plain.node")) << "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";
    std::ofstream(path("plain.ele")) << "1 4 0\n0 0 1 2 3\n";
    expectError({"volume", path("plain.node"), "-o", path("x.png")}, kInput,
                {"has no point scalars"});
}

TEST_F(Cli, BenchVolumeMeasuresEveryMethodOnEveryGrid) {
    const RunResult r = run({"bench", "volume", "--cells", "400,2000", "--frames", "2", "--size",
                             "32x32", "--json", path("bench.json"), "--plot", path("plot.png")});
    ASSERT_EQ(r.code, 0) << r;
    const json bench = json::parse(readFile(path("bench.json")));
    ASSERT_EQ(bench["rows"].size(), 2u * 2 * 5); // two sizes, a cube and a knot, five methods
    for (const json& row : bench["rows"]) {
        SCOPED_TRACE(row.dump());
        EXPECT_GT(row["median_ms"].get<double>(), 0);
        EXPECT_GT(row["cells"].get<uint64_t>(), 100u);
        const std::string method = row["method"];
        if (method == "vissort" || method == "lists" || method == "raycast") {
            EXPECT_LE(row["max_error"].get<int>(), 1);
        }
        if (method == "vissort") {
            // Pass 1 queries every cell but the one drawn first, whatever the start list.
            const double cells = row["cells"].get<double>();
            EXPECT_GE(row["queries_per_cell"].get<double>(), (cells - 1) / cells);
        }
        if (method == "lists") {
            EXPECT_GT(row["list_segments_per_cell"].get<double>(), 0);
        }
    }
    EXPECT_EQ(bench["rows"][0]["convex"], true);
    EXPECT_EQ(bench["rows"][5]["convex"], false);
    EXPECT_GT(readPng(path("plot.png")).width, 0);
    expectError({"bench", "volume", "--cells", "0"}, kUsage,
                {"--cells must be numbers of tetrahedra"});
}

TEST_F(Cli, SceneCommandsPointAGridToVolume) {
    std::vector<const char*> commands = {"order", "collide"};
#if VISSORT_WITH_GL
    commands.push_back("render"); // without OpenGL, render says that first
#endif
    for (const char* command : commands) {
        SCOPED_TRACE(command);
        std::vector<std::string> args = {command, "builtin:knot"};
        if (std::string(command) == "render") {
            args.insert(args.end(), {"-o", path("x.png")});
        }
        expectError(args, kInput,
                    {"builtin:knot is a tetrahedral grid", "'vissort volume' renders it"});
    }
    expectError({"order", dataPath("grids/tetgen_cube.1.node")}, kInput, {"is a tetrahedral grid"});
}

TEST_F(Cli, InfoDescribesAGrid) {
    const RunResult r = run({"info", "builtin:torus?n=8", "--json", path("info.json")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("boundary: "), std::string::npos) << r;
    EXPECT_NE(r.out.find("not convex"), std::string::npos) << r;
    const json info = json::parse(readFile(path("info.json")));
    const TetGrid grid = *loadGrid("builtin:torus?n=8").value;
    EXPECT_EQ(info["tetrahedra"].get<uint64_t>(), grid.tets.size());
    EXPECT_EQ(info["convex"], false);
    EXPECT_EQ(info["scalars"]["name"], "analytic");
    const RunResult cube = run({"info", "builtin:cube?n=2"});
    EXPECT_NE(cube.out.find("boundary: 48 triangles, convex"), std::string::npos) << cube;
    expectError({"info", "builtin:cube", "--objects", "file"}, kUsage,
                {"--objects is for mesh files"});
    const RunResult tetgen = run({"info", dataPath("grids/tetgen_cube.1.ele")});
    ASSERT_EQ(tetgen.code, 0) << tetgen;
    EXPECT_NE(tetgen.out.find("130 tetrahedra"), std::string::npos) << tetgen;
}

} // namespace
} // namespace vissort
