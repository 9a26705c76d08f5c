#pragma once
// sqdem.Particles and sqdem.Contacts: views of a Simulation's stores (store_views.cpp).

#include <pybind11/pybind11.h>

#include "run_state.hpp"
#include "sqdem/scene/simulation.hpp"

namespace sqdem::python {

/// This process's particles in storage order; `owner` (the Python Simulation) keeps the memory
/// and the run's state.
struct ParticleViews {
  pybind11::object owner;
  Simulation& simulation;
  const RunState& state;
};

/// The contact store, one row per candidate pair of the neighbour list.
struct ContactViews {
  pybind11::object owner;
  const World& world;
  const RunState& state;
};

void bindStoreViews(pybind11::module_& m);

}  // namespace sqdem::python
