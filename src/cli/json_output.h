#pragma once
// Writing the commands' JSON documents.

#include <string>

#include <nlohmann/json.hpp>

namespace vissort::cli {

/// Writes document to path, indented one space a level, ending with a newline. Returns
/// kExitOk, or prints "cannot write PATH" and returns kExitFailure.
int writeJsonFile(const std::string& path, const nlohmann::json& document);

} // namespace vissort::cli
