#pragma once
// The files a command reads, as its command line names them: checked against its outputs before
// any work (output_clashes.h).

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/output_clashes.h"

namespace vissort::cli {

/// A command's scene or grid argument.
struct SceneArgument {
    const CLI::App* command;
    std::string specification;
};

/// An option whose value may be a file the command reads (--tf, --script).
struct FileArgument {
    const CLI::App* command;
    std::string option;
    std::string value;
};

/// The files the parsed command reads: a scene file, a grid's files (gridSourceFiles: tetgen's
/// pair, Medit's .sol), a transfer function's JSON file (not a preset's name), a viewer script.
/// Nothing for built-in scenes and grids. The files a scene's loading opens besides (a JSON
/// scene's meshes) are checked once it is loaded (loadSceneOrReport).
std::vector<FileUse> commandInputs(const std::vector<SceneArgument>& scenes,
                                   const std::vector<FileArgument>& files);

} // namespace vissort::cli
