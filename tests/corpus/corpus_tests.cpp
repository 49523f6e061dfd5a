// The corpus test (issue 14): at least 30 real-world-style files in at least 10 formats, written
// by the test itself (corpus_files.h), with touching and coplanar geometry, interpenetration,
// nesting, node hierarchies and transparent materials, and broken files. Each good file must load
// with the triangles its model has and pass every check of corpus_harness.h at every view and
// level: ground-truth order, cycles equal to the exact oracle's strongly connected components,
// vissort's transparency equal to linked-list's; each broken file must be refused with one line
// naming it. No file may crash or hang the process (ctest's TIMEOUT stops a hang).

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <unistd.h>

#include "corpus_files.h"
#include "corpus_harness.h"

namespace vissort {
namespace {

namespace fs = std::filesystem;
using test::CorpusFile;

// This process's folder for the files, removed when the tests end.
class CorpusFolder : public testing::Environment {
public:
    static const fs::path& path() {
        static const fs::path folder =
            fs::temp_directory_path() / ("vissort-corpus-" + std::to_string(getpid()));
        return folder;
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(path(), ignored);
    }
};
const testing::Environment* const kFolder = testing::AddGlobalTestEnvironment(new CorpusFolder);

} // namespace
} // namespace vissort

namespace vissort::test {
// Readable parameters in test logs.
void PrintTo(const CorpusFile& file, std::ostream* out) {
    *out << file.file << " (" << file.format << ")";
}
} // namespace vissort::test

namespace vissort {
namespace {

class Corpus : public testing::TestWithParam<CorpusFile> {};

TEST_P(Corpus, FileIsCheckedOrRefusedCleanly) {
    const CorpusFile& file = GetParam();
    fs::create_directories(CorpusFolder::path());
    const std::string written = file.write(CorpusFolder::path());
    ASSERT_TRUE(written.empty()) << written;
    const std::string path = (CorpusFolder::path() / file.file).string();
    SCOPED_TRACE(file.format);

    const test::CorpusReport report = test::checkCorpusFile(path);
    RecordProperty("report", test::describe(report));
    if (file.broken) {
        EXPECT_FALSE(report.loaded) << "a broken file was accepted: " << test::describe(report);
        EXPECT_TRUE(report.failures.empty()) << test::describe(report);
        return;
    }
    ASSERT_TRUE(report.loaded) << test::describe(report);
    EXPECT_EQ(report.triangles, file.triangles) << "the file does not hold the model's triangles";
    // The views show occlusions: the ground truth had something to check.
    EXPECT_GT(report.pairs_checked, 0u);
    EXPECT_TRUE(report.failures.empty()) << test::describe(report);
}

INSTANTIATE_TEST_SUITE_P(Files, Corpus, testing::ValuesIn(test::corpusFiles()),
                         [](const testing::TestParamInfo<CorpusFile>& info) {
                             return info.param.name;
                         });

// What the issue asks of the corpus: 30 good files in 10 formats, and broken ones.
TEST(CorpusCatalogue, ThirtyFilesInTenFormatsAndBrokenOnes) {
    std::set<std::string> extensions, names;
    std::size_t good = 0, broken = 0;
    for (const CorpusFile& file : test::corpusFiles()) {
        EXPECT_TRUE(names.insert(file.file).second) << "two files named " << file.file;
        if (file.broken) {
            ++broken;
            continue;
        }
        ++good;
        extensions.insert(fs::path(file.file).extension().string());
    }
    EXPECT_GE(good, 30u);
    EXPECT_GE(extensions.size(), 10u);
    EXPECT_GE(broken, 10u);
}

} // namespace
} // namespace vissort
