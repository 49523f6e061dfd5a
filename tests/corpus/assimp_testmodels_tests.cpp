// The sweep over Debian's assimp-testmodels (apt install assimp-testmodels: about 600 files of
// assimp's own test models in /usr/share/assimp/models, some broken on purpose): every file
// assimp can read by its extension goes through the corpus checks (corpus_harness.h), one test
// per file. Each must be either refused in one line naming it, or loaded and pass every check.
// Where the folder is absent the test is skipped, not failed. VISSORT_ASSIMP_MODELS names
// another folder. How to run it: docs/robustness.md, "Corpus".

#include <assimp/Importer.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <sys/resource.h>
#include <vector>

#include "corpus_harness.h"

namespace vissort {
namespace {

namespace fs = std::filesystem;

// The most address space a file may take: a loader that trusts a count in the file (a header
// announcing 10^11 vertices) then fails to allocate instead of taking the machine's memory.
constexpr rlim_t kAddressSpaceLimit = rlim_t(8) << 30;

fs::path modelsFolder() {
    const char* folder = std::getenv("VISSORT_ASSIMP_MODELS");
    return folder && *folder ? fs::path(folder) : fs::path("/usr/share/assimp/models");
}

struct Model {
    std::string name;     // the test's name, from the relative path
    std::string relative; // path under the folder
};

void PrintTo(const Model& model, std::ostream* out) {
    *out << model.relative;
}

// Every regular file whose extension assimp reads, sorted, named after its path.
std::vector<Model> models() {
    std::vector<Model> found;
    const fs::path folder = modelsFolder();
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return found;
    Assimp::Importer importer;
    for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (!it->is_regular_file(ec))
            continue;
        std::string extension = it->path().extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        if (extension.empty() || !importer.IsExtensionSupported(extension))
            continue;
        found.push_back({{}, fs::relative(it->path(), folder).string()});
    }
    std::sort(found.begin(), found.end(),
              [](const Model& a, const Model& b) { return a.relative < b.relative; });
    std::set<std::string> names;
    for (Model& model : found) {
        std::string name;
        for (char c : model.relative)
            name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        while (!names.insert(name).second)
            name += "_";
        model.name = name;
    }
    return found;
}

class AssimpTestModels : public testing::TestWithParam<Model> {
protected:
    static void SetUpTestSuite() {
        rlimit limit{};
        getrlimit(RLIMIT_AS, &limit);
        if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur > kAddressSpaceLimit) {
            limit.rlim_cur = kAddressSpaceLimit;
            setrlimit(RLIMIT_AS, &limit);
        }
    }
};

TEST_P(AssimpTestModels, FileIsCheckedOrRefusedCleanly) {
    const std::string path = (modelsFolder() / GetParam().relative).string();
    test::CorpusSettings settings;
    settings.width = 128;
    settings.height = 96;
    const test::CorpusReport report = test::checkCorpusFile(path, settings);
    RecordProperty("report", test::describe(report));
    std::cout << test::describe(report) << '\n';
    EXPECT_TRUE(report.failures.empty()) << test::describe(report);
    // A refusal for want of memory is the limit above speaking, not the loader.
    EXPECT_EQ(report.load_error.find("bad_alloc"), std::string::npos)
        << "ran out of the test's " << (kAddressSpaceLimit >> 30) << " GiB: " << report.load_error;
}

INSTANTIATE_TEST_SUITE_P(Files, AssimpTestModels, testing::ValuesIn(models()),
                         [](const testing::TestParamInfo<Model>& info) { return info.param.name; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(AssimpTestModels);

TEST(AssimpTestModelsFolder, Present) {
    if (models().empty())
        GTEST_SKIP() << "no model files in " << modelsFolder().string()
                     << " (apt install assimp-testmodels, or set VISSORT_ASSIMP_MODELS)";
    SUCCEED();
}

} // namespace
} // namespace vissort
