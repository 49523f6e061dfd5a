// Every file a command writes is checked before any work (issue 35): a folder that does not
// exist, a path that is a folder, a folder that is a file. The error names the option, the path
// and the reason, and nothing is computed (nothing printed, fast even for the power plant).

#include <fstream>
#include <string>
#include <vector>

#include "cli_fixture.h"

namespace vissort {
namespace {

struct BadOutput {
    std::vector<std::string> args; // the command with the bad path last
    std::string option;
    std::string reason;
};

TEST_F(Cli, OutputPathsAreCheckedBeforeAnyWork) {
    const std::string missing = path("no/such/folder/out");
    const std::string folder = path("");
    std::ofstream(path("a_file")) << "not a folder\n";
    const std::string under_a_file = path("a_file/out.json");
    std::vector<BadOutput> cases = {
        {{"order", "builtin:powerplant", "--frames", "300", "--json", missing + ".json"},
         "--json",
         "does not exist"},
        {{"order", "builtin:powerplant", "--csv", missing + ".csv"}, "--csv", "does not exist"},
        {{"order", "builtin:bunnies", "--dump-primitives", folder},
         "--dump-primitives",
         "it is a folder"},
        {{"info", "builtin:bunnies", "--json", under_a_file}, "--json", "is not a folder"},
        {{"collide", "builtin:bunnies", "--frames", "300", "--pairs-out", missing + ".txt"},
         "--pairs-out",
         "does not exist"},
        {{"collide", "builtin:bunnies", "--csv", folder}, "--csv", "it is a folder"},
        {{"bench", "collision", "--plot", missing + ".png"}, "--plot", "does not exist"},
    };
#if VISSORT_WITH_GL
    cases.push_back({{"render", "builtin:powerplant", "--frames", "30", "-o", missing + "%d.png"},
                     "-o",
                     "does not exist"});
    cases.push_back({{"render", "builtin:bunnies", "-o", path("ok.png"), "--reference",
                      "linked-list", "--error-map", under_a_file},
                     "--error-map",
                     "is not a folder"});
    cases.push_back({{"view", "builtin:bunnies", "--screenshot", missing + ".png"},
                     "--screenshot",
                     "does not exist"});
#endif
    for (const BadOutput& c : cases) {
        SCOPED_TRACE(c.args[0] + " " + c.option);
        expectError(c.args, kFailure, {c.option + ": cannot write '", c.reason});
        EXPECT_TRUE(run(c.args).out.empty()); // nothing done, nothing printed
    }
    // Standard output and a folder that exists are fine.
    EXPECT_EQ(run({"order", "builtin:bunnies?n=2", "--json", "-", "--quiet"}).code, 0);
    EXPECT_EQ(run({"order", "builtin:bunnies?n=2", "--json", path("fine.json"), "--quiet"}).code,
              0);
}

} // namespace
} // namespace vissort
