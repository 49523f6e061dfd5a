#pragma once
// The files a command reads and writes, as its command line names them: no output may be an
// input or another output (output_files.h), checked before any work.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "vissort/output_files.h"

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

/// Keeps this run's outputs, so that the inputs known only once the scene is read (a JSON
/// scene's meshes, an OBJ's .mtl: Scene::source_files) are checked before any work too.
void declareOutputs(OutputFiles outputs);

/// The declared outputs' clash with inputs (OutputFiles::clashWith), or empty.
std::string checkInputs(const std::vector<FileUse>& inputs);

} // namespace vissort::cli
