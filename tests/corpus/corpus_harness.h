#pragma once
// The checks every file of a corpus goes through (tests/corpus): a file is either refused with a
// one-line message naming it, or loaded and, at each view and level,
//  (a) ordered by the cpu oracle and by the exact oracle with no violation of the exact ground
//      truth (ground_truth.h), outside the cycles each reports;
//  (b) the cycles each reports are exactly the strongly connected components (tarjan_scc.h) of
//      the ground truth's occlusion graph (occlusionCycles);
//  (c) rendered all-transparent, vissort matches the per-pixel linked-list reference to 1/255 on
//      every pixel, at each level (with OpenGL only).
// Failures are collected as lines naming the view, level and check with their numbers, so that
// one file's report shows every check that failed, not only the first.

#include <cstdint>
#include <string>
#include <vector>

#include "vissort/camera.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort::test {

struct CorpusView {
    std::string name; // e.g. "ortho(-0.3,-0.5,-1)"
    CameraSpec camera;
};

/// The views every file is checked at: two orthographic directions, one oblique from above and
/// one grazing the horizontal plane (y up), and the default perspective view of the file.
std::vector<CorpusView> corpusViews();

struct CorpusSettings {
    std::vector<CorpusView> views = corpusViews();
    std::vector<OrderLevel> levels = {OrderLevel::object, OrderLevel::triangle};
    uint32_t width = 192, height = 144;
    bool render = true; // (c); ignored without OpenGL
    // The oracles held to (a) and (b); gl, where built, is held to (a) and to cycles that hold
    // the components (it counts what it cannot decide both ways), its extra members measured.
    std::vector<OracleKind> oracles = {OracleKind::cpu, OracleKind::cpu_reference,
                                       OracleKind::exact};
    bool gl = true;
    float alpha = 0.5f; // all-transparent alpha of (c)
};

struct CorpusReport {
    std::string path;
    bool loaded = false;
    std::string load_error; // the loader's message when refused
    std::size_t objects = 0, triangles = 0;
    uint64_t pairs_checked = 0;      // ground-truth occlusions checked over every view and level
    uint32_t max_cycle = 0;          // largest exact strongly connected component seen
    uint64_t true_cycle_members = 0; // members of the exact components, every view and level
    uint64_t gl_cycle_members = 0;   // members of gl's cycles, every view and level
    bool gl_ran = false;
    std::vector<std::string> failures; // one line per failed check
};

/// Whether a loader's error is a clean refusal of path: one non-empty line that names the file.
/// Empty when it is, else what is wrong with it.
std::string refusalProblem(const std::string& path, const std::string& error);

/// Loads path with loadScene and, when it loads, runs every check at every view and level.
/// A refusal is recorded, not failed: the caller decides whether the file had to load
/// (a refusal that is not clean is a failure).
CorpusReport checkCorpusFile(const std::string& path, const CorpusSettings& settings = {});

/// The report in a few lines, for test output.
std::string describe(const CorpusReport& report);

} // namespace vissort::test
