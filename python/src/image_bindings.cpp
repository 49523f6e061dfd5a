// vissort.write_image: an (H, W, 4) uint8 RGBA array as a PNG or JPEG file, by the name's
// extension, with the command line's writer (stb), so that a batch of renders needs nothing
// besides numpy to save its frames.

#include <cstring>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "bindings.h"
#include "vissort/image.h"

namespace py = pybind11;

namespace vissort::python {

void bindImage(py::module_& m) {
    m.def(
        "write_image",
        [](const py::object& path, const py::array& image) {
            const std::string name = py::str(path);
            if (image.ndim() != 3 || image.shape(2) != 4 || image.shape(0) < 1 ||
                image.shape(1) < 1) {
                std::string shape;
                for (py::ssize_t i = 0; i < image.ndim(); ++i) {
                    if (i > 0)
                        shape += ", ";
                    shape += std::to_string(image.shape(i));
                }
                throw py::value_error("image must be an (H, W, 4) RGBA array, got shape (" + shape +
                                      ")");
            }
            if (!image.dtype().is(py::dtype::of<uint8_t>()))
                throw py::value_error("image must be uint8, got " +
                                      std::string(py::str(image.dtype())));
            const auto pixels =
                py::array_t<uint8_t, py::array::c_style | py::array::forcecast>(image);
            std::vector<uint8_t> rgba(std::size_t(pixels.size()));
            std::memcpy(rgba.data(), pixels.data(), rgba.size());
            const auto height = uint32_t(image.shape(0)), width = uint32_t(image.shape(1));
            Status written;
            {
                py::gil_scoped_release release;
                written = writeImage(name, width, height, rgba);
            }
            if (!written)
                throw py::value_error(written.error);
        },
        py::arg("path"), py::arg("image"),
        "Writes an (H, W, 4) uint8 RGBA image, row 0 at the top, as PNG or JPEG by path's "
        "extension (.png, .jpg, .jpeg); ValueError naming the problem otherwise");
}

} // namespace vissort::python
