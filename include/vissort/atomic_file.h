#pragma once
// Files written whole or not at all: every file vissort writes goes first to a temporary file in
// its target's folder and is renamed onto the target once complete (rename within one file
// system replaces the name in one step). A reader never sees half a file, and a run that fails
// or is killed mid-write leaves the old file, or none, where the new one was going: never a
// truncated one. Standard library only.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <functional>
#include <memory>
#include <string>

#include "vissort/result.h"

namespace vissort {

/// One file being written whole or not at all, for writers that stream over a long run (a
/// pairs file written frame by frame): open writePath(), write, close, then commit(). Destroyed
/// uncommitted, it removes its temporary file and the target is untouched. The rules are
/// writeFileAtomically's.
class AtomicFile {
public:
    /// Creates the temporary file beside path; an error naming path and the system's reason
    /// when its folder refuses it.
    static Result<AtomicFile> begin(const std::string& path);
    AtomicFile(AtomicFile&&) noexcept;
    AtomicFile& operator=(AtomicFile&&) noexcept;
    ~AtomicFile();

    /// Where to write: the temporary file, or path itself when it is written in place.
    const std::string& writePath() const;
    /// Renames the written temporary file onto the target (once; nothing after).
    Status commit();

private:
    struct State;
    explicit AtomicFile(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

/// Writes `path` through `write`, which writes a whole file at the path it is given: a new
/// temporary file beside the target (".NAME.vissort-XXXXXXXX.partial"), renamed onto `path`
/// when `write` succeeds, removed when it fails (its error is returned as it is). An existing
/// file keeps its permission bits; a symbolic link is followed (the file it names is replaced,
/// the link stays). Special files (/dev/null, a FIFO, a terminal) and files in a folder that
/// refuses new files but whose file may be written are written in place, as before: there is
/// nothing to replace there, or no other way to write them.
Status writeFileAtomically(const std::string& path,
                           const std::function<Status(const std::string& write_path)>& write);

/// Calls hook with each written temporary file just before its rename (none: no call). For the
/// tests of a run killed mid-write, which hold it there (the command line's
/// VISSORT_TEST_PAUSE_BEFORE_RENAME); set it before any write starts.
void setBeforeRenameHook(std::function<void(const std::string& temporary)> hook);

/// Removes the temporary files of the writes in progress in this process. For a handler of
/// SIGINT or SIGTERM that then ends the process: it only unlinks names kept in fixed slots (no
/// allocation, no lock). A process killed by SIGKILL leaves its temporary file behind, beside
/// the untouched target.
void removeTemporaryFilesOfWritesInProgress() noexcept;

} // namespace vissort
