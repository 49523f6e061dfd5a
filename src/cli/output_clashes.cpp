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
// Each frame's resolved path, the folder resolved once when the conversion is in the name.
std::vector<std::string> framePaths(const fs::path& folder, const std::string& text, int frames);

struct Pattern {
    fs::path folder; // resolved; empty when the conversion is in the folder part
    std::string prefix, suffix;
    int frames = 0;
    std::string text;
    // Frame files that exist and are symbolic or hard links (up to kFramesStatted frames): the
    // only ones that can be an input under another name. Found once, not once an input.
    std::vector<std::pair<int, std::string>> linked;
    // With the conversion in the folder part: every frame's resolved path, and its frame.
    std::vector<std::string> paths;
    std::unordered_map<std::string, int> frame_of_path;
};

Pattern splitPattern(const FileUse& use) {
    Pattern pattern;
    pattern.frames = use.frames;
    pattern.text = use.path;
    const fs::path path(use.path);
    const std::string name = path.filename().string();
    const std::size_t percent = name.find('%');
    if (percent == std::string::npos) {
        pattern.paths = framePaths({}, use.path, use.frames); // checked frame by frame
        for (std::size_t f = 0; f < pattern.paths.size(); ++f)
            pattern.frame_of_path.emplace(pattern.paths[f], int(f));
    } else {
        const std::size_t d = name.find('d', percent);
        pattern.folder = resolved(path.has_parent_path() ? path.parent_path() : fs::path("."));
        pattern.prefix = name.substr(0, percent);
        pattern.suffix = name.substr(d + 1);
    }
    if (pattern.frames <= kFramesStatted)
        for (int f = 0; f < pattern.frames; ++f) {
            const fs::path frame(framePath(use.path, f));
            std::error_code error;
            const bool link = fs::is_symlink(fs::symlink_status(frame, error));
            const auto links = fs::hard_link_count(frame, error);
            if (link || (!error && links > 1))
                pattern.linked.emplace_back(f, frame.string());
        }
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
    const fs::path where = resolved(file);
    if (pattern.folder.empty()) {
        if (auto found = pattern.frame_of_path.find(where.string());
            found != pattern.frame_of_path.end())
            return found->second;
    } else if (std::optional<int> frame =
                   frameNamed(pattern, where.parent_path(), where.filename().string())) {
        return frame;
    }
    for (const auto& [frame, frame_path] : pattern.linked)
        if (sameFile(frame_path, file))
            return frame;
    return std::nullopt;
}

std::vector<std::string> framePaths(const fs::path& folder, const std::string& text, int frames) {
    std::vector<std::string> paths(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f) {
        const fs::path frame(framePath(text, f));
        paths[std::size_t(f)] =
            folder.empty() ? resolved(frame).string() : (folder / frame.filename()).string();
    }
    return paths;
}

// A frame of a that is a frame of b, if any, by their resolved names: two patterns of 100,000
// frames each cost two lists of names and a hash table.
std::optional<std::pair<int, int>> sharedFrame(const Pattern& a, const Pattern& b) {
    if (!a.folder.empty() && !b.folder.empty() && a.folder != b.folder)
        return std::nullopt;
    std::unordered_map<std::string, int> b_frames;
    const std::vector<std::string> b_paths =
        b.folder.empty() ? b.paths : framePaths(b.folder, b.text, b.frames);
    for (std::size_t g = 0; g < b_paths.size(); ++g)
        b_frames.emplace(b_paths[g], int(g));
    const std::vector<std::string> a_paths =
        a.folder.empty() ? a.paths : framePaths(a.folder, a.text, a.frames);
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

// An output with its pattern taken apart once (an output is checked against every input).
struct Prepared {
    const FileUse* use;
    std::optional<Pattern> pattern;
};

Prepared prepared(const FileUse& use) {
    return {&use, use.frames > 0 ? std::optional<Pattern>(splitPattern(use)) : std::nullopt};
}

// Why a (an output) and b are one file, in one line, or empty.
std::string clashOf(const Prepared& a, const Prepared& b, bool b_is_input) {
    std::optional<std::pair<int, int>> frames; // a's and b's
    if (!a.pattern && !b.pattern) {
        if (!isSpecial(a.use->path) && sameFile(a.use->path, b.use->path))
            frames = std::pair{0, 0};
    } else if (a.pattern && b.pattern) {
        frames = sharedFrame(*a.pattern, *b.pattern);
    } else {
        const Prepared& plain = a.pattern ? b : a;
        const Pattern& pattern = a.pattern ? *a.pattern : *b.pattern;
        if (!isSpecial(plain.use->path))
            if (std::optional<int> frame = frameThatIs(pattern, plain.use->path))
                frames = std::pair{*frame, *frame};
    }
    if (!frames)
        return {};
    const std::string first = described(*a.use, frames->first),
                      second = described(*b.use, frames->second);
    return b_is_input ? first + " is " + second +
                            ": vissort never overwrites an input; choose another path"
                      : first + " and " + second + " are one file: give each output its own path";
}

bool isOutput(const FileUse& use) {
    return !use.path.empty() && use.path != "-";
}

} // namespace

std::string findClash(const std::vector<FileUse>& inputs, const std::vector<FileUse>& outputs) {
    std::vector<Prepared> written;
    for (const FileUse& output : outputs)
        if (isOutput(output))
            written.push_back(prepared(output));
    for (const Prepared& output : written)
        for (const FileUse& input : inputs)
            if (!input.path.empty())
                if (std::string clash = clashOf(output, prepared(input), true); !clash.empty())
                    return clash;
    for (std::size_t i = 0; i < written.size(); ++i)
        for (std::size_t j = i + 1; j < written.size(); ++j)
            if (std::string clash = clashOf(written[i], written[j], false); !clash.empty())
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
