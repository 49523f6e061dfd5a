#pragma once
// Never overwrite an input: every file a command writes is compared, before any work, with
// every file it reads and with its other outputs. A clash is one line naming both options and
// the path (issue 56; docs/cli.md, "Outputs").

#include <string>
#include <vector>

namespace vissort::cli {

/// A file a command reads or writes, named as the user knows it.
struct FileUse {
    std::string what; // the option ("--json", "-o") or the input ("the scene file")
    std::string path;
    /// A frame pattern (frame_%04d.png, output_paths.h) naming frames 0 to frames - 1; 0 for
    /// a plain path.
    int frames = 0;
};

/// Why two of these uses are one file, in one line naming both and the path; empty when they
/// are all distinct. Outputs "" and "-" (standard output) are skipped, and so are special files
/// (/dev/null, a FIFO): writing there replaces nothing. Existing files are the same when they
/// are (device and inode: a hard link, a symbolic link, a `./dir/../file` spelling); files not
/// there yet when their resolved paths (links and `..` followed) are. A frame pattern's frames
/// are checked by shape (its folder, the name's prefix, number and suffix) and, up to 4,096
/// frames, each existing frame file as a file: a pattern of 100,000 frames is never listed.
std::string findClash(const std::vector<FileUse>& inputs, const std::vector<FileUse>& outputs);

/// The outputs of this run, declared once the command line is read, so that an input known
/// only once the scene is loaded (a JSON scene's meshes, an OBJ's .mtl) is checked before any
/// work too (checkInputs).
void declareOutputs(std::vector<FileUse> outputs);

/// findClash(inputs, the declared outputs).
std::string checkInputs(const std::vector<FileUse>& inputs);

} // namespace vissort::cli
