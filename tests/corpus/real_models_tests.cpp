// Real files that nobody on this project wrote, shipped in assets/models with their attribution
// (assets/models/SOURCES.md), through the corpus harness (corpus_harness.h): ordered with no
// ground-truth violation, cycles equal to the exact oracle's strongly connected components, and
// rendered all-transparent exactly as the per-pixel linked lists render them.

#include <zlib.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "corpus_harness.h"

namespace vissort {
namespace {

// Unpacks a gzipped asset into a fresh temporary folder and returns the unpacked file's path.
std::string unpackAsset(const std::string& gz_name, const std::string& name) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                         ("vissort-real-models-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::string target = (folder / name).string();
    const std::string source = std::string(VISSORT_SOURCE_DIR) + "/assets/models/" + gz_name;
    gzFile in = gzopen(source.c_str(), "rb");
    if (!in)
        return {};
    std::ofstream out(target, std::ios::binary);
    char buffer[1 << 16];
    int read = 0;
    while ((read = gzread(in, buffer, sizeof buffer)) > 0)
        out.write(buffer, read);
    gzclose(in);
    return read < 0 ? std::string() : target;
}

// Issue 14's first case: at b7aef41 the cpu oracle found one cycle of 257 of the house's 294
// objects at this view, where the exact oracle finds three, of 71, 125 and 19 (faces touching
// all over the model: walls on slabs, windows in walls).
TEST(RealModels, FzkHouseHasTheExactCyclesAndExactTransparency) {
    const std::string path = unpackAsset("AC14-FZK-Haus.ifc.gz", "AC14-FZK-Haus.ifc");
    ASSERT_FALSE(path.empty()) << "could not unpack assets/models/AC14-FZK-Haus.ifc.gz";
    test::CorpusSettings settings;
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.ortho_direction = {-0.3, -0.5, -1};
    settings.views = {{"ortho(-0.3,-0.5,-1)", camera}};
    // Object level, the case. At triangle level the cpu oracle's components differ from
    // the exact ones by a few triangles whose edges pass within the snap distance of a pixel
    // centre (coverage, not depth: docs/robustness.md, "Where it stands").
    settings.levels = {OrderLevel::object};
    settings.width = settings.height = 256;
    const test::CorpusReport report = test::checkCorpusFile(path, settings);
    std::filesystem::remove_all(std::filesystem::path(path).parent_path());
    ASSERT_TRUE(report.loaded) << test::describe(report);
    EXPECT_EQ(report.objects, 294u);
    EXPECT_TRUE(report.failures.empty()) << test::describe(report);
    EXPECT_EQ(report.max_cycle, 125u) << test::describe(report);
    EXPECT_GT(report.pairs_checked, 0u);
}

} // namespace
} // namespace vissort
