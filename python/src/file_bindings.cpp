// The command line's rules for files, for vissort.batch (private: vissort._vissort._NAME): no
// output is an input or another output (output_files.h), and a file is written whole or not
// at all (atomic_file.h).

#include <string>
#include <tuple>
#include <vector>

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "vissort/atomic_file.h"
#include "vissort/output_files.h"

namespace py = pybind11;

namespace vissort::python {

void bindFiles(py::module_& m) {
    m.def("_is_frame_pattern", &isFramePattern, py::arg("path"),
          "Whether path holds exactly one %d field (flags 0-9 only) and no other '%'");
    m.def(
        "_output_clash",
        [](const std::vector<std::tuple<std::string, std::string>>& inputs,
           const std::vector<std::tuple<std::string, std::string, int, int>>& outputs) {
            std::vector<FileUse> read, written;
            for (const auto& [what, path] : inputs)
                read.push_back({what, path});
            for (const auto& [what, path, first_frame, frames] : outputs)
                written.push_back({what, path, frames, first_frame});
            const OutputFiles files(std::move(written));
            std::string clash = files.clashWith(read);
            return clash.empty() ? files.clashAmongThemselves() : clash;
        },
        py::arg("inputs"), py::arg("outputs"),
        "inputs: (what, path) each; outputs: (what, path, first_frame, frames), frames 0 for a "
        "plain path. The first clash in one line, or ''");
    m.def(
        "_write_file_atomically",
        [](const std::string& path, const std::function<void(const std::string&)>& write) {
            // write's Python exception passes through: the temporary file is removed on the way.
            const Status written = writeFileAtomically(path, [&](const std::string& write_path) {
                write(write_path);
                return Status::ok();
            });
            if (!written)
                throw py::value_error(written.error);
        },
        py::arg("path"), py::arg("write"),
        "Calls write(temporary_path) and renames the file it wrote onto path; ValueError naming "
        "the problem");
}

} // namespace vissort::python
