// Never overwrite an input (output_clashes.h).

#include "cli/output_clashes.h"

#include <charconv>
#include <filesystem>
#include <optional>
#include <system_error>
#include <unordered_map>

#include "cli/output_paths.h"

namespace vissort::cli {
namespace {

namespace fs = std::filesystem;

// Up to this many frames, each frame file that exists is compared as a file (a hard link or a
// symbolic link named like a frame); past it the shape alone: no pattern is listed whole.
constexpr int kFramesStatted = 4096;

std::vector<FileUse> g_declared_outputs;

std::string quoted(const std::string& path) {
    return "'" + path + "'";
}

// The path's absolute spelling with links and `..` followed as far as it exists.
fs::path resolved(const fs::path& path) {
    std::error_code error;
    fs::path absolute = fs::absolute(path, error);
    if (error)
        return path.lexically_normal();
    fs::path result = fs::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal() : result;
}

// A file that is there and can be replaced: writing to anything else (a device, a FIFO)
// replaces nothing.
bool isSpecial(const fs::path& path) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    return fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
}

// Whether two plain paths name one file.
bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code error;
    const bool a_exists = fs::exists(a, error), b_exists = fs::exists(b, error);
    if (a_exists && b_exists) {
        const bool same = fs::equivalent(a, b, error);
        return !error && same;
    }
    if (a_exists != b_exists)
        return false;
    return resolved(a) == resolved(b);
}

// A frame pattern split around its one %d conversion.
struct Pattern {
    fs::path folder; // resolved; empty when the conversion is in the folder part
    std::string prefix, suffix;
    int frames = 0;
    std::string text;
};

Pattern splitPattern(const FileUse& use) {
    Pattern pattern;
    pattern.frames = use.frames;
    pattern.text = use.path;
    const fs::path path(use.path);
    const std::string name = path.filename().string();
    const std::size_t percent = name.find('%');
    if (percent == std::string::npos)
        return pattern; // in the folder part: checked frame by frame
    const std::size_t d = name.find('d', percent);
    pattern.folder = resolved(path.has_parent_path() ? path.parent_path() : fs::path("."));
    pattern.prefix = name.substr(0, percent);
    pattern.suffix = name.substr(d + 1);
    return pattern;
}

// The frame of the pattern that is named `name` in `folder` (resolved), if any.
std::optional<int> frameNamed(const Pattern& pattern, const fs::path& folder,
                              const std::string& name) {
    if (pattern.folder.empty() || folder != pattern.folder)
        return std::nullopt;
    if (name.size() <= pattern.prefix.size() + pattern.suffix.size() ||
        !name.starts_with(pattern.prefix) || !name.ends_with(pattern.suffix))
        return std::nullopt;
    const std::string_view digits(name.data() + pattern.prefix.size(),
                                  name.size() - pattern.prefix.size() - pattern.suffix.size());
    int frame = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), frame);
    if (error != std::errc() || end != digits.data() + digits.size() || frame < 0 ||
        frame >= pattern.frames)
        return std::nullopt;
    // The pattern's own spelling of that frame (its zero padding) must be the name.
    if (fs::path(framePath(pattern.text, frame)).filename().string() != name)
        return std::nullopt;
    return frame;
}

// The frame of the pattern that is the file at path, if any.
std::optional<int> frameThatIs(const Pattern& pattern, const std::string& path) {
    const fs::path file(path);
    if (pattern.folder.empty()) { // the conversion is in the folder part: every frame
        for (int f = 0; f < pattern.frames; ++f)
            if (sameFile(framePath(pattern.text, f), file))
                return f;
        return std::nullopt;
    }
    const fs::path where = resolved(file);
    if (std::optional<int> frame =
            frameNamed(pattern, where.parent_path(), where.filename().string()))
        return frame;
    std::error_code error;
    if (pattern.frames <= kFramesStatted && fs::exists(file, error))
        for (int f = 0; f < pattern.frames; ++f)
            if (sameFile(framePath(pattern.text, f), file))
                return f;
    return std::nullopt;
}

// Each frame's resolved path: the folder resolved once when the conversion is in the name.
std::vector<std::string> framePaths(const Pattern& pattern) {
    std::vector<std::string> paths(std::size_t(pattern.frames));
    for (int f = 0; f < pattern.frames; ++f) {
        const fs::path frame(framePath(pattern.text, f));
        paths[std::size_t(f)] = pattern.folder.empty()
                                    ? resolved(frame).string()
                                    : (pattern.folder / frame.filename()).string();
    }
    return paths;
}

// A frame of a that is a frame of b, if any, by their resolved names: two patterns of 100,000
// frames each cost two lists of names and a hash table.
std::optional<std::pair<int, int>> sharedFrame(const Pattern& a, const Pattern& b) {
    if (!a.folder.empty() && !b.folder.empty() && a.folder != b.folder)
        return std::nullopt;
    std::unordered_map<std::string, int> b_frames;
    const std::vector<std::string> b_paths = framePaths(b);
    for (std::size_t g = 0; g < b_paths.size(); ++g)
        b_frames.emplace(b_paths[g], int(g));
    const std::vector<std::string> a_paths = framePaths(a);
    for (std::size_t f = 0; f < a_paths.size(); ++f)
        if (auto found = b_frames.find(a_paths[f]); found != b_frames.end())
            return std::pair{int(f), found->second};
    return std::nullopt;
}

std::string frameNote(const FileUse& use, int frame) {
    return use.frames > 0 ? " (frame " + std::to_string(frame) + ": " +
                                quoted(framePath(use.path, frame)) + ")"
                          : "";
}

// "--json 'x.json'", with the frame's name for a pattern.
std::string described(const FileUse& use, int frame) {
    return use.what + " " + quoted(use.path) + frameNote(use, frame);
}

// Why a (an output) and b are one file, in one line, or empty.
std::string clashOf(const FileUse& a, const FileUse& b, bool b_is_input) {
    std::optional<std::pair<int, int>> frames; // a's and b's
    if (a.frames == 0 && b.frames == 0) {
        if (!isSpecial(a.path) && sameFile(a.path, b.path))
            frames = std::pair{0, 0};
    } else if (a.frames > 0 && b.frames > 0) {
        frames = sharedFrame(splitPattern(a), splitPattern(b));
    } else {
        const FileUse& plain = a.frames > 0 ? b : a;
        if (!isSpecial(plain.path))
            if (std::optional<int> frame =
                    frameThatIs(splitPattern(a.frames > 0 ? a : b), plain.path))
                frames = std::pair{*frame, *frame};
    }
    if (!frames)
        return {};
    const std::string first = described(a, frames->first), second = described(b, frames->second);
    return b_is_input ? first + " is " + second +
                            ": vissort never overwrites an input; choose another path"
                      : first + " and " + second + " are one file: give each output its own path";
}

bool isOutput(const FileUse& use) {
    return !use.path.empty() && use.path != "-";
}

} // namespace

std::string findClash(const std::vector<FileUse>& inputs, const std::vector<FileUse>& outputs) {
    for (const FileUse& output : outputs) {
        if (!isOutput(output))
            continue;
        for (const FileUse& input : inputs)
            if (!input.path.empty())
                if (std::string clash = clashOf(output, input, true); !clash.empty())
                    return clash;
    }
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t j = i + 1; j < outputs.size(); ++j)
            if (isOutput(outputs[i]) && isOutput(outputs[j]))
                if (std::string clash = clashOf(outputs[i], outputs[j], false); !clash.empty())
                    return clash;
    return {};
}

void declareOutputs(std::vector<FileUse> outputs) {
    g_declared_outputs = std::move(outputs);
}

std::string checkInputs(const std::vector<FileUse>& inputs) {
    return findClash(inputs, g_declared_outputs);
}

} // namespace vissort::cli
