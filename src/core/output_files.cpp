// Never overwrite an input (output_files.h).

#include "vissort/output_files.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <regex>
#include <system_error>
#include <unordered_map>
#include <utility>

namespace vissort {
namespace {

namespace fs = std::filesystem;

// Up to this many frames, a pattern's frame files that exist and are links are compared as files
// (a link named like a frame can be an input); past it the shape alone: no pattern is listed.
constexpr int kFramesStatted = 4096;

std::string quoted(const std::string& path) {
    return "'" + path + "'";
}

// The path's absolute spelling with links and `..` followed as far as it exists.
fs::path resolved(const fs::path& path) {
    std::error_code error;
    const fs::path absolute = fs::absolute(path, error);
    if (error)
        return path.lexically_normal();
    const fs::path result = fs::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal() : result;
}

// There and neither a regular file nor a folder (a device, a FIFO): writing replaces nothing.
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
    return !a_exists && !b_exists && resolved(a) == resolved(b);
}

// A frame pattern taken apart around its one %d conversion.
struct Pattern {
    std::string text;
    int first = 0, frames = 0;
    fs::path folder; // resolved; empty when the conversion is in the folder part
    std::string prefix, suffix;
    // With the conversion in the folder part: each resolved frame path's frame.
    std::unordered_map<std::string, int> frame_of_path;
    // Frame files that exist and are symbolic or hard links (up to kFramesStatted frames): the
    // only ones that can be an input under another name.
    std::vector<std::pair<int, std::string>> linked;

    explicit Pattern(const FileUse& use)
        : text(use.path), first(use.first_frame), frames(use.frames) {
        const fs::path path(use.path);
        const std::string name = path.filename().string();
        if (const std::size_t percent = name.find('%'); percent != std::string::npos) {
            folder = resolved(path.has_parent_path() ? path.parent_path() : fs::path("."));
            prefix = name.substr(0, percent);
            suffix = name.substr(name.find('d', percent) + 1);
        } else {
            for (int f = first; f < first + frames; ++f)
                frame_of_path.emplace(resolved(framePath(text, f)).string(), f);
        }
        if (frames > kFramesStatted)
            return;
        for (int f = first; f < first + frames; ++f) {
            const fs::path frame(framePath(text, f));
            std::error_code error;
            const bool link = fs::is_symlink(fs::symlink_status(frame, error));
            const auto links = fs::hard_link_count(frame, error);
            if (link || (!error && links > 1))
                linked.emplace_back(f, frame.string());
        }
    }

    // The frame whose resolved path is `where`, if any.
    std::optional<int> frameAt(const fs::path& where) const {
        if (folder.empty()) {
            const auto found = frame_of_path.find(where.string());
            return found == frame_of_path.end() ? std::nullopt : std::optional<int>(found->second);
        }
        const std::string name = where.filename().string();
        if (where.parent_path() != folder || name.size() <= prefix.size() + suffix.size() ||
            !name.starts_with(prefix) || !name.ends_with(suffix))
            return std::nullopt;
        const char* digits = name.data() + prefix.size();
        const char* digits_end = name.data() + name.size() - suffix.size();
        int frame = 0;
        const auto [end, error] = std::from_chars(digits, digits_end, frame);
        if (error != std::errc() || end != digits_end || frame < first || frame >= first + frames)
            return std::nullopt;
        // The pattern's own spelling of that frame (its zero padding) must be the name.
        if (fs::path(framePath(text, frame)).filename().string() != name)
            return std::nullopt;
        return frame;
    }

    // The frame that is the file at path, if any.
    std::optional<int> frameThatIs(const std::string& path) const {
        if (std::optional<int> frame = frameAt(resolved(path)))
            return frame;
        for (const auto& [frame, frame_path] : linked)
            if (sameFile(frame_path, path))
                return frame;
        return std::nullopt;
    }

    // A frame of this pattern that is a frame of other, if any, by resolved names (two patterns
    // of 100,000 frames: two lists of names and a hash table).
    std::optional<std::pair<int, int>> sharedFrame(const Pattern& other) const {
        if (!folder.empty() && !other.folder.empty() && folder != other.folder)
            return std::nullopt;
        for (int f = first; f < first + frames; ++f) {
            const fs::path frame(framePath(text, f));
            if (std::optional<int> g =
                    other.frameAt(folder.empty() ? resolved(frame) : folder / frame.filename()))
                return std::pair{f, *g};
        }
        return std::nullopt;
    }
};

// "--json 'x.json'", with the frame's own name for a pattern.
std::string described(const FileUse& use, int frame) {
    std::string text = use.what + " " + quoted(use.path);
    if (use.frames > 0)
        text +=
            " (frame " + std::to_string(frame) + ": " + quoted(framePath(use.path, frame)) + ")";
    return text;
}

bool isFile(const FileUse& use) {
    return !use.path.empty() && use.path != "-";
}

} // namespace

bool isFramePattern(const std::string& path) {
    static const std::regex pattern(R"([^%]*%0?[0-9]?d[^%]*)");
    return std::regex_match(path, pattern);
}

std::string framePath(const std::string& pattern, int frame) {
    char buffer[4096];
    std::snprintf(buffer, sizeof(buffer), pattern.c_str(), frame);
    return buffer;
}

// A use with its pattern taken apart once.
struct OutputFiles::Prepared {
    const FileUse* use;
    std::optional<Pattern> pattern;

    explicit Prepared(const FileUse& file) : use(&file) {
        if (file.frames > 0)
            pattern.emplace(file);
    }

    // The frames of this use (an output) and of other that are one file, if any.
    std::optional<std::pair<int, int>> sharedWith(const Prepared& other) const {
        if (!pattern && !other.pattern) {
            if (!isSpecial(use->path) && sameFile(use->path, other.use->path))
                return std::pair{0, 0};
            return std::nullopt;
        }
        if (pattern && other.pattern)
            return pattern->sharedFrame(*other.pattern);
        const Prepared& plain = pattern ? other : *this;
        if (isSpecial(plain.use->path))
            return std::nullopt;
        const std::optional<int> frame =
            (pattern ? *pattern : *other.pattern).frameThatIs(plain.use->path);
        return frame ? std::optional(std::pair{*frame, *frame}) : std::nullopt;
    }
};

OutputFiles::OutputFiles(std::vector<FileUse> outputs) : outputs_(std::move(outputs)) {
    for (const FileUse& output : outputs_)
        if (isFile(output))
            prepared_.push_back(std::make_unique<Prepared>(output));
}
OutputFiles::OutputFiles(OutputFiles&&) noexcept = default;
OutputFiles& OutputFiles::operator=(OutputFiles&&) noexcept = default;
OutputFiles::~OutputFiles() = default;

std::string OutputFiles::clashWith(const std::vector<FileUse>& inputs) const {
    for (const FileUse& input : inputs) {
        if (input.path.empty())
            continue;
        const Prepared read(input);
        for (const auto& output : prepared_)
            if (const auto frames = output->sharedWith(read))
                return described(*output->use, frames->first) + " is " +
                       described(input, frames->second) +
                       ": vissort never overwrites an input; choose another path";
    }
    return {};
}

std::string OutputFiles::clashAmongThemselves() const {
    for (std::size_t i = 0; i < prepared_.size(); ++i)
        for (std::size_t j = i + 1; j < prepared_.size(); ++j)
            if (const auto frames = prepared_[i]->sharedWith(*prepared_[j]))
                return described(*prepared_[i]->use, frames->first) + " and " +
                       described(*prepared_[j]->use, frames->second) +
                       " are one file: give each output its own path";
    return {};
}

} // namespace vissort
