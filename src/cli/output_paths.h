#pragma once
// Output paths checked before any work: a run of minutes must not end in "cannot write" because
// the folder was mistyped.

#include <string>

namespace vissort::cli {

/// Why `path` cannot be written, in a few words with the system's reason: its folder does not
/// exist or is not a folder, the path is a folder, or the system refuses it (no permission, a
/// read-only file system). Empty when it can be written, and for "" (no output) and "-"
/// (standard output). A frame pattern (frame_%04d.png) is checked by its folder.
std::string unwritableReason(const std::string& path);

/// The system's reason for the last failed call (strerror(errno)), or "" when errno is 0: for
/// the "cannot write" of a write that failed after all.
std::string lastSystemError();

/// ": REASON", or "" without one: what follows "cannot write FILE".
inline std::string withReason(const std::string& reason) {
    return reason.empty() ? std::string() : ": " + reason;
}

} // namespace vissort::cli
