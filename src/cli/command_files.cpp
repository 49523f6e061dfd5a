// The files a command reads and writes (command_files.h).

#include "cli/command_files.h"

#include "vissort/tet_grid.h"
#include "vissort/transfer_function.h"

namespace vissort::cli {
namespace {

OutputFiles g_declared_outputs;

bool isTransferPreset(const std::string& name) {
    for (const TransferPreset& preset : transferPresets())
        if (name == preset.name)
            return true;
    return false;
}

} // namespace

std::vector<FileUse> commandInputs(const std::vector<SceneArgument>& scenes,
                                   const std::vector<FileArgument>& files) {
    std::vector<FileUse> inputs;
    for (const SceneArgument& scene : scenes) {
        if (!scene.command->parsed() || scene.specification.empty() ||
            scene.specification.starts_with("builtin:"))
            continue;
        if (isGridSpec(scene.specification))
            for (const std::string& file : gridSourceFiles(scene.specification))
                inputs.push_back({"the grid file", file});
        else
            inputs.push_back({"the scene file", scene.specification});
    }
    for (const FileArgument& file : files) {
        if (!file.command->parsed() || file.value.empty() ||
            (file.option == "--tf" && isTransferPreset(file.value)))
            continue;
        inputs.push_back({"the " + file.option + " file", file.value});
    }
    return inputs;
}

void declareOutputs(OutputFiles outputs) {
    g_declared_outputs = std::move(outputs);
}

std::string checkInputs(const std::vector<FileUse>& inputs) {
    return g_declared_outputs.clashWith(inputs);
}

} // namespace vissort::cli
