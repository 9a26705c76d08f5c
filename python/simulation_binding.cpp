// sqdem.Simulation: a scene set up to run (scene/simulation.hpp), run from Python with the GIL
// released, callbacks every N steps, Ctrl-C and sim.stop() ending a run cleanly, the views of
// its stores (store_views.hpp) and the packing measures. Under mpirun the launched processes are
// the ranks of one run (launchedRanks), each Python process driving its rank.

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <optional>
#include <stdexcept>

#include "bindings.hpp"
#include "sqdem/distributed/mpi_communicator.hpp"
#include "sqdem/scene/particle_file.hpp"
#include "sqdem/scene/simulation.hpp"
#include "sqdem/world/packing_measures.hpp"
#include "store_views.hpp"

namespace py = pybind11;

namespace sqdem::python {
namespace {

/// A run's stop requests: sim.stop() from a callback, or SIGINT (Ctrl-C) while C++ runs.
struct StopFlags {
  volatile std::sig_atomic_t stop = 0;
  volatile std::sig_atomic_t interrupted = 0;
};
/// The flags of the innermost run under way (runs nest when a callback runs another simulation).
std::atomic<StopFlags*> running{nullptr};
static_assert(std::atomic<StopFlags*>::is_always_lock_free);
extern "C" void onInterrupt(int) {
  if (StopFlags* flags = running.load()) {
    flags->interrupted = 1;
    flags->stop = 1;
  }
}

struct NumericalTrouble : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The Python Simulation: the library's, and the callbacks Python registered.
class PySimulation final : public RunObserver {
 public:
  PySimulation(const Scene& scene, const RunOptions& options) : simulation_(scene, options, launchedRanks()) {}

  Simulation& simulation() { return simulation_; }
  const RunState& state() const { return state_; }
  /// The world, when its state may be read or set (RunState::requireIdle).
  World& world(const char* what) {
    state_.requireIdle(what);
    return simulation_.world();
  }

  void every(long steps, py::function callback) {
    if (steps < 1) throw py::value_error("every: the interval is a number of steps >= 1");
    if (state_.running) throw std::runtime_error("every: not while the simulation runs (register callbacks before run())");
    callbacks_.emplace_back(steps, std::move(callback));
  }

  /// Runs with the GIL released; raises what a callback raised, KeyboardInterrupt on Ctrl-C and
  /// NumericalTrouble; returns the outcome's name.
  std::string run(const RunLimit& limit, py::object self) {
    if (state_.running) throw std::runtime_error("run: the simulation is running already (called from its own callback?)");
    flags_.stop = 0;
    flags_.interrupted = 0;
    failure_.reset();
    RunOutcome outcome;
    {
      // Undone however the run ends: the handler restored, the run's state cleared.
      struct Running {
        PySimulation& s;
        StopFlags* outer;
        struct sigaction previous {};
        Running(PySimulation& simulation, PyObject* self) : s(simulation), outer(running.exchange(&simulation.flags_)) {
          s.state_.running = true;
          s.self_ = self;
          struct sigaction handler {};
          handler.sa_handler = onInterrupt;
          sigemptyset(&handler.sa_mask);
          sigaction(SIGINT, &handler, &previous);
        }
        ~Running() {
          sigaction(SIGINT, &previous, nullptr);
          running.store(outer);
          s.state_.running = false;
          s.self_ = nullptr;
        }
      } guard(*this, self.ptr());
      py::gil_scoped_release released;
      outcome = simulation_.run(*this, flags_.stop, limit).outcome;
    }
    if (failure_) {
      py::error_already_set failure = std::move(*failure_);
      failure_.reset();
      throw failure;
    }
    if (flags_.interrupted && outcome == RunOutcome::Interrupted) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
      throw py::error_already_set();
    }
    switch (outcome) {
      case RunOutcome::NumericalTrouble: throw NumericalTrouble(simulation_.runner().report().trouble);
      case RunOutcome::Interrupted: return "stopped";
      case RunOutcome::Paused: return "paused";
      case RunOutcome::Completed: return "completed";
    }
    return "";
  }

  /// Asked from a callback: the run ends after this step (with the latest checkpoint, if it writes files).
  void stop() { flags_.stop = 1; }

  // RunObserver: the callbacks due after this step (the runner agrees the answer over the ranks).
  bool wantsUpdate() override {
    const long step = simulation_.runner().report().totalSteps;
    return std::any_of(callbacks_.begin(), callbacks_.end(), [&](const auto& c) { return step % c.first == 0; });
  }
  void update(const StageSpec&, long, long, long, const World&) override {
    py::gil_scoped_acquire held;
    struct Waiting {  // the engine waits for the callbacks: they may read and set its state
      RunState& state;
      explicit Waiting(RunState& s) : state(s) { state.inCallback = true; }
      ~Waiting() { state.inCallback = false; }
    } waiting(state_);
    const long step = simulation_.runner().report().totalSteps;
    for (std::size_t k = 0; k < callbacks_.size(); ++k) {
      const auto& [every, callback] = callbacks_[k];
      if (step % every != 0 || failure_) continue;
      try {
        callback(py::handle(self_));
      } catch (py::error_already_set& e) {
        failure_.emplace(std::move(e));
        flags_.stop = 1;
      }
    }
  }

 private:
  Simulation simulation_;
  std::vector<std::pair<long, py::function>> callbacks_;
  PyObject* self_ = nullptr;  ///< the Python object during a run (the callbacks' argument)
  RunState state_;            ///< running: no second run, no new callbacks, no access from other threads
  StopFlags flags_;
  std::optional<py::error_already_set> failure_;
};

/// The index of the stage named `name` (ValueError naming the stages otherwise).
std::size_t stageNamed(const Scene& scene, const std::string& name) {
  std::string names;
  for (std::size_t k = 0; k < scene.stages.size(); ++k) {
    if (scene.stages[k].name == name) return k;
    names += (k ? ", " : "") + scene.stages[k].name;
  }
  throw py::value_error("no stage '" + name + "' (stages: " + names + ")");
}

}  // namespace

void bindSimulation(py::module_& m) {
  py::register_exception<NumericalTrouble>(m, "NumericalTrouble", PyExc_RuntimeError);

  bindStoreViews(m);

  py::class_<PySimulation>(m, "Simulation", "A scene set up to run (docs/python.md).")
      .def(py::init([](const Scene& scene, int threads, std::optional<std::string> out, bool overwrite, std::optional<std::string> name,
                       std::optional<std::string> resume, std::optional<std::string> simd) {
             RunOptions options;
             options.threads = threads;
             options.overwrite = overwrite;
             if (out) options.out = *out;
             if (name) options.name = *name;
             if (resume) options.resume = *resume;
             if (simd) options.simd = runnableSimdPath(*simd);
             return std::make_unique<PySimulation>(scene, options);
           }),
           py::arg("scene"), py::kw_only(), py::arg("threads") = 0, py::arg("out") = py::none(), py::arg("overwrite") = false,
           py::arg("name") = py::none(), py::arg("resume") = py::none(), py::arg("simd") = py::none(),
           "threads: a step's threads (0: OpenMP's default); out: the output directory (None: no files); name: the "
           "files' prefix (default: the scene's name); resume: a checkpoint to continue from.")
      .def("run", [](py::object self, std::optional<std::string> stage, std::optional<long> steps) {
             PySimulation& s = self.cast<PySimulation&>();
             RunLimit limit;
             if (stage) limit.stage = stageNamed(s.simulation().scene(), *stage);
             if (steps) {
               if (*steps < 0) throw py::value_error("steps: a count >= 0");
               limit.steps = *steps;
             }
             return s.run(limit, self);
           },
           py::arg("stage") = py::none(), py::arg("steps") = py::none(),
           "Runs every stage, or up to the end of `stage`, or `steps` steps; returns 'completed', 'paused' or "
           "'stopped' (sim.stop() from a callback); raises KeyboardInterrupt on Ctrl-C and NumericalTrouble.")
      .def("step", [](py::object self, long n) {
             if (n < 0) throw py::value_error("step: a count >= 0");
             RunLimit limit;
             limit.steps = n;
             return self.cast<PySimulation&>().run(limit, self);
           },
           py::arg("n") = 1, "Runs n steps (across stages).")
      .def("every", &PySimulation::every, py::arg("steps"), py::arg("callback"),
           "Calls callback(sim) after every `steps`-th step of the run (the run's step count).")
      .def("stop", &PySimulation::stop, "From a callback: ends the run after this step.")
      .def_property_readonly("particles", [](py::object self) {
        PySimulation& s = self.cast<PySimulation&>();
        return ParticleViews{self, s.simulation(), s.state()};
      })
      .def_property_readonly("contacts", [](py::object self) {
        PySimulation& s = self.cast<PySimulation&>();
        return ContactViews{self, s.simulation().world(), s.state()};
      })
      .def_property_readonly("time", [](PySimulation& s) { return s.world("time").time(); }, "Simulated time (s).")
      .def_property_readonly("step_count", [](PySimulation& s) { return s.simulation().runner().report().totalSteps; },
                             "Steps since the run began (the log's step column).")
      .def_property_readonly("stage", [](PySimulation& s) -> std::optional<std::string> {
        const std::size_t k = s.simulation().runner().progress().stage;
        if (k >= s.simulation().scene().stages.size()) return std::nullopt;
        return s.simulation().scene().stages[k].name;
      }, "The stage under way or next (None when every stage is done).")
      .def_property_readonly("stage_steps", [](PySimulation& s) { return s.simulation().plan().stageSteps; },
                             "Each stage's steps at the time step (its duration's; a stop criterion may end it sooner).")
      .def_property_readonly("finished", [](PySimulation& s) { return s.simulation().runner().finished(); })
      .def_property_readonly("time_step", [](PySimulation& s) { return s.simulation().world().timeStep(); }, "(s)")
      .def_property_readonly("threads", [](PySimulation& s) { return s.simulation().world().threads(); })
      .def_property_readonly("rank", [](PySimulation& s) { return s.simulation().world().communicator().rank(); },
                             "This process's rank (0 in one process; docs/python.md, 'Under MPI').")
      .def_property_readonly("ranks", [](PySimulation& s) { return s.simulation().world().communicator().size(); },
                             "The processes of the run (1 without mpirun).")
      .def("measures", [](PySimulation& s) {
             const World& w = s.world("measures");
             const PackingMeasures m = measurePacking(w);
             py::dict out;
             out["time"] = w.time();
             out["solid_fraction"] = m.solidFraction;
             out["coordination"] = m.meanCoordination;
             out["coordination_without_rattlers"] = m.meanCoordinationNonRattlers;
             out["bed_height"] = m.bedHeight;
             out["stress"] = Eigen::Matrix3d(m.stress);
             out["kinetic_energy"] = w.kineticEnergy();
             out["largest_overlap_ratio"] = m.largestOverlapRatio;
             out["yielded_fraction"] = m.yieldedFraction;
             return out;
           },
           "The packing's measures (docs/python.md: solid fraction, coordination, stress (Pa, compression "
           "positive), kinetic energy (J), ...).")
      .def("plate", [](PySimulation& s, std::size_t wall) {
             const PlateMeasures m = measurePlate(s.world("plate"), wall);
             py::dict out;
             out["gap"] = m.gap;
             out["pressure"] = m.pressure;
             out["porosity"] = m.porosity;
             return out;
           },
           py::arg("wall"),
           "A plate (a plane wall facing -z) pressing the bed onto the floor (a plane wall facing +z): its gap to the "
           "floor (m), its pressure (Pa) and the porosity between them.")
      .def("write_particles", [](PySimulation& s, const std::string& path) {
             writeParticleFile(path, s.world("write_particles"), s.simulation().scene().materials);
           },
           py::arg("path"), "Writes the particle file of the current state (the CLI's *_final_particles.csv).");
}

}  // namespace sqdem::python
