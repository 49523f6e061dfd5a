#include "cli/json_output.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <fstream>
#include <vector>

#include "cli/cli_common.h"

namespace vissort::cli {
namespace {

// A control character that the dump escapes: no value a command writes starts with it.
constexpr char kPlaceholderMark = '\x01';

// Writes ids as nlohmann's dump(1) lays out an array of numbers whose key or bracket is on a line
// indented by `indent` spaces: one element a line, one space deeper.
void writeIds(std::ostream& out, const JsonIdList& list, std::size_t indent) {
    if (list.ids.empty()) {
        out << "[]";
        return;
    }
    const std::string element_indent(indent + 1, ' ');
    std::string text = "[\n";
    const std::size_t n = list.ids.size();
    for (std::size_t i = 0; i < n; ++i) {
        text += element_indent;
        char digits[16];
        const uint32_t id = list.ids[list.reversed ? n - 1 - i : i];
        text.append(digits, std::to_chars(digits, digits + sizeof(digits), id).ptr);
        text += i + 1 < n ? ",\n" : "\n";
        if (text.size() >= (1u << 16)) { // written in pieces: the text of a list is never held
            out << text;
            text.clear();
        }
    }
    text.append(indent, ' ');
    text += ']';
    out << text;
}

} // namespace

int writeJsonFile(const std::string& path, const nlohmann::json& document) {
    return writeJsonFile(path, document, {});
}

std::string jsonIdListPlaceholder(std::size_t index) {
    return kPlaceholderMark + std::string("ids:") + std::to_string(index);
}

int writeJsonFile(const std::string& path, const nlohmann::json& document,
                  std::span<const JsonIdList> lists) {
    std::ofstream out(path);
    const std::string text = document.dump(1);
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
    std::size_t written = 0;
    for (const Found& f : found) {
        const std::size_t line = text.rfind('\n', f.at) + 1; // 0 when there is none
        std::size_t indent = 0;
        while (text[line + indent] == ' ')
            ++indent;
        out.write(text.data() + written, std::streamsize(f.at - written));
        writeIds(out, lists[f.list], indent);
        written = f.at + f.length;
    }
    out.write(text.data() + written, std::streamsize(text.size() - written));
    out << '\n';
    if (!out)
        return fail(kExitFailure, "cannot write " + path);
    return kExitOk;
}

} // namespace vissort::cli
