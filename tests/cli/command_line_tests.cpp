// The command line as issue 17 found it and as it is now: each test below failed before the
// change it names. Mistyped commands and options get the nearest name; repeated options and
// non-numbers say so; options a command ignored are gone; JSON goes to standard output with
// `--json -` and is compact unless --pretty; the output counts in words with units, names the
// objects of each cycle, and the header comes before the frames.

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "cli_fixture.h"

namespace vissort {
namespace {

const std::string kSticksAndBox = dataPath("scenes/three_sticks_and_box.json");

std::size_t countOf(const std::string& text, char c) {
    return std::size_t(std::count(text.begin(), text.end(), c));
}

TEST_F(Cli, HelpAndUnknownCommandsAreAnsweredAsPeopleTypeThem) {
    const RunResult help = run({"help"});
    EXPECT_EQ(help.code, 0) << help;
    EXPECT_NE(help.out.find("Usage: vissort"), std::string::npos) << help;
    const RunResult render_help = run({"help", "render"});
    EXPECT_EQ(render_help.code, 0) << render_help;
    EXPECT_NE(render_help.out.find("--method"), std::string::npos) << render_help;
    expectError({"ordr", "x"}, kUsage, {"unknown command 'ordr'", "did you mean 'order'"});
    expectError({"help", "rendr"}, kUsage, {"unknown command 'rendr'", "did you mean 'render'"});
    expectError({"--frobnicate"}, kUsage, {"unknown option '--frobnicate'"});
}

TEST_F(Cli, UnknownOptionsSuggestTheNearestAndTheCommandsHelp) {
    expectError({"order", kSticksAndBox, "--levle", "triangle"}, kUsage,
                {"unknown option '--levle'", "did you mean '--level'", "vissort order --help"});
    expectError({"info", kSticksAndBox, "--jsn", "x.json"}, kUsage,
                {"'--jsn'", "'--json'", "vissort info --help"});
    // Far from every option: no suggestion, still the command's help.
    expectError({"order", kSticksAndBox, "--zzzzzzzz"}, kUsage,
                {"unknown option '--zzzzzzzz'", "vissort order --help"});
    const RunResult far = run({"order", kSticksAndBox, "--zzzzzzzz"});
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far;
}

TEST_F(Cli, RepeatedOptionsAndNonNumbersSaySo) {
    expectError({"order", kSticksAndBox, "--size", "10x10", "--size", "20x20"}, kUsage,
                {"--size was given 2 times", "give it once"});
    expectError({"order", kSticksAndBox, "--fov", "abc"}, kUsage,
                {"--fov expects a number, got 'abc'"});
    expectError({"order", kSticksAndBox, "--frames", "2.5"}, kUsage,
                {"--frames expects a whole number, got '2.5'"});
}

TEST_F(Cli, VersionIsPrinted) {
    const RunResult r = run({"--version"});
    EXPECT_EQ(r.code, 0) << r;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(^vissort \d+\.\d+\.\d+)"))) << r;
}

TEST_F(Cli, InfoTakesNoFramesOrPath) {
    expectError({"info", kSticksAndBox, "--frames", "3"}, kUsage, {"unknown option '--frames'"});
    expectError({"info", kSticksAndBox, "--path", "orbit"}, kUsage, {"unknown option '--path'"});
}

TEST_F(Cli, JsonDashGoesToStandardOutputAlone) {
    const RunResult r = run({"order", kSticksAndBox, "--size", "64x64", "--json", "-"});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_FALSE(std::filesystem::exists(path("-"))) << "a file named '-' was written";
    const json document = json::parse(r.out); // nothing else on standard output
    EXPECT_EQ(document["order"].size(), 4u);
    EXPECT_NE(r.err.find("order (front to back)"), std::string::npos) << r; // the text moved
}

TEST_F(Cli, JsonIsCompactUnlessPretty) {
    const std::vector<std::string> args = {"order",    kSticksAndBox, "--size", "64x64",
                                           "--frames", "3",           "--json"};
    std::vector<std::string> compact = args, pretty = args;
    compact.push_back(path("compact.json"));
    pretty.push_back(path("pretty.json"));
    pretty.push_back("--pretty");
    ASSERT_EQ(run(compact).code, 0);
    ASSERT_EQ(run(pretty).code, 0);
    const std::string one_line = readFile(path("compact.json")),
                      indented = readFile(path("pretty.json"));
    EXPECT_EQ(countOf(one_line, '\n'), 1u); // the final newline only
    EXPECT_GT(countOf(indented, '\n'), 20u);
    const json a = json::parse(one_line), b = json::parse(indented);
    EXPECT_EQ(a["order"], b["order"]);
    EXPECT_EQ(a["cycles"], b["cycles"]);
    EXPECT_EQ(a["frames"].size(), b["frames"].size());
}

TEST_F(Cli, OrderOutputCountsInWordsWithUnitsAndNamesTheCycles) {
    const RunResult r = run({"order", kSticksAndBox, "--size", "64x64"});
    ASSERT_EQ(r.code, 0) << r;
    EXPECT_NE(r.out.find("4 objects, 48 triangles"), std::string::npos) << r;
    EXPECT_NE(r.out.find(", 1 frame\n"), std::string::npos) << r;
    EXPECT_NE(r.out.find("cycle 0 (3 objects): 0 'stick_a' 1 'stick_b' 2 'stick_c'"),
              std::string::npos)
        << r;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(\d+ queries, \d+ draws, \d+\.\d+ ms)")))
        << r;
    const RunResult one = run({"order", dataPath("scenes/disjoint.json"), "--size", "64x64",
                               "--level", "object", "--frames", "2"});
    ASSERT_EQ(one.code, 0) << one;
    EXPECT_EQ(one.out.find("1 cycles"), std::string::npos) << one;
    EXPECT_EQ(one.out.find(" 1 iterations"), std::string::npos) << one;
    // The header first, then the frames.
    const std::size_t header = one.out.find("disjoint.json: "), frame = one.out.find("frame 0: ");
    ASSERT_NE(header, std::string::npos) << one;
    ASSERT_NE(frame, std::string::npos) << one;
    EXPECT_LT(header, frame) << one;
}

// The scenes examples/scenes/ ships (README, docs/scene-format.md) load and order from a clean
// clone: their mesh paths resolve inside the repository.
TEST_F(Cli, EveryExampleSceneLoadsAndOrders) {
    std::size_t scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(VISSORT_SOURCE_DIR) +
                                                                 "/examples/scenes")) {
        if (entry.path().extension() != ".json")
            continue;
        ++scenes;
        const RunResult r = run({"order", entry.path().string(), "--size", "96x72"});
        EXPECT_EQ(r.code, 0) << r;
        EXPECT_TRUE(r.err.empty()) << r;
    }
    EXPECT_GE(scenes, 3u);
}

// The long names of the options a command's --help lists ("  -o,--output TEXT ..." -> --output).
std::set<std::string> helpOptions(const std::string& help) {
    std::set<std::string> names;
    static const std::regex option(R"(^  (?:-[a-zA-Z],)?(--[a-z][a-z0-9-]*))");
    std::istringstream lines(help);
    for (std::string line; std::getline(lines, line);) {
        std::smatch match;
        if (std::regex_search(line, match, option) && match[1] != "--help")
            names.insert(match[1]);
    }
    return names;
}

// The options docs/cli.md's table lists under "## `vissort COMMAND`" ("| `--size WxH` |").
std::set<std::string> documentedOptions(const std::string& doc, const std::string& command) {
    std::set<std::string> names;
    const std::string heading = "## `vissort " + command + "`";
    const std::size_t start = doc.find(heading);
    if (start == std::string::npos)
        return names;
    const std::size_t end = doc.find("\n## ", start + heading.size());
    std::istringstream lines(doc.substr(start, end - start));
    static const std::regex row(R"(^\| `(?:-[a-zA-Z], )?(--[a-z][a-z0-9-]*))");
    for (std::string line; std::getline(lines, line);) {
        std::smatch match;
        if (std::regex_search(line, match, row))
            names.insert(match[1]);
    }
    return names;
}

// docs/cli.md documents every option of every command, and no option a command lacks.
TEST_F(Cli, EveryCommandsHelpAgreesWithDocsCli) {
    const std::string doc = readFile(std::string(VISSORT_SOURCE_DIR) + "/docs/cli.md");
    ASSERT_FALSE(doc.empty());
    for (const char* command : {"order", "info", "render", "collide", "bench", "view", "volume"}) {
        SCOPED_TRACE(command);
        const RunResult help = run({command, "--help"});
        ASSERT_EQ(help.code, 0) << help;
        const std::set<std::string> listed = helpOptions(help.out);
        EXPECT_GT(listed.size(), 3u) << help;
        EXPECT_EQ(documentedOptions(doc, command), listed);
    }
}

} // namespace
} // namespace vissort
