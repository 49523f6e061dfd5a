// End to end, with OpenGL: the gl oracle and `info --gl` as a user runs them, and their one-line
// errors when no context can be made. Built only with VISSORT_WITH_GL.

#include <cstdlib>
#include <string>

#include "cli_fixture.h"

namespace vissort {
namespace {

const std::string kBunnies = "builtin:bunnies?n=4";

// The gl oracle gives the cpu oracle's order (tests/gl checks why they agree), named in the JSON.
TEST_F(Cli, GlOracleOrdersAsCpu) {
    const json cpu = orderJson({kBunnies, "--size", "64x48"}, "cpu.json");
    const json gl = orderJson({kBunnies, "--size", "64x48", "--oracle", "gl"}, "gl.json");
    EXPECT_EQ(gl.value("oracle", json()), "gl");
    EXPECT_EQ(gl["order"], cpu["order"]);
    EXPECT_EQ(gl["cycles"], cpu["cycles"]);
    EXPECT_EQ(gl["stats"]["queries"], cpu["stats"]["queries"]);
}

TEST_F(Cli, InfoGlNamesTheDriver) {
    const RunResult r = run({"info", "--gl"});
    ASSERT_EQ(r.code, 0) << r;
    for (const char* field : {"OpenGL: 4.", "renderer: ", "vendor: ", "EGL platform: "})
        EXPECT_NE(r.out.find(field), std::string::npos) << field << r;
    // With a scene too: both reports.
    const RunResult both = run({"info", "--gl", kBunnies});
    ASSERT_EQ(both.code, 0) << both;
    EXPECT_NE(both.out.find("renderer: "), std::string::npos) << both;
    EXPECT_NE(both.out.find("triangles: "), std::string::npos) << both;
}

// No OpenGL context (here: an EGL platform that does not exist): one line naming the problem for
// every command that needs one, and the cpu oracle still works.
TEST_F(Cli, ErrorNoGlContext) {
    ASSERT_EQ(setenv("VISSORT_GL_PLATFORM", "wayland", 1), 0);
    expectError({"order", kBunnies, "--size", "32x32", "--oracle", "gl"}, kFailure,
                {"VISSORT_GL_PLATFORM", "wayland"});
    expectError({"info", "--gl"}, kFailure, {"VISSORT_GL_PLATFORM", "wayland"});
    const RunResult cpu = run({"order", kBunnies, "--size", "32x32"});
    unsetenv("VISSORT_GL_PLATFORM");
    EXPECT_EQ(cpu.code, 0) << cpu;
}

} // namespace
} // namespace vissort
