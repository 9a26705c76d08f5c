#pragma once
// Whether a Python Simulation's engine is computing: while run() works without the GIL, another
// Python thread must neither read nor set its state (a data race, and under MPI collective calls
// out of order); between runs and from its callbacks (the engine waits for them) it may.

#include <stdexcept>
#include <string>

namespace sqdem::python {

struct RunState {
  bool running = false;     ///< run() is under way
  bool inCallback = false;  ///< ... and waits for a callback

  /// RuntimeError naming `what` while the engine computes.
  void requireIdle(const char* what) const {
    if (running && !inCallback) {
      throw std::runtime_error(std::string(what) + ": not while the simulation runs (from another thread); read and set "
                               "its state from its callbacks or between runs");
    }
  }
};

}  // namespace sqdem::python
