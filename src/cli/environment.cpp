#include "cli/environment.h"

#include <charconv>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <thread>

#include "vissort/atomic_file.h"

#if VISSORT_WITH_GL
#include "vissort/gl_context.h"
#endif

namespace vissort::cli {
namespace {

// One thread by default, as the library: on the 2-core VM a second thread has not paid yet (the
// bind and the depth images run on one; docs/benchmarks.md, "Threads"), so the cores are the
// user's to give (--threads, VISSORT_THREADS).
OracleOptions oracle_options;
std::optional<uint32_t> threads_option;

constexpr uint32_t kMaxThreads = 256;

// The variable's value, or empty when unset.
std::string_view variable(const char* name) {
    const char* value = std::getenv(name);
    return value == nullptr ? std::string_view{} : std::string_view(value);
}

} // namespace

Status applyEnvironment() {
    // Read by Mesa when the first display opens; a value the user set stays.
    setenv("LP_NUM_THREADS", "0", 0);
    if (std::string_view threads = variable("VISSORT_THREADS"); !threads.empty()) {
        uint32_t value = 0;
        const auto [end, error] =
            std::from_chars(threads.data(), threads.data() + threads.size(), value);
        if (error != std::errc{} || end != threads.data() + threads.size() || value > kMaxThreads)
            return Status::failure(
                "VISSORT_THREADS must be a whole number from 0 (one per core) to " +
                std::to_string(kMaxThreads) + ", not '" + std::string(threads) + "'");
        oracle_options.threads = value;
    }
    if (threads_option)
        oracle_options.threads = *threads_option;
    if (std::string_view simd = variable("VISSORT_SIMD"); !simd.empty()) {
        if (simd != "0" && simd != "1")
            return Status::failure("VISSORT_SIMD must be 0 or 1, not '" + std::string(simd) + "'");
        oracle_options.allow_simd = simd == "1";
    }
    if (std::string_view pause = variable("VISSORT_TEST_PAUSE_BEFORE_RENAME"); !pause.empty()) {
        double seconds = 0;
        const auto [end, error] =
            std::from_chars(pause.data(), pause.data() + pause.size(), seconds);
        if (error != std::errc{} || end != pause.data() + pause.size() || !(seconds >= 0))
            return Status::failure("VISSORT_TEST_PAUSE_BEFORE_RENAME must be seconds, not '" +
                                   std::string(pause) + "'");
        setBeforeRenameHook([seconds](const std::string& temporary) {
            std::cerr << "vissort: test pause before renaming " << temporary << std::endl;
            std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
        });
    }
#if VISSORT_WITH_GL
    if (std::string_view platform = variable("VISSORT_GL_PLATFORM"); !platform.empty()) {
        Result<GlPlatform> parsed = parseGlPlatform(platform);
        // Only the commands that need OpenGL fail: the cpu oracle still works.
        if (parsed)
            GlContext::setSharedPlatform(*parsed.value);
        else
            GlContext::refuseShared("no OpenGL context: VISSORT_GL_PLATFORM: " + parsed.error);
    }
#endif
    return Status::ok();
}

void addThreadsOption(CLI::App& command) {
    command
        .add_option_function<uint32_t>(
            "--threads", [](const uint32_t& threads) { threads_option = threads; },
            "Threads of the cpu oracle's passes, the calling one included (default 1; 0: one "
            "per core; the order never depends on it); over VISSORT_THREADS")
        ->check(CLI::Range(uint32_t(0), kMaxThreads))
        ->type_name("N");
}

const OracleOptions& environmentOracleOptions() {
    return oracle_options;
}

} // namespace vissort::cli
