// Replays every kept fuzz input (tests/fuzz/corpus/<target>/: the seeds and what the fuzzers
// found interesting; tests/fuzz/crashes/<target>/: inputs that once crashed, hung or leaked)
// through the fuzz targets' entry points, in the normal build: each must be handled again.

#include "fuzz_entry_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace vissort {
namespace {

namespace fs = std::filesystem;

const fs::path kFuzzData = fs::path(VISSORT_SOURCE_DIR) / "tests" / "fuzz";

std::vector<fs::path> filesIn(const fs::path& folder) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.is_regular_file() && entry.path().filename() != ".gitkeep")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string readBytes(const fs::path& path) {
    std::ifstream stream(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

void replay(const fuzz::Target& target, const fs::path& folder) {
    for (const fs::path& file : filesIn(folder)) {
        SCOPED_TRACE(file.string());
        const std::string bytes = readBytes(file);
        target.run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    }
}

TEST(FuzzReplay, EveryTargetHasASeedCorpus) {
    for (const fuzz::Target& target : fuzz::targets()) {
        SCOPED_TRACE(target.name);
        EXPECT_FALSE(filesIn(kFuzzData / "corpus" / target.name).empty());
    }
}

TEST(FuzzReplay, CorpusInputsAreHandled) {
    for (const fuzz::Target& target : fuzz::targets())
        replay(target, kFuzzData / "corpus" / target.name);
}

TEST(FuzzReplay, CrashReproducersAreHandled) {
    for (const fuzz::Target& target : fuzz::targets())
        replay(target, kFuzzData / "crashes" / target.name);
}

} // namespace
} // namespace vissort
