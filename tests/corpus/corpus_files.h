#pragma once
// The corpus: every file the corpus test writes and checks, good ones (the models of
// corpus_models.h in assimp's exported formats and hand-written text formats) and broken ones
// (empty, garbage, truncated, NaN coordinates, wrong counts) that must be refused in one line.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vissort::test {

struct CorpusFile {
    std::string name;   // the test's name: letters, digits and '_'
    std::string file;   // file name in the corpus folder
    std::string format; // how it was written, e.g. "collada (assimp exporter)"
    bool broken = false;
    std::size_t triangles = 0; // good files: the model's triangles once polygons are fanned
    /// Writes the file (and any file it refers to) into a folder; empty or a one-line error.
    std::function<std::string(const std::filesystem::path& folder)> write;
};

/// Every file of the corpus, without writing any (the names are known before a test runs).
const std::vector<CorpusFile>& corpusFiles();

} // namespace vissort::test
