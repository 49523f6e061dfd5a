#pragma once
// Feedback on long work: a progress bar with the rate and the time left on a terminal, plain
// lines when standard error is not one, nothing with --quiet or for work done within a second.

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

#include <CLI/CLI.hpp>

namespace vissort::cli {

/// Adds --quiet/-q: no progress, and none of the text for people on standard output (errors
/// and warnings still go to standard error; `--json -` and `--csv -` still write).
void addQuietOption(CLI::App& command);

/// With --quiet: what the command prints for people goes nowhere from this call on, while
/// `-` outputs still reach standard output (json_output.h's standardOutputBuffer).
void applyQuiet();

/// Progress of `total` units of work named `unit` ("frame"), shown on standard error under
/// `what` ("render"). update() may be called as often as wanted: the bar is drawn at most ten
/// times a second, plain lines every five seconds, the first after one second of work.
class Progress {
public:
    Progress(std::string what, uint64_t total, std::string unit);
    ~Progress(); // erases the bar
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// done units so far (a fraction of one inside a long unit), from any thread; detail, when
    /// given, says what is being done ("bunnies, 36 of them").
    void update(double done, const std::string& detail = "");
    /// Erases the bar before a line is printed to standard output, when that is the same
    /// terminal; the next update redraws it.
    void clear();

private:
    void draw(double done, double elapsed, const std::string& detail);
    void erase();

    std::string what_, unit_;
    uint64_t total_;
    bool terminal_, enabled_;
    bool shares_terminal_; // standard output is a terminal too: its lines would cross the bar
    double first_after_, line_every_;
    std::chrono::steady_clock::time_point start_, last_drawn_;
    bool drawn_ = false, ever_drawn_ = false;
    std::mutex mutex_;
};

} // namespace vissort::cli
