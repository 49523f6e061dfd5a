// End to end: `vissort render` and `vissort bench transparency` as a user runs them: the PNGs
// they write (read back with stb_image and, for flat shading, checked against the ray-cast
// A-buffer of tests/support), the statistics JSON, frame sequences, and one-line errors.

#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "a_buffer.h"
#include "cli_fixture.h"
#include "png_reading.h"
#include "scenes/scene_library.h"
#include "vissort/camera.h"
#include "vissort/scene.h"
#include "vissort/transparency_renderer.h"

namespace vissort {
namespace {

const std::string kSticks = dataPath("scenes/three_sticks.json");

TEST_F(Cli, RenderWritesThePngTheJsonAndTheErrorMap) {
    const RunResult r =
        run({"render", "builtin:slabs?layers=6", "--size", "64x48", "-o", path("out.png"), "--json",
             path("stats.json"), "--reference", "linked-list", "--error-map", path("error.png")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_TRUE(r.err.empty()) << r;
    EXPECT_NE(r.out.find("against linked-list"), std::string::npos) << r;
    const Png png = readPng(path("out.png"));
    EXPECT_EQ(png.width, 64);
    EXPECT_EQ(png.height, 48);
    const Png map = readPng(path("error.png"));
    EXPECT_EQ(map.width, 64);
    const json stats = json::parse(readFile(path("stats.json")));
    EXPECT_EQ(stats.value("method", ""), "vissort");
    for (const char* key : {"order", "render", "total"}) {
        ASSERT_TRUE(stats["ms"].contains(key)) << key;
        EXPECT_GE(stats["ms"][key].get<double>(), 0.0) << key;
    }
    EXPECT_GE(stats["ms"]["total"].get<double>(), stats["ms"]["render"].get<double>());
    EXPECT_EQ(stats.value("passes", 0), 1);
    EXPECT_EQ(stats.value("groups", -1), 0);          // the slabs order cleanly
    EXPECT_EQ(stats.value("repaired_pixels", -1), 0); // and the order is right on every pixel
    EXPECT_TRUE(stats.contains("fragments"));
    // The ordering's counts under "order": each of six slabs but the last queried.
    ASSERT_TRUE(stats.contains("order")) << stats.dump();
    EXPECT_GE(stats["order"].value("queries", 0), 5) << stats.dump();
    EXPECT_EQ(stats["order"].value("stuck_iterations", -1), 0) << stats.dump();
    ASSERT_TRUE(stats.contains("error")) << stats.dump();
    EXPECT_LE(stats["error"]["max_abs"].get<int>(), 1);
    EXPECT_TRUE(stats["error"].contains("rmse"));
    EXPECT_TRUE(stats["error"].contains("psnr"));
    EXPECT_EQ(stats.value("size", json()), json({64, 48}));
    EXPECT_EQ(stats.value("shading", ""), "lit");
    EXPECT_EQ(stats.value("samples", 0), 1);
}

// Each triangle's flat colour under --all-transparent --alpha A --shading flat.
std::vector<Rgba> coloursAtAlpha(const Scene& scene, float alpha) {
    std::vector<Rgba> colours(scene.triangleCount());
    for (const SceneObject& object : scene.objects)
        for (uint32_t t = 0; t < object.triangle_count; ++t) {
            colours[object.first_triangle + t] = object.colour;
            colours[object.first_triangle + t].a = alpha;
        }
    return colours;
}

// The tool's flat-shaded output against the ray-cast A-buffer, for every exact method.
TEST_F(Cli, FlatRenderOfEveryExactMethodMatchesTheRayCastABuffer) {
    Result<Scene> loaded = samples::loadScene(kSticks);
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 96, 72);
    const test::ABuffer reference = test::rayCastComposite(
        scene.positions, view, coloursAtAlpha(scene, 0.4f), kDefaultBackground);
    for (const char* method : {"vissort", "peel", "dual-peel", "linked-list"}) {
        const RunResult r =
            run({"render", kSticks, "--size", "96x72", "--all-transparent", "--alpha", "0.4",
                 "--shading", "flat", "--method", method, "-o", path("out.png")});
        ASSERT_EQ(r.code, 0) << r;
        const Png png = readPng(path("out.png"));
        const test::ABufferComparison compared = test::compareWithABuffer(png.rgba, reference);
        EXPECT_GT(compared.compared, 96u * 72u / 2) << method;
        EXPECT_LE(compared.max_abs, 1)
            << method << " at (" << compared.worst_x << ", " << compared.worst_y << ")";
    }
}

TEST_F(Cli, RenderRunsEveryMethodAndNamesThemInJson) {
    for (const char* method :
         {"vissort", "unsorted", "centroid", "peel", "dual-peel", "linked-list", "weighted"}) {
        const RunResult r = run({"render", "builtin:bunnies?n=3", "--size", "40x30", "--method",
                                 method, "-o", path("out.png"), "--json", path("stats.json")});
        ASSERT_EQ(r.code, 0) << r;
        EXPECT_EQ(json::parse(readFile(path("stats.json"))).value("method", ""), method);
    }
}

// --method all: every method and its error map in one PNG, and each one's figures in the JSON.
TEST_F(Cli, RenderEveryMethodSideBySide) {
    const RunResult r = run({"render", kSticks, "--all-transparent", "--size", "40x30", "--method",
                             "all", "-o", path("strip.png"), "--json", path("all.json")});
    ASSERT_EQ(r.code, 0) << r;
    const Png strip = readPng(path("strip.png"));
    EXPECT_GT(strip.width, 7 * 40);  // seven columns, with margins
    EXPECT_GT(strip.height, 2 * 30); // images above, error maps below, with captions
    const json doc = json::parse(readFile(path("all.json")));
    std::set<std::string> methods;
    for (const json& record : doc["methods"]) {
        const std::string method = record["method"];
        methods.insert(method);
        const int error = record["error"]["max_abs"];
        if (method == "vissort" || method == "linked-list" || method == "dual-peel") {
            EXPECT_LE(error, 1) << method;
        }
        if (method == "unsorted") {
            EXPECT_GT(error, 1); // the three sticks overlap in a cycle
        }
    }
    EXPECT_EQ(methods.size(), 7u);
    expectError({"render", kSticks, "--method", "all", "--frames", "2", "-o", path("s%d.png")},
                kUsage, {"--method all"});
    expectError({"render", kSticks, "--method", "all", "--reference", "peel", "-o", path("s.png")},
                kUsage, {"--method all"});
}

TEST_F(Cli, RenderFramesWriteASequence) {
    const RunResult r =
        run({"render", "builtin:bunnies?n=3", "--size", "40x30", "--frames", "3", "--path", "orbit",
             "--level", "triangle", "-o", path("frame_%02d.png"), "--json", path("stats.json")});
    ASSERT_EQ(r.code, 0) << r;
    for (const char* name : {"frame_00.png", "frame_01.png", "frame_02.png"})
        EXPECT_EQ(readPng(path(name)).width, 40) << name;
    EXPECT_FALSE(fs::exists(path("frame_03.png")));
    const json stats = json::parse(readFile(path("stats.json")));
    ASSERT_TRUE(stats.contains("frames"));
    EXPECT_EQ(stats["frames"].size(), 3u);
    EXPECT_EQ(stats.value("level", ""), "triangle");
}

// --samples 4: each pixel the mean of a 2 x 2 grid of samples, against the A-buffer cast at the
// samples and averaged the same way; the header says so.
TEST_F(Cli, RenderAtFourSamplesMatchesTheSupersampledABuffer) {
    Result<Scene> loaded = samples::loadScene(kSticks);
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    const ViewProjection samples = frameCamera(*scene.camera, scene.positions.bounds(), 192, 144);
    const test::ABuffer reference = test::resolveSamples(
        test::rayCastComposite(scene.positions, samples, coloursAtAlpha(scene, 0.4f),
                               kDefaultBackground),
        2, 2);
    for (const char* method : {"vissort", "linked-list"}) {
        const RunResult r =
            run({"render", kSticks, "--size", "96x72", "--all-transparent", "--alpha", "0.4",
                 "--shading", "flat", "--samples", "4", "--method", method, "-o", path("out.png")});
        ASSERT_EQ(r.code, 0) << r;
        EXPECT_NE(r.out.find("96x72 at 4 samples"), std::string::npos) << r;
        const Png png = readPng(path("out.png"));
        ASSERT_EQ(png.width, 96);
        const test::ABufferComparison compared = test::compareWithABuffer(png.rgba, reference);
        EXPECT_GT(compared.compared, 96u * 72u / 2) << method;
        EXPECT_LE(compared.max_abs, 1)
            << method << " at (" << compared.worst_x << ", " << compared.worst_y << ")";
    }
    // And membrane shading is a shading the command takes.
    const RunResult membrane = run({"render", kSticks, "--size", "32x24", "--shading", "membrane",
                                    "--samples", "8", "-o", path("membrane.png")});
    EXPECT_EQ(membrane.code, 0) << membrane;
}

TEST_F(Cli, RenderErrorsNameTheProblem) {
    const std::string out = path("out.png");
    expectError({"render", kSticks, "-o", out, "--method", "sorted"}, kUsage,
                {"--method", "sorted"});
    expectError({"render", kSticks, "-o", out, "--reference", "exact"}, kUsage,
                {"--reference", "exact"});
    expectError({"render", kSticks, "-o", out, "--all-transparent", "--alpha", "0"}, kUsage,
                {"--alpha"});
    expectError({"render", kSticks, "-o", out, "--level", "pixel"}, kUsage, {"--level", "pixel"});
    expectError({"render", kSticks, "-o", out, "--oracle", "magic"}, kUsage, {"--oracle"});
    expectError({"render", kSticks, "-o", out, "--shading", "phong"}, kUsage,
                {"--shading", "phong", "membrane"});
    expectError({"render", kSticks, "-o", out, "--size", "8192x8192", "--samples", "2"}, kFailure,
                {"8192x8192 at 2 samples a pixel"});
    for (const char* samples : {"0", "3", "16", "-4"})
        expectError({"render", kSticks, "-o", out, "--samples", samples}, kUsage,
                    {"--samples must be 1, 2, 4 or 8", samples});
    expectError({"render", kSticks, "-o", out, "--check", "maybe"}, kUsage,
                {"--check", "unknown order check", "maybe"});
    expectError({"render", kSticks, "-o", out, "--list-memory", "0"}, kUsage, {"--list-memory"});
    expectError({"render", kSticks, "-o", out, "--error-map", path("e.png")}, kUsage,
                {"--error-map", "--reference"});
    expectError({"render", kSticks, "-o", out, "--frames", "2"}, kUsage, {"%d"});
    expectError({"render", kSticks, "-o", path("f%d.png"), "--frames", "2", "--reference", "peel",
                 "--error-map", path("e.png")},
                kUsage, {"--error-map", "%d"});
    expectError({"render", kSticks}, kUsage, {"--output"});
    expectError({"render", dataPath("no_such_scene.json"), "-o", out}, kInput, {"no_such_scene"});
    expectError({"render", kSticks, "--size", "0x10", "-o", out}, kUsage, {"--size"});
    const std::string unwritable = path("no/such/folder/out.png");
    expectError({"render", kSticks, "--size", "16x16", "-o", unwritable}, kFailure, {unwritable});
}

// Every method and scene at every depth, errors against linked-list, in one run.
TEST_F(Cli, BenchTransparencyMeasuresEveryMethodInOneRun) {
    const RunResult r = run({"bench", "transparency", "--size", "48x32", "--depths", "2,6",
                             "--frames", "2", "--json", path("bench.json")});
    ASSERT_EQ(r.code, 0) << r;
    const json doc = json::parse(readFile(path("bench.json")));
    EXPECT_TRUE(doc.contains("machine"));
    EXPECT_EQ(doc.value("level", ""), "multistage");
    std::map<std::string, std::set<std::string>> methods; // scene and depth -> methods
    for (const json& row : doc["rows"]) {
        const std::string key =
            row["scene"].get<std::string>() + " " + std::to_string(row["depth"].get<int>());
        methods[key].insert(row["method"].get<std::string>());
        EXPECT_GE(row["ms"].get<double>(), 0.0) << row.dump();
        const std::string method = row["method"];
        if (method == "vissort" || method == "dual-peel") {
            EXPECT_LE(row["error"]["max_abs"].get<int>(), 1) << row.dump();
        }
        if (row["scene"] == "slabs") { // a slab a layer, all over the middle of the view
            EXPECT_EQ(row["depth_seen"], row["depth"]) << row.dump();
        }
    }
    const std::set<std::string> all{"vissort",     "peel",     "dual-peel",
                                    "linked-list", "weighted", "centroid"};
    EXPECT_EQ(methods.size(), 4u);
    for (const auto& [key, found] : methods)
        EXPECT_EQ(found, all) << key;
}

// --samples 2: every method at 1 and 2 samples a pixel in the same run, each with its cost.
TEST_F(Cli, BenchTransparencyMeasuresSamplesNextToOne) {
    const RunResult r = run({"bench", "transparency", "--size", "32x24", "--depths", "2",
                             "--frames", "2", "--samples", "2", "--json", path("bench.json")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("at 1 and 2 samples a pixel"), std::string::npos) << r;
    EXPECT_NE(r.out.find("cost: a method's time at 2 samples"), std::string::npos) << r;
    const json doc = json::parse(readFile(path("bench.json")));
    EXPECT_EQ(doc.value("samples", 0), 2);
    std::map<int, int> records; // samples -> records
    for (const json& row : doc["rows"]) {
        const int samples = row["samples"].get<int>();
        ++records[samples];
        EXPECT_EQ(row.contains("ms_over_one_sample"), samples == 2) << row.dump();
        const std::string method = row["method"];
        if (method == "vissort" || method == "peel") {
            EXPECT_LE(row["error"]["max_abs"].get<int>(), 1) << row.dump();
        }
    }
    // Two families at one depth, six methods, at each count.
    EXPECT_EQ(records, (std::map<int, int>{{1, 12}, {2, 12}}));
}

TEST_F(Cli, BenchTransparencyErrors) {
    expectError({"bench", "transparency", "--samples", "3"}, kUsage,
                {"--samples must be 1, 2, 4 or 8", "3"});
    expectError({"bench", "transparency", "--depths", "2,x"}, kUsage, {"--depths", "2,x"});
    expectError({"bench", "transparency", "--depths", "0"}, kUsage, {"--depths"});
    expectError({"bench", "transparency", "--frames", "1"}, kUsage, {"--frames"});
    expectError({"bench", "transparency", "--level", "none"}, kUsage, {"--level"});
    expectError({"bench", "transparency", "--size", "4"}, kUsage, {"--size"});
    expectError({"bench", "nothing"}, kUsage, {"nothing", "transparency"});
}

const std::string kInterpenetrating = dataPath("scenes/interpenetrating.json");

// Pixels of the highlight colour (shading.h: magenta, opaque), lit or not.
int magentaPixels(const std::string& png_path) {
    int width = 0, height = 0, channels = 0;
    unsigned char* png = stbi_load(png_path.c_str(), &width, &height, &channels, 4);
    if (png == nullptr)
        return -1;
    int count = 0;
    for (int i = 0; i < width * height; ++i) {
        const unsigned char* p = png + 4 * i;
        count += p[0] > 120 && p[1] < 0.15 * p[0] && p[2] > 0.4 * p[0] && p[2] < 0.7 * p[0];
    }
    stbi_image_free(png);
    return count;
}

TEST_F(Cli, RenderHighlightsCollidingTriangles) {
    const RunResult plain =
        run({"render", kInterpenetrating, "--size", "200x150", "-o", path("a.png")});
    ASSERT_EQ(plain.code, 0) << plain;
    const RunResult marked =
        run({"render", kInterpenetrating, "--size", "200x150", "-o", path("b.png"),
             "--highlight-collisions", "--json", path("b.json")});
    ASSERT_EQ(marked.code, 0) << marked;
    EXPECT_NE(marked.out.find("colliding triangles highlighted"), std::string::npos) << marked;
    EXPECT_EQ(magentaPixels(path("a.png")), 0);
    EXPECT_GT(magentaPixels(path("b.png")), 500);
    EXPECT_GT(json::parse(readFile(path("b.json"))).value("colliding_triangles", 0), 20);
    expectError({"render", kInterpenetrating, "--method", "all", "--highlight-collisions", "-o",
                 path("c.png")},
                kUsage, {"--highlight-collisions"});
}

// --colour-cycles: the three sticks are one cycle, painted (orange, the palette's first colour);
// the box beside them is in none and keeps its colour. Only vissort has cycles to colour, and a
// painted picture cannot be compared with a reference.
TEST_F(Cli, RenderColoursTheCycles) {
    const std::string scene = dataPath("scenes/three_sticks_and_box.json");
    const std::vector<std::string> common = {
        "render",    scene,  "--size",       "200x150", "--all-transparent",
        "--shading", "flat", "--background", "1,1,1"};
    auto with = [&](std::vector<std::string> more) {
        std::vector<std::string> args = common;
        args.insert(args.end(), more.begin(), more.end());
        return args;
    };
    ASSERT_EQ(run(with({"-o", path("plain.png")})).code, 0);
    const RunResult painted = run(with({"--colour-cycles", "-o", path("painted.png")}));
    ASSERT_EQ(painted.code, 0) << painted;
    const Png plain = readPng(path("plain.png")), cycles = readPng(path("painted.png"));
    ASSERT_EQ(plain.rgba.size(), cycles.rgba.size());
    // A stick's two faces in orange over white at alpha 0.5: (255, 169, 64); the sticks' own
    // colours never are.
    auto orange = [](const Png& png) {
        int count = 0;
        for (std::size_t i = 0; i < png.rgba.size(); i += 4)
            count += png.rgba[i] == 255 && std::abs(png.rgba[i + 1] - 169) <= 1 &&
                     std::abs(png.rgba[i + 2] - 64) <= 1;
        return count;
    };
    EXPECT_EQ(orange(plain), 0);
    EXPECT_GT(orange(cycles), 1000);
    // The box (right of the sticks, at 72% of the width) is the same in both.
    const int box_column = plain.width * 72 / 100, row = plain.height / 2;
    const std::size_t box = (std::size_t(row) * plain.width + box_column) * 4;
    EXPECT_NE(plain.rgba[box], 255); // the box is there
    EXPECT_EQ(std::vector<uint8_t>(plain.rgba.begin() + box, plain.rgba.begin() + box + 4),
              std::vector<uint8_t>(cycles.rgba.begin() + box, cycles.rgba.begin() + box + 4));
    expectError(with({"--colour-cycles", "--method", "unsorted", "-o", path("x.png")}), kUsage,
                {"--colour-cycles", "unsorted"});
    expectError(with({"--colour-cycles", "--reference", "linked-list", "-o", path("x.png")}),
                kUsage, {"--colour-cycles", "--reference"});
}

// Images are written in the format their name asks for, or refused before any work; a frame
// pattern with one frame names frame 0 (it wrote a file with '%04d' in its name).
TEST_F(Cli, RenderWritesTheFormatItsNameAsksFor) {
    ASSERT_EQ(run({"render", kSticks, "--size", "32x24", "-o", path("out.jpg")}).code, 0);
    const std::string jpeg = readFile(path("out.jpg"));
    ASSERT_GE(jpeg.size(), 3u);
    EXPECT_EQ(uint8_t(jpeg[0]), 0xFF); // JPEG's start of image, not PNG's signature
    EXPECT_EQ(uint8_t(jpeg[1]), 0xD8);
    expectError({"render", kSticks, "--size", "32x24", "-o", path("out.bmp")}, kUsage,
                {"-o", "out.bmp", ".png or .jpg"});
    EXPECT_FALSE(fs::exists(path("out.bmp")));
    const RunResult one = run({"render", kSticks, "--size", "32x24", "-o", path("f_%04d.png")});
    ASSERT_EQ(one.code, 0) << one;
    EXPECT_TRUE(fs::exists(path("f_0000.png"))) << one;
    EXPECT_FALSE(fs::exists(path("f_%04d.png"))) << one;
}

// Units on every time, words that agree with their counts, a note on opaque-only scenes, a
// summary after --frames, and a warning for transparent materials with alpha 0 (teapots.DAE
// rendered all white without one).
TEST_F(Cli, RenderOutputSaysWhatItMeasuredAndWhy) {
    const RunResult opaque = run({"render", kSticks, "--size", "32x24", "--frames", "3", "--path",
                                  "orbit", "-o", path("s_%d.png")});
    ASSERT_EQ(opaque.code, 0) << opaque;
    EXPECT_TRUE(std::regex_search(
        opaque.out, std::regex(R"(s_0\.png: [0-9.]+ ms \(order [0-9.]+ ms, render [0-9.]+ ms\))")))
        << opaque;
    EXPECT_NE(opaque.out.find("note: no transparent objects"), std::string::npos) << opaque;
    EXPECT_NE(opaque.out.find("--all-transparent"), std::string::npos) << opaque;
    EXPECT_NE(opaque.out.find("3 frames written"), std::string::npos) << opaque;
    EXPECT_EQ(opaque.out.find("1 passes"), std::string::npos) << opaque;
    EXPECT_TRUE(opaque.err.empty()) << opaque;

    std::ofstream(path("glass.mtl")) << "newmtl glass\nKd 0.2 0.4 0.9\nd 0\n";
    std::ofstream(path("glass.obj")) << "mtllib glass.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                        "usemtl glass\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n";
    const RunResult unseen =
        run({"render", path("glass.obj"), "--size", "32x24", "-o", path("glass.png")});
    ASSERT_EQ(unseen.code, 0) << unseen;
    EXPECT_NE(unseen.err.find("vissort: warning: transparent objects with alpha 0"),
              std::string::npos)
        << unseen;
    EXPECT_NE(unseen.err.find("--all-transparent --alpha"), std::string::npos) << unseen;
    const RunResult overridden = run({"render", path("glass.obj"), "--size", "32x24",
                                      "--all-transparent", "-o", path("glass.png")});
    EXPECT_TRUE(overridden.err.empty()) << overridden;
}

// Standard output reaches a pipe line by line: the header arrives while the frame still renders
// (it came only at the end).
TEST_F(Cli, RenderReportsBeforeItFinishes) {
    const std::string command =
        "cd " + shellQuote(dir_.string()) + " && " + shellQuote(kTool) +
        " render 'builtin:powerplant?scale=0.2' --size 400x300 --level triangle -o late.png";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char line[4096] = {};
    ASSERT_NE(std::fgets(line, sizeof(line), pipe), nullptr);
    EXPECT_NE(std::string(line).find("builtin:powerplant"), std::string::npos) << line;
    EXPECT_FALSE(fs::exists(path("late.png"))) << "the header came after the frame was written";
    while (std::fgets(line, sizeof(line), pipe) != nullptr) {
    } // the rest, so that the tool never writes into a closed pipe
    EXPECT_EQ(pclose(pipe), 0);
    EXPECT_TRUE(fs::exists(path("late.png")));
}

// The covered pixels' bounding box in a picture: the pixels unlike the top-left corner's.
struct Covered {
    int left = 1 << 30, right = -1, top = 1 << 30, bottom = -1;
};
Covered coveredBox(const Png& png) {
    Covered box;
    for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x)
            if (std::memcmp(&png.rgba[(std::size_t(y) * png.width + x) * 4], png.rgba.data(), 4)) {
                box.left = std::min(box.left, x);
                box.right = std::max(box.right, x);
                box.top = std::min(box.top, y);
                box.bottom = std::max(box.bottom, y);
            }
    return box;
}

// Without camera options a model fills the picture as mesh viewers frame it: the extent that
// binds spans about 95% of the image (the bounding sphere's framing left the bunny at 63%, and
// the cow at 64%), nothing is cut (no covered pixel on the border), and the other extent is
// centred. Landscape and portrait alike.
TEST_F(Cli, DefaultFramingFillsThePicture) {
    for (const std::string model : {"bunny-lowres.obj", "teapot.obj"})
        for (const auto& [w, h] : {std::pair{160, 120}, std::pair{120, 160}}) {
            const std::string size = std::to_string(w) + "x" + std::to_string(h);
            const RunResult r = run({"render", kSource + "/assets/models/" + model, "--size", size,
                                     "-o", path("framed.png")});
            ASSERT_EQ(r.code, 0) << r;
            const Covered box = coveredBox(readPng(path("framed.png")));
            const double width = box.right - box.left + 1, height = box.bottom - box.top + 1;
            EXPECT_GE(std::max(width / w, height / h), 0.92) << model << ' ' << size;
            EXPECT_GT(box.left, 0) << model << ' ' << size;
            EXPECT_GT(box.top, 0) << model << ' ' << size;
            EXPECT_LT(box.right, w - 1) << model << ' ' << size;
            EXPECT_LT(box.bottom, h - 1) << model << ' ' << size;
            EXPECT_LE(std::abs((box.left + box.right) - (w - 1)), 0.06 * w) << model << ' ' << size;
            EXPECT_LE(std::abs((box.top + box.bottom) - (h - 1)), 0.06 * h) << model << ' ' << size;
        }
}

// render --csv: a row a frame, with the reference's error columns when there is one; the
// camera of each frame in the JSON.
TEST_F(Cli, RenderCsvAndCamera) {
    const RunResult r = run({"render", "builtin:bunnies?n=3", "--size", "48x48", "--frames", "2",
                             "-o", path("f%d.png"), "--reference", "linked-list", "--csv",
                             path("r.csv"), "--json", path("r.json")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("camera: perspective from"), std::string::npos) << r;
    const std::vector<std::string> rows = lines(readFile(path("r.csv")));
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0], "frame,time_s,order_ms,render_ms,total_ms,passes,fragments,groups,"
                       "repaired_pixels,triangles,boxed_objects,culled_objects,queries,draws,"
                       "clears,iterations,stuck_iterations,cycle_queries,cycle_draws,hinted_cycles,"
                       "graph_passes,max_abs,rmse,pixels_over_one");
    EXPECT_EQ(rows[2].substr(0, 2), "1,");
    const json doc = json::parse(readFile(path("r.json")));
    EXPECT_EQ(doc["frames"][1]["camera"]["projection"], "perspective");
    expectError({"render", "builtin:bunnies?n=3", "--method", "all", "-o", path("a.png"), "--csv",
                 path("a.csv")},
                kUsage, {"--csv", "--method all"});
}

// The background: a dark slate grey by default (kDefaultBackground), under which the default
// grey at alpha 0.5 shows; --background takes R,G,B[,A] or #RRGGBB, and refuses the rest.
TEST_F(Cli, RenderBackgroundByDefaultAndAsAsked) {
    const auto corner = [&](const std::vector<std::string>& more) {
        std::vector<std::string> args = {"render", kSticks, "--size",
                                         "40x30",  "-o",    path("bg.png")};
        args.insert(args.end(), more.begin(), more.end());
        const RunResult r = run(args);
        EXPECT_EQ(r.code, 0) << r;
        const Png png = readPng(path("bg.png"));
        return std::vector<int>(png.rgba.begin(), png.rgba.begin() + 3);
    };
    const std::vector<int> plain = corner({});
    const Rgba& d = kDefaultBackground;
    const float expected[3] = {d.r * 255, d.g * 255, d.b * 255};
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(plain[c], expected[c], 1.0) << c;
    EXPECT_EQ(corner({"--background", "0,0,1"}), (std::vector<int>{0, 0, 255}));
    EXPECT_EQ(corner({"--background", "#ff8000"}), (std::vector<int>{255, 128, 0}));
    EXPECT_EQ(corner({"--background", "1,1,1,1"}), (std::vector<int>{255, 255, 255}));
    for (const char* bad : {"2,0,0", "red", "#ff00", "1,1", "1,1,1,1,1", "0,,1", "#gg0000"})
        expectError({"render", kSticks, "--background", bad, "-o", path("x.png")}, kUsage,
                    {"--background expects R,G,B or R,G,B,A", bad});
}

} // namespace
} // namespace vissort
