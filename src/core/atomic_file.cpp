// Files written whole or not at all (atomic_file.h).

#include "vissort/atomic_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <optional>
#include <random>
#include <system_error>

namespace vissort {
namespace {

namespace fs = std::filesystem;

// The temporary files of writes in progress, where a signal handler can read them: a slot is
// taken (1), filled, then published (2); the handler unlinks only published names.
constexpr std::size_t kSlots = 64, kSlotBytes = 4096;
struct PendingSlot {
    std::atomic<int> state{0};
    char path[kSlotBytes] = {};
};
std::array<PendingSlot, kSlots> g_pending;

// The slot holding path, or -1 when every slot is taken or the name is too long (the write
// still happens; only a signal's clean-up would miss it).
int publishPending(const std::string& path) {
    if (path.size() >= kSlotBytes)
        return -1;
    for (std::size_t i = 0; i < kSlots; ++i) {
        int free_state = 0;
        if (g_pending[i].state.compare_exchange_strong(free_state, 1)) {
            std::memcpy(g_pending[i].path, path.c_str(), path.size() + 1);
            g_pending[i].state.store(2);
            return int(i);
        }
    }
    return -1;
}

void releasePending(int slot) {
    if (slot >= 0)
        g_pending[std::size_t(slot)].state.store(0);
}

// Eight hex digits; a name already taken is tried again ("x" mode below).
std::string randomSuffix() {
    thread_local std::mt19937 random{std::random_device{}()};
    char text[9];
    std::snprintf(text, sizeof text, "%08x", unsigned(random()));
    return text;
}

// Creates a new, empty temporary file beside target (never an existing one: "x" mode) and
// returns its path, or "" with errno set when the folder refuses it.
std::string createTemporaryBeside(const fs::path& target) {
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    // A name near the system's limit of 255 bytes would not take the additions.
    const std::string name = target.filename().string().substr(0, 200);
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path candidate =
            folder / ("." + name + ".vissort-" + randomSuffix() + ".partial");
        errno = 0;
        if (std::FILE* file = std::fopen(candidate.c_str(), "wbx")) {
            std::fclose(file);
            return candidate.string();
        }
        if (errno != EEXIST)
            return {};
    }
    errno = EEXIST;
    return {};
}

// Called with each written temporary file before its rename (setBeforeRenameHook).
std::function<void(const std::string&)> g_before_rename;

} // namespace

struct AtomicFile::State {
    std::string target;    // the file replaced at commit (a link's file, not the link)
    std::string shown;     // the path as the caller gave it, for messages
    std::string temporary; // empty when written in place
    std::optional<fs::perms> permissions; // an existing file's, given to its replacement
    int slot = -1;
    bool committed = false;

    ~State() {
        if (!temporary.empty() && !committed)
            std::remove(temporary.c_str());
        releasePending(slot);
    }
    const std::string& writePath() const { return temporary.empty() ? shown : temporary; }
};

AtomicFile::AtomicFile(std::unique_ptr<State> state) : state_(std::move(state)) {}
AtomicFile::AtomicFile(AtomicFile&&) noexcept = default;
AtomicFile& AtomicFile::operator=(AtomicFile&&) noexcept = default;
AtomicFile::~AtomicFile() = default;

Result<AtomicFile> AtomicFile::begin(const std::string& path) {
    auto state = std::make_unique<State>();
    state->shown = path;
    std::error_code error;
    fs::path target(path);
    // A link's file is the one replaced: renaming onto the link would replace the link.
    if (fs::is_symlink(fs::symlink_status(target, error))) {
        const fs::path resolved = fs::weakly_canonical(target, error);
        if (!error)
            target = resolved;
    }
    state->target = target.string();
    const fs::file_status status = fs::status(target, error);
    const bool exists = fs::exists(status);
    if (exists && !fs::is_regular_file(status))
        return {AtomicFile(std::move(state)), ""}; // /dev/null, a FIFO: no name to replace
    if (exists)
        state->permissions = status.permissions();
    state->temporary = createTemporaryBeside(target);
    if (state->temporary.empty()) {
        if (exists && (errno == EACCES || errno == EPERM || errno == EROFS))
            return {AtomicFile(std::move(state)), ""}; // the folder takes no new file
        return Result<AtomicFile>::failure("cannot write " + path + ": " + std::strerror(errno));
    }
    state->slot = publishPending(state->temporary);
    return {AtomicFile(std::move(state)), ""};
}

const std::string& AtomicFile::writePath() const {
    return state_->writePath();
}

Status AtomicFile::commit() {
    State& state = *state_;
    if (state.committed)
        return Status::failure("cannot write " + state.shown + ": already committed");
    state.committed = true;
    if (state.temporary.empty())
        return Status::ok();
    std::error_code error;
    if (state.permissions)
        fs::permissions(state.temporary, *state.permissions, error); // best effort
    if (g_before_rename)
        g_before_rename(state.temporary);
    fs::rename(state.temporary, state.target, error);
    if (error) {
        state.committed = false; // the temporary file is still there: removed with the state
        return Status::failure("cannot write " + state.shown + ": " + error.message());
    }
    return Status::ok();
}

Status writeFileAtomically(const std::string& path,
                           const std::function<Status(const std::string& write_path)>& write) {
    Result<AtomicFile> file = AtomicFile::begin(path);
    if (!file)
        return Status::failure(file.error);
    if (Status written = write(file.value->writePath()); !written)
        return written;
    return file.value->commit();
}

void setBeforeRenameHook(std::function<void(const std::string& temporary)> hook) {
    g_before_rename = std::move(hook);
}

void removeTemporaryFilesOfWritesInProgress() noexcept {
    for (PendingSlot& slot : g_pending)
        if (slot.state.load() == 2)
            std::remove(slot.path);
}

} // namespace vissort
