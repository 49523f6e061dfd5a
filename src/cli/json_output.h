#pragma once
// Writing the commands' JSON documents.

#include <cstdint>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

namespace vissort::cli {

/// Writes document to path, indented one space a level, ending with a newline. Returns
/// kExitOk, or prints "cannot write PATH" and returns kExitFailure.
int writeJsonFile(const std::string& path, const nlohmann::json& document);

/// A list of ids written into a document where it holds jsonIdListPlaceholder(index): straight
/// from the caller's array, not as a json array (16 bytes an element, then its text again: more
/// than everything else a large order holds).
struct JsonIdList {
    std::span<const uint32_t> ids;
    bool reversed = false; // written last to first
};

/// The string value that stands for lists[index] in writeJsonFile's document.
std::string jsonIdListPlaceholder(std::size_t index);

/// writeJsonFile, with each list's placeholder replaced by the list, laid out as the document's
/// own arrays are. Every placeholder must occur once.
int writeJsonFile(const std::string& path, const nlohmann::json& document,
                  std::span<const JsonIdList> lists);

} // namespace vissort::cli
