#pragma once
// Writing the commands' JSON documents.

#include <cstdint>
#include <functional>
#include <ostream>
#include <span>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "vissort/camera.h"

namespace vissort::cli {

/// Where a command's JSON goes: a file, or standard output for "-"; compact (one line) unless
/// pretty (indented one space a level).
struct JsonOutput {
    std::string path;
    bool pretty = false;
};

/// A point or vector as the JSON array [x, y, z].
nlohmann::json vec3Json(const Vec3& v);

/// A camera as JSON: {"projection": "perspective", "eye": [x, y, z], "target": [...], "up": [...],
/// "fov_degrees": f} or {"projection": "orthographic", "direction": [x, y, z]}.
nlohmann::json cameraJson(const CameraSpec& camera);

/// Adds --json PATH (its help: what) and --pretty.
void addJsonOptions(CLI::App& command, JsonOutput& output, const std::string& what);

/// With `--json -`: the document goes to standard output, and from this call on everything the
/// command prints for people goes to standard error, so that a pipe receives the JSON alone.
void reserveStandardOutputFor(const JsonOutput& output);
/// The same for any output path ("-": standard output), such as --csv's.
void reserveStandardOutputFor(const std::string& path);

/// Where "-" writes: standard output, whichever stream the people's text was moved to.
std::streambuf* standardOutputBuffer();

/// Writes what emit writes to path, whole (writeTextFile, output_paths.h), or for "-" to standard
/// output. Returns kExitOk, or prints "cannot write PATH: REASON" and returns kExitFailure.
int writeTextOutput(const std::string& path, const std::function<void(std::ostream&)>& emit);

/// Writes document to output's path ("-": standard output), ending with a newline. Returns
/// kExitOk, or prints "cannot write PATH" and returns kExitFailure.
int writeJsonFile(const JsonOutput& output, const nlohmann::json& document);

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
/// own arrays are (one line, or one element a line when pretty). Every placeholder must occur once.
int writeJsonFile(const JsonOutput& output, const nlohmann::json& document,
                  std::span<const JsonIdList> lists);

} // namespace vissort::cli
