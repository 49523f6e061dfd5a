#pragma once
// The fixture of the end-to-end tests: runs the built `vissort` tool (VISSORT_TOOL) as a user
// would, in a fresh temporary folder per test, and checks exit codes and one-line errors.

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scratch_folder.h"

namespace vissort {

namespace fs = std::filesystem;
using nlohmann::json;

inline const std::string kTool = VISSORT_TOOL;
inline const std::string kSource = VISSORT_SOURCE_DIR;
// The tool's exit codes (cli_common.h).
inline constexpr int kUsage = 2, kInput = 3, kFailure = 1;

inline std::string dataPath(const std::string& relative) {
    return kSource + "/tests/data/" + relative;
}

inline std::string shellQuote(const std::string& text) {
    std::string quoted = "'";
    for (char c : text)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

inline std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        result.push_back(line);
    return result;
}

struct RunResult {
    int code = -1;   // the tool's exit status; 124 = killed by `timeout`, >= 128 = a signal
    std::string out; // stdout
    std::string err; // stderr
    std::string command;
};

inline std::ostream& operator<<(std::ostream& os, const RunResult& r) {
    return os << "\n  command: " << r.command << "\n  exit: " << r.code << "\n  stdout: " << r.out
              << "\n  stderr: " << r.err;
}

// Each test gets a fresh folder, removed afterwards; the tool runs with it as working directory.
class Cli : public testing::Test {
protected:
    void SetUp() override {
        // Progress lines depend on timing (a slow sanitizer build crosses the first second):
        // off unless a test asks for them (VISSORT_PROGRESS_SECONDS=0 in its wrapper).
        setenv("VISSORT_PROGRESS_SECONDS", "100000", 1);
        ASSERT_FALSE(scratch_.path().empty());
        dir_ = scratch_.path();
    }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // Runs the tool; killed (code 124) after timeout_seconds: a hang fails the test, not the run.
    // wrapper: a command line the tool runs under (xvfb-run for the viewer), shell words.
    RunResult run(const std::vector<std::string>& args, int timeout_seconds = 60,
                  const std::string& wrapper = "") {
        RunResult r;
        std::string command = (wrapper.empty() ? "" : wrapper + " ") + "timeout " +
                              std::to_string(timeout_seconds) + " " + shellQuote(kTool);
        for (const std::string& a : args)
            command += ' ' + shellQuote(a);
        r.command = command;
        const std::string out = path("tool.stdout"), err = path("tool.stderr");
        const std::string full = "cd " + shellQuote(dir_.string()) + " && " + command + " >" +
                                 shellQuote(out) + " 2>" + shellQuote(err);
        const int status = std::system(full.c_str());
        if (status != -1 && WIFEXITED(status))
            r.code = WEXITSTATUS(status);
        else if (status != -1 && WIFSIGNALED(status))
            r.code = 128 + WTERMSIG(status);
        r.out = readFile(out);
        r.err = readFile(err);
        return r;
    }

    // Runs `order` with --json into the test folder and returns the document.
    json orderJson(std::vector<std::string> args, const std::string& name = "out.json") {
        args.insert(args.begin(), "order");
        args.push_back("--json");
        args.push_back(path(name));
        const RunResult r = run(args);
        EXPECT_EQ(r.code, 0) << r;
        EXPECT_TRUE(r.err.empty()) << r;
        try {
            return json::parse(readFile(path(name)));
        } catch (const std::exception& e) {
            ADD_FAILURE() << "invalid JSON from the tool: " << e.what() << r;
            return json::object();
        }
    }

    // Exactly one line on stderr, "vissort: error: ..." mentioning every needle, and the code.
    void expectError(const std::vector<std::string>& args, int code,
                     const std::vector<std::string>& needles) {
        const RunResult r = run(args);
        EXPECT_EQ(r.code, code) << r;
        EXPECT_LT(r.code, 124) << "crashed or hung" << r;
        const auto err_lines = lines(r.err);
        EXPECT_EQ(err_lines.size(), 1u) << "expected exactly one line on stderr" << r;
        EXPECT_FALSE(r.err.empty() || r.err.back() != '\n')
            << "stderr must end with a newline" << r;
        if (!err_lines.empty()) {
            EXPECT_EQ(err_lines[0].rfind("vissort: error: ", 0), 0u) << r;
            for (const std::string& needle : needles)
                EXPECT_NE(err_lines[0].find(needle), std::string::npos)
                    << "the error should name '" << needle << "'" << r;
        }
    }

    ScratchFolder scratch_;
    fs::path dir_; // scratch_'s path
};

} // namespace vissort
