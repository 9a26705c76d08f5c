#pragma once
// The parts of the Python module (module.cpp), one concern each.

#include <pybind11/pybind11.h>

namespace sqdem::python {

/// sqdem.Scene (load, from_dict, from_text) and sqdem.SceneError.
void bindScene(pybind11::module_& m);
/// sqdem.Simulation: runs, callbacks, measures (and the views' classes, bindStoreViews).
void bindSimulation(pybind11::module_& m);
/// sqdem.contact (the single-contact driver) and sqdem.geometry (the detector on one pair).
void bindProbes(pybind11::module_& m);

}  // namespace sqdem::python
