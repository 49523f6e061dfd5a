// Output paths checked before any work (output_paths.h).

#include "cli/output_paths.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <unistd.h>

#include "vissort/atomic_file.h"

namespace vissort::cli {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) {
    return "'" + path.string() + "'";
}

} // namespace

std::string unwritableReason(const std::string& path) {
    if (path.empty() || path == "-")
        return {};
    const fs::path file(path);
    std::error_code error;
    if (fs::is_directory(file, error))
        return "cannot write " + quoted(file) + ": it is a folder";
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    const fs::file_status status = fs::status(folder, error);
    if (!fs::exists(status))
        return "cannot write " + quoted(file) + ": the folder " + quoted(folder) +
               " does not exist";
    if (!fs::is_directory(status))
        return "cannot write " + quoted(file) + ": " + quoted(folder) + " is not a folder";
    // The file if it is there, else the folder it would be made in.
    const fs::path target = fs::exists(file, error) ? file : folder;
    if (::access(target.c_str(), W_OK) != 0)
        return "cannot write " + quoted(file) + ": " + std::strerror(errno);
    return {};
}

std::string cannotWrite(const std::string& path) {
    return "cannot write " + path +
           (errno == 0 ? std::string() : ": " + std::string(std::strerror(errno)));
}

Status writeTextFile(const std::string& path, const std::function<void(std::ostream&)>& emit) {
    return writeFileAtomically(path, [&](const std::string& write_path) {
        errno = 0;
        std::ofstream file(write_path, std::ios::binary);
        if (file)
            emit(file);
        file.close();
        if (!file)
            return Status::failure(cannotWrite(path));
        return Status::ok();
    });
}

} // namespace vissort::cli
