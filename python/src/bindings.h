#pragma once
// The parts of the module, each adding its classes and functions (module.cpp calls them in
// this order: later parts use the earlier parts' types in their signatures).

#include <pybind11/pybind11.h>

namespace vissort::python {

void bindScene(pybind11::module_& m);
void bindCamera(pybind11::module_& m);
void bindOrder(pybind11::module_& m);
void bindRender(pybind11::module_& m);
void bindCollide(pybind11::module_& m);
void bindVolume(pybind11::module_& m);
void bindImage(pybind11::module_& m);
void bindFiles(pybind11::module_& m);

} // namespace vissort::python
