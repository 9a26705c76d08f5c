// The Python module `sqdem` (pybind11): a thin binding of the library (docs/python.md). Each
// part binds one concern; no physics and no validation live here (the library checks every
// input and raises SceneError / InputError with its messages).

#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(sqdem, m) {
  m.doc() = "sqdem: DEM of superquadric and ellipsoidal particles (docs/python.md)";
  sqdem::python::bindScene(m);
  sqdem::python::bindSimulation(m);
  sqdem::python::bindProbes(m);
}
