#pragma once
// Checks the element counts that a mesh file's header declares against what the file's size
// can hold, before assimp sees the file. Internal to src/scene/.
//
// Why: several of assimp's readers allocate (and zero) storage for the declared counts before
// reading a single element. A 309-byte OFF file declaring 3.5 billion vertices made assimp take
// 89 s and 15.8 GB before it failed; a 189-byte ASCII PLY declaring 2 billion vertices grew past
// 10.8 GB in a minute. A count that the file's bytes cannot possibly hold is refused here, in
// microseconds, with a message naming the count and the size.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace vissort::detail {

/// How many bytes of a file's start `declaredSizeProblem` looks at: enough for any header it
/// reads (a PLY header without end_header in this many bytes is refused).
inline constexpr std::size_t kDeclaredSizeHeadBytes = 64 * 1024;

/// Empty when the counts declared by the header of `head` (the first kDeclaredSizeHeadBytes of a
/// file of `file_size` bytes, or all of it where declaredSizesNeedWholeFile) fit in the file, else
/// a one-line
/// problem without the file's name. `extension` is the file's, lowercase or not, without the dot.
/// Checked: PLY (ASCII and binary, by its "ply" signature), OFF and its variants (COFF, NOFF,
/// STOFF, 4OFF, nOFF; by extension or keyword), binary STL and classic NFF (by extension), text
/// and binary DirectX, Caligari trueSpace and binary glTF (by signature). Anything
/// else, and any header this does not understand, gives an empty answer: assimp then decides.
std::string declaredSizeProblem(std::string_view head, uint64_t file_size,
                                std::string_view extension);

/// Whether declaredSizeProblem needs the whole file rather than its first bytes (`head`):
/// formats whose counts can be anywhere (NFF by extension; text and binary DirectX and
/// Caligari by signature). Checked in full up to kDeclaredSizeWholeFileBytes.
bool declaredSizesNeedWholeFile(std::string_view extension, std::string_view head);

/// The largest file read whole for declaredSizeProblem; a larger one is checked on its start.
inline constexpr uint64_t kDeclaredSizeWholeFileBytes = 64ull * 1024 * 1024;

} // namespace vissort::detail
