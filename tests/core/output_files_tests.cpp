// No output is an input or another output (output_files.h), on files made here: the command
// line's and Python's end-to-end tests (tests/cli/input_output_cli_tests.cpp,
// python/tests/test_outputs_kept.py) run the same rule through their options.

#include "vissort/output_files.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "scratch_folder.h"

namespace vissort {
namespace {

namespace fs = std::filesystem;

class OutputFilesTest : public testing::Test {
protected:
    std::string path(const std::string& name) const { return (scratch_.path() / name).string(); }
    void put(const std::string& name) const { std::ofstream(path(name)) << name; }

    ScratchFolder scratch_;
};

TEST(FramePattern, OneIntegerFieldNamesEachFrame) {
    EXPECT_TRUE(isFramePattern("out/frame_%04d.png"));
    EXPECT_TRUE(isFramePattern("%d.png"));
    EXPECT_FALSE(isFramePattern("frame.png"));
    EXPECT_FALSE(isFramePattern("%d_%d.png"));
    EXPECT_FALSE(isFramePattern("100%.png"));
    EXPECT_EQ(framePath("out/frame_%04d.png", 7), "out/frame_0007.png");
}

TEST_F(OutputFilesTest, AnInputAmongThePatternsFramesIsNamedWithItsFrame) {
    put("f_0012.obj");
    const OutputFiles outputs({{"-o", path("f_%04d.obj"), 5, 10}}); // frames 10 to 14
    EXPECT_EQ(outputs.clashWith({{"the scene file", path("f_0012.obj")}}),
              "-o '" + path("f_%04d.obj") + "' (frame 12: '" + path("f_0012.obj") +
                  "') is the scene file '" + path("f_0012.obj") +
                  "': vissort never overwrites an input; choose another path");
    // Frames before first_frame and from first_frame + frames on are not the pattern's.
    put("f_0009.obj");
    put("f_0015.obj");
    EXPECT_EQ(outputs.clashWith(
                  {{"the scene file", path("f_0009.obj")}, {"the scene file", path("f_0015.obj")}}),
              "");
}

TEST_F(OutputFilesTest, TwoPatternsSharingAFrameAreOneFileThere) {
    const OutputFiles outputs(
        {{"-o", path("a_%d.png"), 3, 8}, {"--error-map", path("./a_%d.png"), 3, 10}});
    EXPECT_EQ(outputs.clashAmongThemselves(),
              "-o '" + path("a_%d.png") + "' (frame 10: '" + path("a_10.png") +
                  "') and --error-map '" + path("./a_%d.png") + "' (frame 10: '" +
                  path("./a_10.png") + "') are one file: give each output its own path");
    const OutputFiles apart(
        {{"-o", path("a_%d.png"), 3, 0}, {"--error-map", path("a_%d.png"), 3, 3}});
    EXPECT_EQ(apart.clashAmongThemselves(), "");
}

TEST_F(OutputFilesTest, StandardOutputAndSpecialFilesAreNoFiles) {
    const OutputFiles outputs({{"--json", "-"},
                               {"--csv", "-"},
                               {"--json", "/dev/null"},
                               {"--csv", "/dev/null"},
                               {"--x", ""}});
    EXPECT_EQ(outputs.clashAmongThemselves(), "");
    EXPECT_EQ(outputs.clashWith({{"the scene file", "/dev/null"}}), "");
}

TEST_F(OutputFilesTest, AHardLinkIsTheFileAndACopyIsNot) {
    put("scene.obj");
    fs::create_hard_link(path("scene.obj"), path("linked.obj"));
    fs::copy_file(path("scene.obj"), path("copy.obj"));
    const std::vector<FileUse> scene = {{"the scene file", path("scene.obj")}};
    EXPECT_NE(OutputFiles({{"--json", path("linked.obj")}}).clashWith(scene), "");
    EXPECT_EQ(OutputFiles({{"--json", path("copy.obj")}}).clashWith(scene), "");
}

} // namespace
} // namespace vissort
