// End to end: `vissort bench paper --quick` as CI runs it: every output under --out produced and
// well formed (the JSON's paths and frames, the CSV's rows, the PNG plots read back), the figures
// plausible (every coherent frame ordered with queries, collisions on the bunnies only), and
// one-line errors for bad options. With OpenGL also the gl oracle's frames, the frame times with
// transparency and figure 6; without it, the files say so.

#include <stb/stb_image.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.h"

namespace vissort {
namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

// The median of an odd number of values (--quick: 5 coherent frames a path).
double median(std::vector<double> values) {
    EXPECT_EQ(values.size() % 2, 1u);
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

std::size_t fields(const std::string& line) {
    return std::size_t(std::count(line.begin(), line.end(), ',')) + 1;
}

TEST_F(Cli, BenchPaperQuickWritesEveryFigure) {
    const std::string out = path("paper");
    // A hang guard, not a time limit: under AddressSanitizer the quick walk's 28 steps take
    // about a minute (CI's sanitizer stage met 60 s at step 14 of 28 with another test beside).
    const RunResult r =
        run({"bench", "paper", "--quick", "--out", out}, 300, "env VISSORT_PROGRESS_SECONDS=0");
    ASSERT_EQ(r.code, 0) << r;
    for (const char* name :
         {"plant-walkthrough", "bunnies-static", "bunnies-moving", "plant-x10-lod"})
        EXPECT_NE(r.out.find(name), std::string::npos) << name << r;
    // Not a terminal: plain progress lines on stderr (at once here; by default after a second,
    // then every five).
    EXPECT_NE(r.err.find("bench paper "), std::string::npos) << r;
    EXPECT_NE(r.err.find(" steps, "), std::string::npos) << r;

    const json doc = json::parse(readFile(out + "/paper.json"));
    EXPECT_EQ(doc["benchmark"], "paper");
    EXPECT_EQ(doc["quick"], true);
#if VISSORT_WITH_GL
    EXPECT_EQ(doc["gl_frames"], 2); // quick's default, on any renderer
#else
    EXPECT_EQ(doc["gl_frames"], 0);
#endif
    ASSERT_EQ(doc["paths"].size(), 4u);
    // Ten times the quick plant, with levels of detail within 1 pixel (the default).
    EXPECT_NE(r.out.find("plant-x10-lod: builtin:powerplant?scale=0.5"), std::string::npos) << r;
    std::size_t frames_seen = 0;
    for (const json& path : doc["paths"]) {
        const std::string name = path["name"];
        const bool levels = name == "plant-x10-lod";
        ASSERT_EQ(path["frames"].size(), 6u) << name;
        EXPECT_GT(path["primitives"].get<uint64_t>(), 0u) << name;
        EXPECT_EQ(path["paper"].empty(), levels) << name;
        EXPECT_EQ(path["lod_error"].get<double>(), levels ? 1.0 : 0.0) << name;
        EXPECT_EQ(path["levels_ms"].get<double>() > 0, levels) << name;
        // Collisions do not depend on the camera: measured once, with the static viewer.
        const bool collides = name == "bunnies-static";
        std::vector<double> order_ms, queries, cycle_queries;
        for (const json& frame : path["frames"]) {
            EXPECT_GT(frame["cpu_queries"].get<uint64_t>(), 0u) << name;
            // The cycle search's share of the frame's queries.
            EXPECT_LE(frame["cpu_cycle_queries"].get<uint64_t>(),
                      frame["cpu_queries"].get<uint64_t>())
                << name;
            EXPECT_GT(frame["cpu_order_ms"].get<double>(), 0.0) << name;
            EXPECT_EQ(frame["collide_ms"].is_number(), collides) << name;
            // Levels of detail order fewer triangles than the scene has; else every one.
            if (levels)
                EXPECT_LT(frame["triangles_drawn"].get<uint64_t>(),
                          path["triangles"].get<uint64_t>());
            else
                EXPECT_EQ(frame["triangles_drawn"], path["triangles"]);
            if (frame["frame"].get<int>() > 0) {
                order_ms.push_back(frame["cpu_order_ms"].get<double>());
                queries.push_back(double(frame["cpu_queries"].get<uint64_t>()));
                cycle_queries.push_back(double(frame["cpu_cycle_queries"].get<uint64_t>()));
            }
#if VISSORT_WITH_GL
            EXPECT_TRUE(frame["render_ms"].is_number()) << name;
            EXPECT_EQ(frame["gl_queries"].is_number(), frame["frame"].get<int>() < 2 && !levels)
                << name;
#else
            EXPECT_TRUE(frame["render_ms"].is_null()) << name;
            EXPECT_TRUE(frame["gl_queries"].is_null()) << name;
#endif
            ++frames_seen;
        }
        const json& medians = path["coherent_medians"];
        // The medians are over the coherent frames (all but the first): recomputed here.
        EXPECT_DOUBLE_EQ(medians["cpu_order_ms"].get<double>(), median(order_ms)) << name;
        EXPECT_DOUBLE_EQ(medians["cpu_queries"].get<double>(), median(queries)) << name;
        EXPECT_DOUBLE_EQ(medians["cpu_cycle_queries"].get<double>(), median(cycle_queries)) << name;
        // The plant's walls and glass panes make cycles on every frame (found by group tests or,
        // for its large stuck set, from the cpu oracle's graph in one pass).
        if (name == "plant-walkthrough") {
            EXPECT_GT(path["frames"][0]["cpu_cycles"].get<uint64_t>(), 0u);
        }
        EXPECT_DOUBLE_EQ(medians["cpu_queries_per_primitive"].get<double>(),
                         median(queries) / path["primitives"].get<double>())
            << name;
        // Vis-sort asks at least one query a primitive and, on coherent frames, a few at most.
        EXPECT_GE(medians["cpu_queries_per_primitive"].get<double>(), 1.0) << name;
        EXPECT_LE(medians["cpu_queries_per_primitive"].get<double>(), 20.0) << name;
    }

    const std::vector<std::string> csv = lines(readFile(out + "/paper.csv"));
    ASSERT_EQ(csv.size(), 1 + frames_seen);
    for (const std::string& line : csv)
        EXPECT_EQ(fields(line), fields(csv[0])) << line;

    std::vector<std::string> plots = {"figure5-plant-ms.png", "figure5-plant-queries.png",
                                      "figure5-bunnies-ms.png", "figure5-bunnies-queries.png"};
#if VISSORT_WITH_GL
    plots.push_back("figure6.png");
    ASSERT_TRUE(doc["figure6"].is_object());
    // Two families at two depths, a record a method (six), as `bench transparency --json`.
    ASSERT_EQ(doc["figure6"]["rows"].size(), 4u * 6);
    for (const json& record : doc["figure6"]["rows"]) {
        EXPECT_TRUE(record["ms"].is_number()) << record;
        EXPECT_EQ(record.contains("error"), record["method"] != "linked-list") << record;
    }
    const std::vector<std::string> figure6 = lines(readFile(out + "/figure6.csv"));
    EXPECT_EQ(figure6.size(), 1 + 4u * 6); // a line a method, six methods
#else
    EXPECT_TRUE(doc["figure6"].is_null());
    EXPECT_NE(doc["gl"].get<std::string>().find("not measured"), std::string::npos);
#endif
    for (const std::string& plot : plots) {
        int width = 0, height = 0, channels = 0;
        unsigned char* png = stbi_load((out + "/" + plot).c_str(), &width, &height, &channels, 4);
        ASSERT_NE(png, nullptr) << plot;
        EXPECT_EQ(width, 1000) << plot;
        EXPECT_EQ(height, 600) << plot;
        stbi_image_free(png);
    }
}

#if VISSORT_WITH_GL
// Without the gl oracle (as on a software renderer by default: minutes a frame there), every
// frame is still ordered through the cpu oracle and rendered.
TEST_F(Cli, BenchPaperGlFramesZeroLeavesTheGlOracleOut) {
    const std::string out = path("paper");
    const RunResult r =
        run({"bench", "paper", "--quick", "--frames", "2", "--gl-frames", "0", "--out", out}, 60);
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("the gl oracle not measured (--gl-frames 0)"), std::string::npos) << r;
    const json doc = json::parse(readFile(out + "/paper.json"));
    EXPECT_EQ(doc["gl_frames"], 0);
    for (const json& path : doc["paths"]) {
        ASSERT_EQ(path["frames"].size(), 2u);
        for (const json& frame : path["frames"]) {
            EXPECT_TRUE(frame["gl_queries"].is_null()) << frame;
            EXPECT_GT(frame["cpu_queries"].get<uint64_t>(), 0u) << frame;
            EXPECT_TRUE(frame["render_ms"].is_number()) << frame;
        }
    }
}
#endif

TEST_F(Cli, BenchPaperBadOptionsAreOneLineErrors) {
    expectError({"bench", "paper", "--frames", "1", "--out", path("p")}, kUsage, {"--frames"});
    expectError({"bench", "paper", "--gl-frames", "-1", "--out", path("p")}, kUsage,
                {"--gl-frames"});
    expectError({"bench", "paper", "--size", "0x5", "--out", path("p")}, kUsage, {"size"});
    std::ofstream(path("file")) << "x";
    expectError({"bench", "paper", "--quick", "--out", path("file") + "/below"}, kFailure,
                {"--out", "cannot create"});
}

} // namespace
} // namespace vissort
