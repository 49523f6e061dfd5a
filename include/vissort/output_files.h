#pragma once
// Never overwrite an input: the files a run will write compared, before any work, with the files
// it reads and with one another, and the frame patterns (frame_%04d.png) that name a file a
// frame. One rule for the command line and the Python module (docs/cli.md, "Inputs are never
// overwritten"). Standard library only.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <memory>
#include <string>
#include <vector>

namespace vissort {

/// Whether path is a frame pattern, "frame_%04d.png" and the like: exactly one %d conversion
/// (flags 0-9 only), no other '%'.
bool isFramePattern(const std::string& path);

/// The pattern's path for one frame.
std::string framePath(const std::string& pattern, int frame);

/// A file a run reads or writes, named as its user knows it.
struct FileUse {
    std::string what; // the option ("--json", "-o") or the input ("the scene file")
    std::string path;
    /// For a frame pattern, how many frames it names, from first_frame on; 0 for a plain path.
    int frames = 0;
    int first_frame = 0;
};

/// A run's outputs, each pattern taken apart once, to be compared with its inputs (known at
/// once, or only once a scene is read) and with one another. Outputs "" and "-" (standard
/// output) are no files, and neither are special files (/dev/null, a FIFO): writing there
/// replaces nothing, so any number of outputs may go there.
///
/// Two paths are one file when both exist and are (device and inode: a hard link, a symbolic
/// link, a `./dir/../file` spelling), or neither exists and their resolved paths (links and
/// `..` followed) are equal. A frame pattern's frames are matched by shape (its folder, the
/// name's prefix, number and suffix, and the pattern's own spelling of the number: frame_2.png
/// is no frame of frame_%04d.png); up to 4,096 frames, its frame files that exist and are links
/// are also compared as files. A pattern of 100,000 frames is never listed on disk.
class OutputFiles {
public:
    explicit OutputFiles(std::vector<FileUse> outputs = {});
    OutputFiles(OutputFiles&&) noexcept;
    OutputFiles& operator=(OutputFiles&&) noexcept;
    ~OutputFiles();

    /// An output that is one of inputs, in one line naming both and the path ("--json 'a.obj'
    /// is the scene file 'a.obj': vissort never overwrites an input; choose another path");
    /// empty when there is none.
    std::string clashWith(const std::vector<FileUse>& inputs) const;
    /// Two outputs that are one file, in one line naming both and the path ("... are one file:
    /// give each output its own path"); empty when there is none.
    std::string clashAmongThemselves() const;

private:
    struct Prepared;
    std::vector<FileUse> outputs_;
    std::vector<std::unique_ptr<Prepared>> prepared_; // one per output that is a file
};

} // namespace vissort
