// End to end: --lod-error as users give it to `render` and `order`: 0 is the output without
// levels, byte for byte; a bound draws and orders fewer triangles and says so; the orders are
// permutations of the objects; bad values are one-line usage errors.

#include <string>
#include <vector>

#include "cli_fixture.h"

namespace vissort {
namespace {

const std::string kPlant = "builtin:powerplant?scale=0.05";

TEST_F(Cli, OrderWithLevelsOfDetailOrdersEveryObjectAndSaysWhatItOrdered) {
    const RunResult r = run({"order", kPlant, "--path", "scene", "--frames", "3", "--size",
                             "160x120", "--lod-error", "2", "--json", path("o.json")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("levels of detail within 2 px"), std::string::npos) << r;
    EXPECT_NE(r.out.find("triangles ordered ("), std::string::npos) << r;
    const json doc = json::parse(readFile(path("o.json")));
    std::vector<uint32_t> order = doc["order"].get<std::vector<uint32_t>>();
    std::sort(order.begin(), order.end());
    ASSERT_EQ(order.size(), 344u); // every object of the plant, those out of view last
    for (uint32_t i = 0; i < order.size(); ++i)
        ASSERT_EQ(order[i], i);
    // Without levels: the same objects, and the plain header.
    const RunResult plain =
        run({"order", kPlant, "--size", "160x120", "--lod-error", "0", "--json", path("p.json")});
    ASSERT_EQ(plain.code, 0) << plain;
    EXPECT_EQ(plain.out.find("levels of detail"), std::string::npos) << plain;
}

#if VISSORT_WITH_GL
TEST_F(Cli, RenderWithLevelsOfDetailZeroIsTheRenderWithout) {
    const std::vector<std::string> common = {"render",   kPlant, "--path", "scene",
                                             "--frames", "2",    "--size", "160x120"};
    std::vector<std::string> plain = common, zero = common, bound = common;
    plain.insert(plain.end(), {"-o", path("a%d.png")});
    zero.insert(zero.end(), {"-o", path("b%d.png"), "--lod-error", "0"});
    bound.insert(bound.end(), {"-o", path("c%d.png"), "--lod-error", "2", "--json", path("c.json"),
                               "--reference", "linked-list"});
    for (const auto& args : {plain, zero, bound}) {
        const RunResult r = run(args);
        ASSERT_EQ(r.code, 0) << r;
    }
    for (int f = 0; f < 2; ++f)
        EXPECT_EQ(readFile(path("a" + std::to_string(f) + ".png")),
                  readFile(path("b" + std::to_string(f) + ".png")))
            << "frame " << f;
    const json doc = json::parse(readFile(path("c.json")));
    for (const json& frame : doc["frames"]) {
        EXPECT_LT(frame["triangles"].get<uint64_t>(), 120004u) << frame;
        EXPECT_GT(frame["culled_objects"].get<uint64_t>(), 0u) << frame;
        // linked-list draws the same levels: the exact picture of the same geometry.
        EXPECT_LE(frame["error"]["max_abs"].get<int>(), 1) << frame;
    }
}
#endif

TEST_F(Cli, LevelOfDetailErrorsNameTheOption) {
    for (const char* bad : {"-1", "inf"})
        expectError({"order", kPlant, "--lod-error", bad}, kUsage, {"--lod-error", bad});
    expectError({"order", kPlant, "--lod-error", "1e9"}, kUsage, {"--lod-error", "up to 1e6"});
    expectError({"order", kPlant, "--lod-error", "abc"}, kUsage, {"--lod-error"});
#if VISSORT_WITH_GL
    expectError({"render", kPlant, "-o", path("x.png"), "--lod-error", "-2"}, kUsage,
                {"--lod-error", "-2"});
#endif
    expectError({"bench", "paper", "--lod-error", "-1", "--out", path("p")}, kUsage,
                {"--lod-error"});
}

} // namespace
} // namespace vissort
