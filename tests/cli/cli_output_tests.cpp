// End-to-end tests of what the commands tell their users (issue 17): the cameras a mesh file
// stores, the camera used, per-frame CSV, progress and --quiet, info's object list, cameras
// placed by azimuth and elevation.

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_fixture.h"

namespace vissort {
namespace {

const std::string kCameras = dataPath("meshes/cameras.gltf"); // cameras 'front' and 'top'

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    for (const std::string& line : lines(text)) {
        std::vector<std::string> cells;
        std::istringstream in(line);
        for (std::string cell; std::getline(in, cell, ',');)
            cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

// The glTF file's two cameras are listed by info, in text and JSON; the first is the default,
// placed by its node (not twice: assimp also copies the translation into the camera).
TEST_F(Cli, InfoListsTheCamerasOfAMeshFile) {
    const RunResult r = run({"info", kCameras, "--json", path("info.json")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("2 cameras in the file"), std::string::npos) << r;
    EXPECT_NE(r.out.find("camera 0 'front': perspective from 0.5,0,3"), std::string::npos) << r;
    EXPECT_NE(r.out.find("camera 1 'top': orthographic along 0,-1,"), std::string::npos) << r;
    EXPECT_NE(r.out.find("(the file's camera 0 'front')"), std::string::npos) << r;
    const json doc = json::parse(readFile(path("info.json")));
    ASSERT_EQ(doc["cameras"].size(), 2u);
    EXPECT_EQ(doc["cameras"][0]["name"], "front");
    EXPECT_EQ(doc["cameras"][0]["eye"], json::array({0.5, 0.0, 3.0}));
    // glTF's yfov of 0.6 radians.
    EXPECT_NEAR(doc["cameras"][0]["fov_degrees"].get<double>(), 0.6 * 180 / M_PI, 1e-4);
    EXPECT_EQ(doc["cameras"][1]["projection"], "orthographic");
    EXPECT_EQ(doc["camera"], [&] {
        json used = doc["cameras"][0];
        used.erase("name");
        return used;
    }());
}

// --camera picks by name or index, the same camera both ways; the JSON says which was used.
TEST_F(Cli, CameraPicksAStoredCamera) {
    const json by_name = orderJson({kCameras, "--camera", "top"}, "name.json");
    const json by_index = orderJson({kCameras, "--camera", "1"}, "index.json");
    EXPECT_EQ(by_name["camera"]["projection"], "orthographic");
    EXPECT_EQ(by_name["camera"], by_index["camera"]);
    const json first = orderJson({kCameras}, "first.json");
    EXPECT_EQ(first["camera"]["eye"], json::array({0.5, 0.0, 3.0}));
    // Settings given beside it change that camera only.
    const json wider = orderJson({kCameras, "--camera", "front", "--fov", "60"}, "fov.json");
    EXPECT_EQ(wider["camera"]["eye"], first["camera"]["eye"]);
    EXPECT_EQ(wider["camera"]["fov_degrees"], 60.0);
}

// A camera a mesh file stores that sees almost nothing is used with a warning naming --camera
// framed, which frames the whole scene instead (issue 35).
TEST_F(Cli, CameraFramedAndTheWarningOfACameraThatSeesLittle) {
    const std::string away = dataPath("meshes/camera_looking_away.gltf");
    const RunResult own = run({"info", away});
    ASSERT_EQ(own.code, 0) << own;
    EXPECT_NE(own.err.find("vissort: warning: the file's camera 0 'front' sees 0% of the "
                           "scene's surface: --camera framed frames the whole scene"),
              std::string::npos)
        << own;
    // A camera that crops the scene (the glTF's close-up of its quad): a note, not a warning.
    const RunResult close_up = run({"info", kCameras});
    EXPECT_TRUE(close_up.err.empty()) << close_up;
    EXPECT_NE(close_up.out.find("note: the file's camera 0 'front' sees "), std::string::npos)
        << close_up;
    EXPECT_NE(close_up.out.find("the rest is outside the picture; --camera framed"),
              std::string::npos)
        << close_up;
    const RunResult framed = run({"info", away, "--camera", "framed"});
    ASSERT_EQ(framed.code, 0) << framed;
    EXPECT_TRUE(framed.err.empty()) << framed;
    EXPECT_NE(framed.out.find("(framed to the geometry)"), std::string::npos) << framed;
    // The file's cameras set aside: the same camera as a file without any.
    const json plain = orderJson({kCameras, "--camera", "framed"}, "framed.json");
    EXPECT_NE(plain["camera"]["eye"], json::array({0.5, 0.0, 3.0}));
}

TEST_F(Cli, ErrorCamera) {
    expectError({"order", kCameras, "--camera", "frnt"}, kUsage,
                {"no camera 'frnt'", "indices 0 and 1", "did you mean 'front'?"});
    expectError({"order", kCameras, "--camera", "2"}, kUsage, {"no camera '2'"});
    expectError({"order", "builtin:slabs", "--camera", "0"}, kUsage,
                {"--camera", "stores no camera"});
    expectError({"order", kCameras, "--camera", "top", "--eye", "1,2,3"}, kUsage,
                {"orthographic", "--eye"});
    expectError({"order", kCameras, "--camera", "0", "--ortho-dir", "0,0,-1"}, kUsage,
                {"--camera cannot be combined with --ortho-dir"});
}

// Every command with a view prints the camera it used, and order's JSON has it per frame.
TEST_F(Cli, TheCameraUsedIsPrintedAndInTheJson) {
    const RunResult r = run({"order", "builtin:slabs?layers=3", "--eye", "0,0,9"});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("camera: perspective from 0,0,9 towards"), std::string::npos) << r;
    const json doc = orderJson({"builtin:slabs?layers=3", "--frames", "3", "--path", "orbit"});
    ASSERT_EQ(doc["frames"].size(), 3u);
    EXPECT_NE(doc["frames"][0]["camera"]["eye"], doc["frames"][2]["camera"]["eye"]);
    EXPECT_EQ(doc["camera"], doc["frames"][2]["camera"]);
    const RunResult orbit = run({"order", "builtin:slabs", "--frames", "2", "--path", "orbit"});
    EXPECT_NE(orbit.out.find("--path orbit moves it every frame"), std::string::npos) << orbit;
}

// --azimuth/--elevation: the eye in that direction from the scene's centre, framed, or at
// --distance; the angles the user gave, whatever the scene.
TEST_F(Cli, AzimuthElevationDistance) {
    const std::string scene = dataPath("meshes/groups.obj");
    const json at = orderJson({scene, "--azimuth", "90", "--elevation", "30", "--distance", "7"});
    const json& camera = at["camera"];
    std::vector<double> eye = camera["eye"], target = camera["target"];
    const double dx = eye[0] - target[0], dy = eye[1] - target[1], dz = eye[2] - target[2];
    EXPECT_NEAR(std::sqrt(dx * dx + dy * dy + dz * dz), 7.0, 1e-9);
    EXPECT_NEAR(dx / 7, std::cos(M_PI / 6), 1e-9); // azimuth 90: along +x
    EXPECT_NEAR(dy / 7, 0.5, 1e-9);                // elevation 30
    EXPECT_NEAR(dz / 7, 0.0, 1e-9);
    // Without --distance: framed, as close as the geometry fits, the same direction.
    const json framed = orderJson({scene, "--azimuth", "90", "--elevation", "30"}, "f.json");
    std::vector<double> e = framed["camera"]["eye"], t = framed["camera"]["target"];
    const double fx = e[0] - t[0], fy = e[1] - t[1], length = std::hypot(fx, fy, e[2] - t[2]);
    EXPECT_NEAR(fx / length, std::cos(M_PI / 6), 1e-9);
    EXPECT_NEAR(fy / length, 0.5, 1e-9);
    // Looking straight down has a usable up vector.
    EXPECT_EQ(run({"order", scene, "--elevation", "90"}).code, 0);
    expectError({"order", scene, "--elevation", "91"}, kUsage, {"--elevation", "-90 and 90"});
    expectError({"order", scene, "--distance", "0"}, kUsage, {"--distance", "positive"});
    expectError({"order", scene, "--azimuth", "10", "--eye", "1,2,3"}, kUsage,
                {"cannot be combined with --eye"});
}

// --csv: a header and one row a frame, agreeing with the JSON's per-frame statistics; '-'
// writes it to standard output alone.
TEST_F(Cli, CsvHasARowAFrame) {
    const json doc = orderJson({"builtin:bunnies?n=4", "--frames", "3", "--csv", path("o.csv")});
    const auto rows = csvRows(readFile(path("o.csv")));
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{"frame", "time_s", "primitives", "cycles",
                                                 "queries", "draws", "clears", "iterations",
                                                 "stuck_iterations", "cycle_queries", "cycle_draws",
                                                 "hinted_cycles", "graph_passes", "ms"}));
    for (int f = 0; f < 3; ++f) {
        ASSERT_EQ(rows[f + 1].size(), rows[0].size());
        EXPECT_EQ(rows[f + 1][0], std::to_string(f));
        EXPECT_EQ(std::stoull(rows[f + 1][3]), doc["frames"][f]["cycles"].size());
        // Every count agrees with the JSON's (both are written from VisSortStats' one table).
        for (std::size_t c = 4; c + 1 < rows[0].size(); ++c)
            EXPECT_EQ(std::stoull(rows[f + 1][c]), doc["frames"][f]["stats"][rows[0][c]])
                << rows[0][c];
    }
    const RunResult piped = run({"collide", "builtin:bunnies?n=4", "--frames", "2", "--csv", "-"});
    ASSERT_EQ(piped.code, 0) << piped;
    const auto collide_rows = csvRows(piped.out);
    ASSERT_EQ(collide_rows.size(), 3u) << piped;
    EXPECT_EQ(collide_rows[0],
              (std::vector<std::string>{
                  "frame", "time_s", "box_object_pairs", "object_pairs", "box_triangle_pairs",
                  "triangle_pairs", "intersecting", "colliding_object_pairs", "candidate_objects",
                  "directions", "queries", "update_ms", "cull_ms", "exact_ms", "total_ms"}));
    EXPECT_NE(piped.err.find("frame 1:"), std::string::npos) << "the text goes to stderr" << piped;
    expectError({"order", "builtin:slabs", "--csv", "-", "--json", "-"}, kUsage,
                {"standard output"});
    expectError({"order", "builtin:slabs", "--csv", path("no/such/folder/x.csv")}, kFailure,
                {"cannot write"});
}

// Progress on standard error while frames and a long frame go (VISSORT_PROGRESS_SECONDS=0
// reports at once instead of after a second); none, and no report either, with --quiet.
TEST_F(Cli, ProgressAndQuiet) {
    const auto progress = [&](const std::vector<std::string>& args) {
        return run(args, 60, "env VISSORT_PROGRESS_SECONDS=0");
    };
    const RunResult frames = progress({"order", "builtin:bunnies?n=4", "--frames", "3"});
    ASSERT_EQ(frames.code, 0) << frames;
    EXPECT_NE(frames.err.find("order 1/3 frames"), std::string::npos) << frames;
    EXPECT_NE(frames.err.find("left"), std::string::npos) << frames;
    // One frame at triangle level, bunnies in cycles: Vis-sort's iterations report a share.
    const RunResult one = progress({"order", "builtin:bunnies?n=4", "--level", "triangle"});
    ASSERT_EQ(one.code, 0) << one;
    EXPECT_NE(one.err.find("%"), std::string::npos) << one;
    const RunResult quiet = progress({"order", "builtin:bunnies?n=4", "--frames", "3", "--quiet"});
    EXPECT_EQ(quiet.code, 0) << quiet;
    EXPECT_EQ(quiet.out, "") << quiet;
    EXPECT_EQ(quiet.err, "") << quiet;
    // --quiet keeps the document asked for on standard output.
    const RunResult json_only = run({"order", "builtin:slabs", "-q", "--json", "-"});
    EXPECT_EQ(json_only.code, 0) << json_only;
    EXPECT_EQ(json::parse(json_only.out)["level"], "object") << json_only;
    EXPECT_EQ(json_only.err, "") << json_only;
    // Errors still show.
    expectError({"order", "missing.obj", "--quiet"}, kInput, {"missing.obj"});
}

// info lists ten objects and says how many more and where they all are; --all-objects and the
// JSON have every one.
TEST_F(Cli, InfoListsTenObjectsAndSaysHowToSeeAll) {
    const std::string scene = "builtin:bunnies?n=12";
    const RunResult r = run({"info", scene, "--json", path("i.json")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("object 9 'bunny_9'"), std::string::npos) << r;
    EXPECT_EQ(r.out.find("object 10 'bunny_10'"), std::string::npos) << r;
    EXPECT_NE(r.out.find("... and 2 more (--all-objects"), std::string::npos) << r;
    const RunResult all = run({"info", scene, "--all-objects"});
    EXPECT_NE(all.out.find("object 11 'bunny_11': 3674 triangles, transparent"), std::string::npos)
        << all;
    EXPECT_EQ(all.out.find("more (--all-objects"), std::string::npos) << all;
    const json doc = json::parse(readFile(path("i.json")));
    ASSERT_EQ(doc["object_list"].size(), 12u);
    EXPECT_EQ(doc["object_list"][11]["name"], "bunny_11");
    EXPECT_EQ(doc["object_list"][11]["first_triangle"], 11 * 3674);
    EXPECT_EQ(doc["object_list"][11]["transparent"], true);
}

} // namespace
} // namespace vissort
