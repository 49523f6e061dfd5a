#pragma once
// Input replayed by `vissort view --script FILE`, so that tests (and demos) drive the viewer the
// way a user does. A text file, one event per line, '#' to the end of a line is a comment:
//
//   FRAME key NAME                  a key press: W A S D Q E F R P H C K X T [ ] SPACE ESCAPE
//                                   TAB 1 .. 7
//   FRAME drag BUTTON X0 Y0 X1 Y1   a mouse drag, left, right or middle, in window pixels
//   FRAME wheel STEPS               wheel steps, positive towards the scene (may be fractional)
//   FRAME resize WIDTH HEIGHT       the window resized
//
// FRAME is the frame before which the event happens: 0 before the first rendered frame, 1 after
// the first and before the second, and so on. Events of one frame happen in file order.

#include <cstdint>
#include <string>
#include <vector>

#include "vissort/result.h"

namespace vissort::viewer {

struct ScriptEvent {
    enum class Kind { key, drag, wheel, resize };
    int frame = 0;
    Kind kind = Kind::key;
    std::string key;                       // key: the name as written, upper case
    int button = 0;                        // drag: 0 left, 1 right, 2 middle (GLFW's numbering)
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0; // drag
    double steps = 0;                      // wheel
    uint32_t width = 0, height = 0;        // resize
};

/// The keys a script may press, as written there.
inline constexpr const char* kScriptKeys[] = {"W", "A", "S", "D", "Q",     "E",      "F", "R", "P",
                                              "H", "C", "K", "X", "SPACE", "ESCAPE", "1", "2", "3",
                                              "4", "5", "6", "7", "TAB",   "T",      "[", "]"};

/// The events of a script's text, sorted by frame (file order within a frame), or a one-line
/// error naming the line and what is wrong with it.
Result<std::vector<ScriptEvent>> parseInputScript(const std::string& text);

/// parseInputScript of a file's contents; the error names the file.
Result<std::vector<ScriptEvent>> loadInputScript(const std::string& path);

} // namespace vissort::viewer
