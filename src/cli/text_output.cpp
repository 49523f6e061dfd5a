// How the commands write for people (text_output.h).

#include "cli/text_output.h"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace vissort::cli {

std::string counted(uint64_t count, const std::string& noun, const std::string& plural) {
    return std::to_string(count) + ' ' + (count == 1 ? noun : plural.empty() ? noun + "s" : plural);
}

std::string milliseconds(double ms) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(ms < 10 ? 2 : ms < 100 ? 1 : 0) << ms;
    return text.str() + " ms";
}

bool colourOnStandardError() {
    const char* no_colour = std::getenv("NO_COLOR");
    return isatty(STDERR_FILENO) == 1 && (no_colour == nullptr || *no_colour == '\0');
}

void warn(const std::string& message) {
    if (colourOnStandardError())
        std::cerr << "vissort: \033[33mwarning:\033[0m " << message << '\n';
    else
        std::cerr << "vissort: warning: " << message << '\n';
}

} // namespace vissort::cli
