// One-line errors for a mistyped command line (command_line_errors.h).

#include "cli/command_line_errors.h"

#include <cctype>
#include <regex>
#include <sstream>
#include <vector>

#include "vissort/closest_name.h"

namespace vissort::cli {
namespace {

std::vector<std::string> commandNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
        names.push_back(command->get_name());
    return names;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return text;
}

// Every spelling of the command's options: --long and -s.
std::vector<std::string> optionSpellings(const CLI::App& command) {
    std::vector<std::string> spellings;
    for (const CLI::Option* option : command.get_options()) {
        for (const std::string& name : option->get_lnames())
            spellings.push_back("--" + name);
        for (const std::string& name : option->get_snames())
            spellings.push_back("-" + name);
    }
    return spellings;
}

std::string helpHint(const CLI::App* command) {
    return command == nullptr ? " (run 'vissort --help')"
                              : " (run 'vissort " + command->get_name() + " --help')";
}

// The option a token names, if it is one: "--size=2x2" -> "--size", "-o" -> "-o"; "" for values
// ("-1,2,3" is a vector, "-" is standard output).
std::string optionOf(const std::string& token) {
    if (token.size() < 2 || token[0] != '-')
        return "";
    if (token[1] == '-')
        return token.substr(0, token.find('='));
    if (std::isdigit(static_cast<unsigned char>(token[1])) || token[1] == '.')
        return "";
    return token.substr(0, 2);
}

const CLI::App* parsedCommand(const CLI::App& app) {
    const std::vector<const CLI::App*> parsed =
        app.get_subcommands([](const CLI::App* command) { return command->parsed(); });
    return parsed.empty() ? nullptr : parsed.front();
}

} // namespace

std::string formatNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string checkCommandLine(const CLI::App& app, int argc, const char* const* argv) {
    const std::vector<std::string> commands = commandNames(app);
    const std::vector<std::string> top_options = optionSpellings(app);
    int at = 1;
    for (; at < argc; ++at) {
        const std::string token = argv[at];
        if (optionOf(token).empty())
            break;
        const std::string option = optionOf(token);
        if (std::find(top_options.begin(), top_options.end(), option) == top_options.end())
            return "unknown option '" + option + "'" + didYouMean(option, top_options) +
                   "; options go after the command" + helpHint(nullptr);
        return ""; // --help, --version: CLI11 answers them
    }
    if (at == argc)
        return "a command is required: " + joined(commands) + helpHint(nullptr);
    const std::string name = argv[at];
    const CLI::App* command = nullptr;
    try {
        command = app.get_subcommand(name);
    } catch (const CLI::OptionNotFound&) {
        return "unknown command '" + name + "'" + didYouMean(name, commands) +
               "; commands: " + joined(commands) + helpHint(nullptr);
    }
    const std::vector<std::string> options = optionSpellings(*command);
    for (int i = at + 1; i < argc; ++i) {
        const std::string token = argv[i];
        if (token == "--")
            break;
        const std::string option = optionOf(token);
        if (option.empty() || std::find(options.begin(), options.end(), option) != options.end())
            continue;
        return "unknown option '" + option + "' for " + name + didYouMean(option, options) +
               helpHint(command);
    }
    return "";
}

std::string explainParseError(const CLI::App& app, const CLI::ParseError& error) {
    const CLI::App* command = parsedCommand(app);
    const std::string what = error.what();
    std::smatch match;
    // "--size: At Most 1 required but received 2"
    static const std::regex repeated(R"(^(\S+): At Most 1 required but received (\d+))");
    if (std::regex_search(what, match, repeated))
        return match[1].str() + " was given " + match[2].str() + " times: give it once" +
               helpHint(command);
    // "Could not convert: --fov = abc"
    static const std::regex conversion(R"(^Could not convert: (\S+) = (.*)$)");
    if (std::regex_search(what, match, conversion)) {
        const std::string option = match[1].str();
        std::string expected = "a value of another kind";
        if (command != nullptr)
            if (const CLI::Option* found = command->get_option_no_throw(option)) {
                const std::string type = found->get_type_name();
                if (type == "INT" || type == "UINT")
                    expected = "a whole number";
                else if (type == "FLOAT")
                    expected = "a number";
            }
        return option + " expects " + expected + ", got '" + match[2].str() + "'" +
               helpHint(command);
    }
    return what + helpHint(command);
}

} // namespace vissort::cli
