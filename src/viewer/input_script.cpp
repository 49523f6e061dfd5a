// Parsing `vissort view --script` files (input_script.h).

#include "viewer/input_script.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

namespace vissort::viewer {
namespace {

using Events = Result<std::vector<ScriptEvent>>;

Events failure(std::size_t line, const std::string& message) {
    return {std::nullopt, "line " + std::to_string(line) + ": " + message};
}

bool readNumber(std::istringstream& in, double& value) {
    std::string word;
    if (!(in >> word))
        return false;
    char* end = nullptr;
    value = std::strtod(word.c_str(), &end);
    return end == word.c_str() + word.size() && std::isfinite(value);
}

std::string upper(std::string text) {
    for (char& c : text)
        c = char(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

} // namespace

Events parseInputScript(const std::string& text) {
    std::vector<ScriptEvent> events;
    std::istringstream lines(text);
    std::string line;
    for (std::size_t number = 1; std::getline(lines, line); ++number) {
        line = line.substr(0, line.find('#'));
        std::istringstream in(line);
        std::string frame_word;
        if (!(in >> frame_word))
            continue; // blank or comment
        ScriptEvent event;
        double frame = 0;
        std::istringstream frame_in(frame_word);
        if (!readNumber(frame_in, frame) || frame < 0 || frame > 1e7 || frame != std::floor(frame))
            return failure(number,
                           "the frame must be a whole number from 0, got '" + frame_word + "'");
        event.frame = int(frame);
        std::string kind;
        if (!(in >> kind))
            return failure(number, "an event (key, drag, wheel or resize) must follow the frame");
        if (kind == "key") {
            std::string key;
            if (!(in >> key))
                return failure(number, "key needs a key name");
            event.key = upper(key);
            if (std::find_if(std::begin(kScriptKeys), std::end(kScriptKeys), [&](const char* k) {
                    return event.key == k;
                }) == std::end(kScriptKeys))
                return failure(number,
                               "unknown key '" + key +
                                   "' (expected W A S D Q E F R P H C K X SPACE ESCAPE TAB 1-7)");
        } else if (kind == "drag") {
            event.kind = ScriptEvent::Kind::drag;
            std::string button;
            in >> button;
            if (button == "left")
                event.button = 0;
            else if (button == "right")
                event.button = 1;
            else if (button == "middle")
                event.button = 2;
            else
                return failure(number,
                               "drag needs a button (left, right or middle), got '" + button + "'");
            if (!readNumber(in, event.x0) || !readNumber(in, event.y0) ||
                !readNumber(in, event.x1) || !readNumber(in, event.y1))
                return failure(number, "drag needs four numbers: X0 Y0 X1 Y1");
        } else if (kind == "wheel") {
            event.kind = ScriptEvent::Kind::wheel;
            if (!readNumber(in, event.steps) || std::abs(event.steps) > 1000)
                return failure(number, "wheel needs a number of steps between -1000 and 1000");
        } else if (kind == "resize") {
            event.kind = ScriptEvent::Kind::resize;
            double width = 0, height = 0;
            if (!readNumber(in, width) || !readNumber(in, height) || width < 1 || height < 1 ||
                width > 16384 || height > 16384 || width != std::floor(width) ||
                height != std::floor(height))
                return failure(number, "resize needs a width and a height, whole numbers from 1 "
                                       "to 16384");
            event.width = uint32_t(width);
            event.height = uint32_t(height);
        } else {
            return failure(number,
                           "unknown event '" + kind + "' (expected key, drag, wheel or resize)");
        }
        std::string extra;
        if (in >> extra)
            return failure(number, "unexpected '" + extra + "' after the event");
        events.push_back(event);
    }
    std::stable_sort(events.begin(), events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    return {std::move(events), ""};
}

Events loadInputScript(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return {std::nullopt, "cannot read the script '" + path + "'"};
    std::ostringstream text;
    text << in.rdbuf();
    if (text.str().size() > (std::size_t(16) << 20))
        return {std::nullopt, "the script '" + path + "' is larger than 16 MiB"};
    Events events = parseInputScript(text.str());
    if (!events)
        return {std::nullopt, "script '" + path + "', " + events.error};
    return events;
}

} // namespace vissort::viewer
