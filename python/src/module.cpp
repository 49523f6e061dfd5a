// The module vissort._vissort, re-exported by the package vissort (python/vissort/__init__.py).

#include <cstdlib>

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "vissort/camera_path.h"

PYBIND11_MODULE(_vissort, m) {
    m.doc() = "Visibility orderings of triangles from occlusion queries, exact order-independent "
              "transparency and collision detection (docs/python.md)";
    m.attr("__version__") = VISSORT_VERSION;
    m.attr("has_gl") = bool(VISSORT_WITH_GL);
    // Seconds between frames: frame f of a run is at time f * FRAME_INTERVAL, as the command
    // line's --frames.
    m.attr("FRAME_INTERVAL") = vissort::kFrameInterval;
    // As the vissort command does: Mesa's llvmpipe, read when the first context opens, then
    // rasterizes on the calling thread, 6 times faster for the oracle's many small draws
    // (docs/benchmarks.md). A value the user set stays.
    setenv("LP_NUM_THREADS", "0", 0);
    vissort::python::bindScene(m);
    vissort::python::bindCamera(m);
    vissort::python::bindOrder(m);
    vissort::python::bindRender(m);
    vissort::python::bindCollide(m);
    vissort::python::bindVolume(m);
    vissort::python::bindImage(m);
    vissort::python::bindFiles(m);
}
