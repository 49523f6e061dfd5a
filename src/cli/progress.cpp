#include "cli/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/json_output.h"
#include "cli/text_output.h"

namespace vissort::cli {
namespace {

bool g_quiet = false;

// Discards what is written: standard output's buffer under --quiet.
class NullBuffer : public std::streambuf {
protected:
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

constexpr double kTerminalEvery = 0.1; // seconds between redraws of the bar

// Seconds before the first report and between plain lines: 1 and 5, or both
// VISSORT_PROGRESS_SECONDS (0 in the tests: every update reports).
double firstAfter() {
    const char* text = std::getenv("VISSORT_PROGRESS_SECONDS");
    return text && *text ? std::atof(text) : 1.0;
}
double lineEvery() {
    const char* text = std::getenv("VISSORT_PROGRESS_SECONDS");
    return text && *text ? std::atof(text) : 5.0;
}

std::string duration(double seconds) {
    std::ostringstream text;
    if (seconds < 60)
        text << int(std::ceil(seconds)) << " s";
    else if (seconds < 3600)
        text << int(seconds / 60) << " min " << int(std::fmod(seconds, 60)) << " s";
    else
        text << int(seconds / 3600) << " h " << int(std::fmod(seconds, 3600) / 60) << " min";
    return text.str();
}

} // namespace

void addQuietOption(CLI::App& command) {
    command.add_flag_callback(
        "--quiet,-q", [] { g_quiet = true; },
        "No progress and no report on standard output (errors and warnings still on standard "
        "error)");
}

void applyQuiet() {
    if (!g_quiet)
        return;
    // Never destroyed: std::cout is flushed at exit, after function-local statics are gone.
    static NullBuffer* const nowhere = new NullBuffer;
    reserveStandardOutputFor("-"); // keeps standard output for `-` outputs
    std::cout.rdbuf(nowhere);
}

Progress::Progress(std::string what, uint64_t total, std::string unit)
    : what_(std::move(what)), unit_(std::move(unit)), total_(std::max<uint64_t>(total, 1)),
      terminal_(isatty(STDERR_FILENO) == 1), enabled_(!g_quiet),
      shares_terminal_(terminal_ && isatty(STDOUT_FILENO) == 1), first_after_(firstAfter()),
      line_every_(lineEvery()), start_(std::chrono::steady_clock::now()), last_drawn_(start_) {}

Progress::~Progress() {
    erase();
}

void Progress::clear() {
    if (shares_terminal_)
        erase();
}

void Progress::erase() {
    std::lock_guard lock(mutex_);
    if (drawn_ && terminal_)
        std::cerr << "\r\033[K" << std::flush;
    drawn_ = false;
}

void Progress::update(double done, const std::string& detail) {
    if (!enabled_)
        return;
    std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double since = std::chrono::duration<double>(now - last_drawn_).count();
    if (elapsed < first_after_ ||
        (ever_drawn_ && since < (terminal_ ? std::min(kTerminalEvery, line_every_) : line_every_)))
        return;
    last_drawn_ = now;
    draw(done, elapsed, detail);
}

void Progress::draw(double done, double elapsed, const std::string& detail) {
    const double share = std::clamp(done / double(total_), 0.0, 1.0);
    std::ostringstream text;
    text << what_ << ' ';
    if (terminal_) {
        constexpr int kWidth = 24;
        const int filled = int(share * kWidth);
        text << '[' << std::string(filled, '#') << std::string(kWidth - filled, '-') << "] ";
    }
    if (total_ > 1) {
        text << uint64_t(done) << '/' << counted(total_, unit_);
        if (done >= 1)
            text << ", " << std::fixed << std::setprecision(done / elapsed < 10 ? 2 : 1)
                 << done / elapsed << ' ' << unit_ << "s/s";
    } else {
        text << int(share * 100) << '%';
    }
    if (share > 0)
        text << ", " << duration(elapsed * (1 - share) / share) << " left";
    if (!detail.empty())
        text << " (" << detail << ')';
    if (terminal_)
        std::cerr << "\r\033[K" << text.str() << std::flush;
    else
        std::cerr << text.str() << '\n';
    drawn_ = ever_drawn_ = true;
}

} // namespace vissort::cli
