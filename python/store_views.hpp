#pragma once
// sqdem.Particles and sqdem.Contacts: views of a Simulation's stores (store_views.cpp).

#include <pybind11/pybind11.h>

#include "sqdem/scene/simulation.hpp"

namespace sqdem::python {

/// This process's particles in storage order; `owner` (the Python Simulation) keeps the memory.
struct ParticleViews {
  pybind11::object owner;
  Simulation& simulation;
};

/// The contact store, one row per candidate pair of the neighbour list.
struct ContactViews {
  pybind11::object owner;
  World& world;
};

void bindStoreViews(pybind11::module_& m);

}  // namespace sqdem::python
