// End-to-end tests of `vissort collide` and `vissort bench collision`: the vissort method's
// pairs against brute force's over many frames, the documented outputs, and one-line errors.

#include <algorithm>
#include <sstream>

#include <stb/stb_image.h>

#include "cli_fixture.h"

namespace vissort {
namespace {

const std::string kInterpenetrating = dataPath("scenes/interpenetrating.json");

// The lines of a --pairs-out file, each checked to read "FRAME A B" with A < B.
std::vector<std::string> pairLines(const std::string& text) {
    const std::vector<std::string> all = lines(text);
    for (const std::string& line : all) {
        std::istringstream in(line);
        long frame = -1, a = -1, b = -1;
        std::string rest;
        EXPECT_TRUE(in >> frame >> a >> b) << line;
        EXPECT_FALSE(in >> rest) << line;
        EXPECT_GE(frame, 0) << line;
        EXPECT_LT(a, b) << line;
    }
    return all;
}

TEST_F(Cli, CollideMatchesBruteForceOver300FramesOfBunnies) {
    for (const char* method : {"vissort", "brute"}) {
        const RunResult r = run({"collide", "builtin:bunnies?n=18", "--frames", "300", "--method",
                                 method, "--pairs-out", path(std::string(method) + ".txt")},
                                /*timeout_seconds=*/400); // brute force: 8 s in a release build
        ASSERT_EQ(r.code, 0) << r;
        EXPECT_NE(r.out.find("300 frames"), std::string::npos) << r;
    }
    const std::string vissort = readFile(path("vissort.txt")), brute = readFile(path("brute.txt"));
    const std::vector<std::string> pairs = pairLines(brute);
    EXPECT_GT(pairs.size(), 300u * 500) << "the bunnies collide every frame";
    EXPECT_TRUE(
        std::is_sorted(pairs.begin(), pairs.end(), [](const std::string& p, const std::string& q) {
            long fp, ap, bp, fq, aq, bq;
            std::istringstream(p) >> fp >> ap >> bp;
            std::istringstream(q) >> fq >> aq >> bq;
            return std::tie(fp, ap, bp) < std::tie(fq, aq, bq);
        }));
    EXPECT_TRUE(vissort == brute) << "vissort and brute force disagree on some pair";
}

TEST_F(Cli, EveryExactMethodAgreesOnRealMeshes) {
    std::string expected;
    for (const char* method : {"brute", "vissort", "bullet"}) {
        const RunResult r = run(
            {"collide", kInterpenetrating, "--method", method, "--pairs-out", path("pairs.txt")});
        ASSERT_EQ(r.code, 0) << r;
        const std::string pairs = readFile(path("pairs.txt"));
        if (expected.empty())
            expected = pairs;
        EXPECT_EQ(pairs, expected) << method;
    }
    EXPECT_GT(pairLines(expected).size(), 20u);
    const RunResult fcl = run({"collide", kInterpenetrating, "--method", "fcl"});
    EXPECT_EQ(fcl.code, 0) << fcl;
}

TEST_F(Cli, CollideJsonHasEveryDocumentedKey) {
    const RunResult r = run({"collide", "builtin:bunnies?n=6", "--frames", "3", "--json",
                             path("c.json"), "--size", "32x16", "--threads", "2"});
    ASSERT_EQ(r.code, 0) << r;
    const json doc = json::parse(readFile(path("c.json")));
    EXPECT_EQ(doc.value("method", json()), "vissort");
    EXPECT_EQ(doc.value("size", json()), json({32, 16}));
    ASSERT_EQ(doc["frames"].size(), 3u);
    for (int f = 0; f < 3; ++f) {
        const json& frame = doc["frames"][f];
        EXPECT_EQ(frame.value("frame", -1), f);
        for (const char* key : {"object_pairs", "triangle_pairs", "intersecting"})
            EXPECT_TRUE(frame.contains(key) && frame[key].is_number_unsigned()) << key;
        EXPECT_GE(frame["triangle_pairs"].get<uint64_t>(), frame["intersecting"].get<uint64_t>());
        for (const char* key : {"update", "cull", "exact", "total"})
            EXPECT_GE(frame["ms"].value(key, -1.0), 0.0) << key;
    }
}

// The colliding objects by id and name (issue 35): the two crossed bars and not the box apart,
// in the text, the JSON (ids into "objects") and the CSV's count; checked against the pairs of
// --pairs-out mapped to their objects here.
TEST_F(Cli, CollideSaysWhichObjectsCollide) {
    const std::string scene =
        std::string(VISSORT_SOURCE_DIR) + "/tests/data/scenes/crossed_bars.json";
    const RunResult r = run({"collide", scene, "--json", path("c.json"), "--csv", path("c.csv"),
                             "--pairs-out", path("pairs.txt")});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("colliding objects: 1 pair: 0 'bar_x' and 1 'bar_y'\n"), std::string::npos)
        << r;
    const json doc = json::parse(readFile(path("c.json")));
    EXPECT_EQ(doc["objects"], json({"bar_x", "bar_y", "box"}));
    const json& frame = doc["frames"][0];
    EXPECT_EQ(frame["object_pairs_colliding"], json::parse("[[0, 1]]"));
    EXPECT_EQ(frame.value("colliding_object_pairs", -1), 1);
    EXPECT_GE(frame.value("candidate_objects", -1), 2);
    // Every triangle pair lies between the bars: 12 triangles each, in file order.
    int pairs = 0;
    for (const std::string& line : lines(readFile(path("pairs.txt")))) {
        std::istringstream words(line);
        int f = -1, a = -1, b = -1;
        words >> f >> a >> b;
        EXPECT_TRUE(a < 12 && b >= 12 && b < 24) << line;
        ++pairs;
    }
    EXPECT_GT(pairs, 0);
    const std::vector<std::string> rows = lines(readFile(path("c.csv")));
    ASSERT_EQ(rows.size(), 2u);
    const auto fields = [](const std::string& row) {
        std::vector<std::string> out;
        std::istringstream cells(row);
        for (std::string cell; std::getline(cells, cell, ',');)
            out.push_back(cell);
        return out;
    };
    const std::vector<std::string> header = fields(rows[0]), values = fields(rows[1]);
    const auto column = std::find(header.begin(), header.end(), "colliding_object_pairs");
    ASSERT_NE(column, header.end());
    EXPECT_EQ(values[std::size_t(column - header.begin())], "1");
}

TEST_F(Cli, CollideDumpsOneGroupPerObjectInTriangleOrder) {
    const RunResult r = run({"collide", "builtin:bunnies?n=3", "--dump-primitives", path("d.obj")});
    ASSERT_EQ(r.code, 0) << r;
    int groups = 0, faces = 0;
    for (const std::string& line : lines(readFile(path("d.obj")))) {
        if (line.rfind("o prim_", 0) == 0) {
            EXPECT_EQ(line, "o prim_" + std::to_string(groups++));
        }
        faces += line.rfind("f ", 0) == 0;
    }
    EXPECT_EQ(groups, 3);
    EXPECT_EQ(faces, 3 * 3674);
}

TEST_F(Cli, CollideErrorsAreOneLine) {
    expectError({"collide", "builtin:bunnies", "--method", "gjk"}, kUsage, {"--method", "gjk"});
    expectError({"collide", "builtin:bunnies", "--size", "0x5"}, kUsage, {"--size"});
    expectError({"collide", "builtin:bunnies", "--object-stage", "sometimes"}, kUsage,
                {"--object-stage", "sometimes"});
    expectError({"collide", "builtin:bunnies", "--size", "5000x64"}, kUsage, {"--size"});
    expectError({"collide", "no_such_file.obj"}, kInput, {"no_such_file.obj"});
    expectError({"collide", dataPath("cli/nan_coordinate.obj")}, kInput, {"nan_coordinate.obj"});
    expectError({"collide", "builtin:bunnies", "--pairs-out", "/no/such/dir/p.txt"}, kFailure,
                {"/no/such/dir/p.txt"});
}

TEST_F(Cli, BenchCollisionMeasuresEveryMethod) {
    std::vector<std::string> args = {"bench",    "collision", "--counts", "2,3",
                                     "--frames", "2",         "--json",   path("b.json")};
#if VISSORT_WITH_GL // the PNG writer is in the GL renderer's target for now
    args.insert(args.end(), {"--plot", path("b.png")});
#endif
    const RunResult r = run(args);
    ASSERT_EQ(r.code, 0) << r;
    const json doc = json::parse(readFile(path("b.json")));
    // vissort and bullet at 1 and 2 threads, and brute, for each count.
    ASSERT_EQ(doc["rows"].size(), 2u * 5);
    EXPECT_EQ(doc["speedups"].size(), 2u * 2);
    for (const json& row : doc["rows"]) {
        const std::string method = row.value("method", "");
        EXPECT_GT(row.value("median_ms", 0.0), 0.0) << method;
        if (method != "fcl") {
            EXPECT_EQ(row.value("missed", -1), 0) << method;
            EXPECT_EQ(row.value("invented", -1), 0) << method;
        }
    }
#if VISSORT_WITH_GL
    int width = 0, height = 0, channels = 0;
    unsigned char* png = stbi_load(path("b.png").c_str(), &width, &height, &channels, 4);
    ASSERT_NE(png, nullptr);
    EXPECT_GT(width, 100);
    stbi_image_free(png);
#endif
    expectError({"bench", "collision", "--counts", "0"}, kUsage, {"--counts"});
    expectError({"bench", "collision", "--scene", "soup"}, kUsage, {"--scene", "soup"});
    expectError({"bench", "collision", "--methods", "vissort,gjk"}, kUsage, {"--methods", "gjk"});
    expectError({"bench", "collision", "--threads", "1,0"}, kUsage, {"--threads"});
    expectError({"bench", "collision", "--counts", "5000", "--frames", "1"}, kInput,
                {"builtin:bunnies", "n=5000"});
}

// The pile of small bodies, the methods asked for (brute always: the ground truth), one thread
// count.
TEST_F(Cli, BenchCollisionOnThePileWithChosenMethods) {
    const RunResult r =
        run({"bench", "collision", "--scene", "pile", "--counts", "6", "--frames", "2", "--methods",
             "vissort,fcl", "--threads", "1", "--json", path("pile.json")});
    ASSERT_EQ(r.code, 0) << r;
    const json doc = json::parse(readFile(path("pile.json")));
    EXPECT_EQ(doc.value("scene", ""), "pile");
    std::vector<std::string> methods;
    for (const json& row : doc["rows"]) {
        methods.push_back(row.value("method", ""));
        EXPECT_EQ(row.value("n", 0), 6);
        if (row.value("method", "") != "fcl") {
            EXPECT_EQ(row.value("missed", -1), 0) << row.value("method", "");
        }
    }
    EXPECT_EQ(methods, (std::vector<std::string>{"vissort-1t", "brute", "fcl"}));
    EXPECT_TRUE(doc["speedups"].empty()); // no bullet to compare with
}

} // namespace
} // namespace vissort
