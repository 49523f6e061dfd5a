#include "cli/json_output.h"

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <charconv>
#include <iostream>
#include <vector>

#include "cli/cli_common.h"
#include "cli/output_paths.h"

namespace vissort::cli {
namespace {

// A control character that the dump escapes: no value a command writes starts with it.
constexpr char kPlaceholderMark = '\x01';

// Standard output as it was before reserveStandardOutputFor sent the commands' text elsewhere.
std::streambuf* g_standard_output = nullptr;

// Writes ids as nlohmann's dump lays out an array of numbers: on one line (compact), or (pretty,
// dump(1)) with its key or bracket on a line indented by `indent` spaces, one element a line,
// one space deeper.
void writeIds(std::ostream& out, const JsonIdList& list, bool pretty, std::size_t indent) {
    if (list.ids.empty()) {
        out << "[]";
        return;
    }
    const std::string element_indent(pretty ? indent + 1 : 0, ' ');
    std::string text = pretty ? "[\n" : "[";
    const std::size_t n = list.ids.size();
    for (std::size_t i = 0; i < n; ++i) {
        text += element_indent;
        char digits[16];
        const uint32_t id = list.ids[list.reversed ? n - 1 - i : i];
        text.append(digits, std::to_chars(digits, digits + sizeof(digits), id).ptr);
        if (pretty)
            text += i + 1 < n ? ",\n" : "\n";
        else if (i + 1 < n)
            text += ',';
        if (text.size() >= (1u << 16)) { // written in pieces: the text of a list is never held
            out << text;
            text.clear();
        }
    }
    if (pretty)
        text.append(indent, ' ');
    text += ']';
    out << text;
}

} // namespace

nlohmann::json vec3Json(const Vec3& v) {
    return nlohmann::json::array({v.x, v.y, v.z});
}

nlohmann::json cameraJson(const CameraSpec& camera) {
    if (camera.projection == Projection::orthographic)
        return {{"projection", "orthographic"}, {"direction", vec3Json(camera.ortho_direction)}};
    return {{"projection", "perspective"},
            {"eye", vec3Json(camera.eye)},
            {"target", vec3Json(camera.target)},
            {"up", vec3Json(camera.up)},
            {"fov_degrees", camera.fov_degrees}};
}

void addJsonOptions(CLI::App& command, JsonOutput& output, const std::string& what) {
    command.add_option("--json", output.path, what + " (FILE, or - for standard output)");
    command.add_flag("--pretty", output.pretty, "Indent the JSON (default: one compact line)");
}

void reserveStandardOutputFor(const JsonOutput& output) {
    reserveStandardOutputFor(output.path);
}

void reserveStandardOutputFor(const std::string& path) {
    if (path != "-" || g_standard_output != nullptr)
        return;
    g_standard_output = std::cout.rdbuf(std::cerr.rdbuf());
}

std::streambuf* standardOutputBuffer() {
    return g_standard_output ? g_standard_output : std::cout.rdbuf();
}

int writeJsonFile(const JsonOutput& output, const nlohmann::json& document) {
    return writeJsonFile(output, document, {});
}

std::string jsonIdListPlaceholder(std::size_t index) {
    return kPlaceholderMark + std::string("ids:") + std::to_string(index);
}

int writeJsonFile(const JsonOutput& output, const nlohmann::json& document,
                  std::span<const JsonIdList> lists) {
    const std::string text = output.pretty ? document.dump(1) : document.dump();
    // Where each placeholder is, as dumped (the mark escaped, in quotes), in the text's order.
    struct Found {
        std::size_t at, length, list;
    };
    std::vector<Found> found;
    for (std::size_t index = 0; index < lists.size(); ++index) {
        const std::string quoted = nlohmann::json(jsonIdListPlaceholder(index)).dump();
        const std::size_t at = text.find(quoted);
        assert(at != std::string::npos);
        if (at != std::string::npos)
            found.push_back({at, quoted.size(), index});
    }
    std::sort(found.begin(), found.end(),
              [](const Found& a, const Found& b) { return a.at < b.at; });
    const auto emit = [&](std::ostream& out) {
        std::size_t written = 0;
        for (const Found& f : found) {
            const std::size_t line = text.rfind('\n', f.at) + 1; // 0 when there is none
            std::size_t indent = 0;
            while (text[line + indent] == ' ')
                ++indent;
            out.write(text.data() + written, std::streamsize(f.at - written));
            writeIds(out, lists[f.list], output.pretty, indent);
            written = f.at + f.length;
        }
        out.write(text.data() + written, std::streamsize(text.size() - written));
        out << '\n';
        out.flush();
    };
    return writeTextOutput(output.path, emit);
}

int writeTextOutput(const std::string& path, const std::function<void(std::ostream&)>& emit) {
    if (path == "-") {
        std::ostream out(standardOutputBuffer());
        errno = 0;
        emit(out);
        if (!out)
            return fail(kExitFailure, cannotWrite("standard output"));
        return kExitOk;
    }
    if (Status written = writeTextFile(path, emit); !written)
        return fail(kExitFailure, written.error);
    return kExitOk;
}

} // namespace vissort::cli
