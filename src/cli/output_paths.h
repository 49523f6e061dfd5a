#pragma once
// Output paths checked before any work: a run of minutes must not end in "cannot write" because
// the folder was mistyped.

#include <functional>
#include <ostream>
#include <string>

#include "vissort/result.h"

namespace vissort::cli {

/// Why `path` cannot be written, in a few words with the system's reason: its folder does not
/// exist or is not a folder, the path is a folder, or the system refuses it (no permission, a
/// read-only file system). Empty when it can be written, and for "" (no output) and "-"
/// (standard output). A frame pattern (frame_%04d.png) is checked by its folder.
std::string unwritableReason(const std::string& path);

/// "cannot write PATH: REASON" after a write that failed, REASON the system's (strerror(errno))
/// when it gave one: callers set errno to 0 before the write.
std::string cannotWrite(const std::string& path);

/// Writes the file at path whole or not at all (writeFileAtomically, atomic_file.h): emit writes
/// the text into a stream on a temporary file beside it. "cannot write PATH: REASON" on failure.
Status writeTextFile(const std::string& path, const std::function<void(std::ostream&)>& emit);

} // namespace vissort::cli
