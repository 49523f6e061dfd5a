// End to end, without OpenGL (VISSORT_WITH_GL=OFF): what needs OpenGL fails with one line naming
// the build, exit code 1, and the rest still works. Built only without VISSORT_WITH_GL.

#include <string>

#include "cli_fixture.h"

namespace vissort {
namespace {

const std::string kWithoutGl = "this vissort was built without OpenGL (VISSORT_WITH_GL=OFF)";

TEST_F(Cli, RenderNeedsOpenGl) {
    expectError({"render", "builtin:bunnies?n=2", "--size", "32x32", "-o", path("a.png")}, kFailure,
                {kWithoutGl, "render is not available"});
    EXPECT_FALSE(fs::exists(path("a.png")));
    // Whatever the options, the same line: not a usage error about a missing -o.
    expectError({"render", "builtin:bunnies?n=2"}, kFailure, {kWithoutGl, "render"});
}

TEST_F(Cli, BenchTransparencyAndInfoGlNeedOpenGl) {
    expectError({"bench", "transparency"}, kFailure, {kWithoutGl, "bench transparency"});
    expectError({"info", "--gl"}, kFailure, {kWithoutGl, "info --gl"});
    expectError({"order", "builtin:bunnies?n=2", "--size", "32x32", "--oracle", "gl"}, kFailure,
                {"VISSORT_WITH_GL=OFF"});
    const RunResult cpu = run({"order", "builtin:bunnies?n=2", "--size", "32x32"});
    EXPECT_EQ(cpu.code, 0) << cpu;
}

} // namespace
} // namespace vissort
