// sqdem.Simulation: a scene set up to run (scene/simulation.hpp), run from Python with the GIL
// released, callbacks every N steps, Ctrl-C and sim.stop() ending a run cleanly, zero-copy views
// of the particle and contact stores (views.hpp) and the packing measures.

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <signal.h>

#include <algorithm>
#include <csignal>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "bindings.hpp"
#include "sqdem/scene/particle_file.hpp"
#include "sqdem/scene/simulation.hpp"
#include "sqdem/world/packing_measures.hpp"
#include "views.hpp"

namespace py = pybind11;

namespace sqdem::python {
namespace {

/// Raised by the run: SIGINT (Ctrl-C) while C++ runs, or sim.stop() from a callback.
volatile std::sig_atomic_t stopRequested = 0;
volatile std::sig_atomic_t interrupted = 0;
extern "C" void onInterrupt(int) {
  interrupted = 1;
  stopRequested = 1;
}

struct NumericalTrouble : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The Python Simulation: the library's, and the callbacks Python registered.
class PySimulation final : public RunObserver {
 public:
  PySimulation(const Scene& scene, const RunOptions& options) : simulation_(scene, options) {}

  Simulation& simulation() { return simulation_; }
  World& world() { return simulation_.world(); }

  void every(long steps, py::function callback) {
    if (steps < 1) throw py::value_error("every: the interval is a number of steps >= 1");
    if (running_) throw std::runtime_error("every: not while the simulation runs (register callbacks before run())");
    callbacks_.emplace_back(steps, std::move(callback));
  }

  /// Runs with the GIL released; raises what a callback raised, KeyboardInterrupt on Ctrl-C and
  /// NumericalTrouble; returns the outcome's name.
  std::string run(const RunLimit& limit, py::object self) {
    if (running_) throw std::runtime_error("run: the simulation is running already (called from its own callback?)");
    stopRequested = 0;
    interrupted = 0;
    failure_.reset();
    RunOutcome outcome;
    {
      // Undone however the run ends: the handler restored, the run's state cleared.
      struct Running {
        PySimulation& s;
        struct sigaction previous {};
        Running(PySimulation& simulation, PyObject* self) : s(simulation) {
          s.running_ = true;
          s.self_ = self;
          struct sigaction handler {};
          handler.sa_handler = onInterrupt;
          sigemptyset(&handler.sa_mask);
          sigaction(SIGINT, &handler, &previous);
        }
        ~Running() {
          sigaction(SIGINT, &previous, nullptr);
          s.running_ = false;
          s.self_ = nullptr;
        }
      } running(*this, self.ptr());
      py::gil_scoped_release released;
      outcome = simulation_.run(*this, stopRequested, limit).outcome;
    }
    if (failure_) {
      py::error_already_set failure = std::move(*failure_);
      failure_.reset();
      throw failure;
    }
    if (interrupted && outcome == RunOutcome::Interrupted) {
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
  void stop() { stopRequested = 1; }

  // RunObserver: the callbacks due after this step (the runner agrees the answer over the ranks).
  bool wantsUpdate() override {
    const long step = simulation_.runner().report().totalSteps;
    return std::any_of(callbacks_.begin(), callbacks_.end(), [&](const auto& c) { return step % c.first == 0; });
  }
  void update(const StageSpec&, long, long, long, const World&) override {
    py::gil_scoped_acquire held;
    const long step = simulation_.runner().report().totalSteps;
    for (std::size_t k = 0; k < callbacks_.size(); ++k) {
      const auto& [every, callback] = callbacks_[k];
      if (step % every != 0 || failure_) continue;
      try {
        callback(py::handle(self_));
      } catch (py::error_already_set& e) {
        failure_.emplace(std::move(e));
        stopRequested = 1;
      }
    }
  }

 private:
  Simulation simulation_;
  std::vector<std::pair<long, py::function>> callbacks_;
  PyObject* self_ = nullptr;  ///< the Python object during a run (the callbacks' argument)
  bool running_ = false;      ///< run() is under way: no second run, no new callbacks
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

/// Views of the particle store (this process's particles, in storage order).
struct ParticleViews {
  py::object owner;
  World& world;
};

/// Views of the contact store: one row per candidate pair, `acting` marks the contacts.
struct ContactViews {
  py::object owner;
  World& world;
};

Vec3 semiAxes(const World& world, std::size_t i) { return world.shapes()[world.particles().shape[i]].halfExtents(); }

/// The particles' state as copies, in id order.
py::dict sortedById(const World& world) {
  const ParticleStore& p = world.particles();
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  const auto n = static_cast<py::ssize_t>(p.size());
  py::array_t<std::uint32_t> id(n), material(n);
  py::array_t<double> position({n, py::ssize_t{3}}), orientation({n, py::ssize_t{4}}), velocity({n, py::ssize_t{3}}),
      spin({n, py::ssize_t{3}}), force({n, py::ssize_t{3}}), torque({n, py::ssize_t{3}}), axes({n, py::ssize_t{3}}),
      exponents({n, py::ssize_t{2}});
  for (py::ssize_t r = 0; r < n; ++r) {
    const std::size_t i = order[static_cast<std::size_t>(r)];
    id.mutable_at(r) = p.id[i];
    material.mutable_at(r) = p.material[i];
    const Superquadric& s = world.shapes()[p.shape[i]];
    for (int d = 0; d < 3; ++d) {
      position.mutable_at(r, d) = p.position[i](d);
      velocity.mutable_at(r, d) = p.velocity[i](d);
      spin.mutable_at(r, d) = p.angularVelocity[i](d);
      force.mutable_at(r, d) = p.force[i](d);
      torque.mutable_at(r, d) = p.torque[i](d);
      axes.mutable_at(r, d) = s.halfExtents()(d);
    }
    for (int d = 0; d < 4; ++d) orientation.mutable_at(r, d) = p.orientation[i].coeffs()(d);
    exponents.mutable_at(r, 0) = s.n1();
    exponents.mutable_at(r, 1) = s.n2();
  }
  py::dict out;
  out["id"] = id;
  out["position"] = position;
  out["orientation"] = orientation;
  out["velocity"] = velocity;
  out["angular_velocity"] = spin;
  out["force"] = force;
  out["torque"] = torque;
  out["semi_axes"] = axes;
  out["exponents"] = exponents;
  out["material"] = material;
  return out;
}

/// (N, k) rows of a caller's array, checked.
py::array_t<double, py::array::c_style | py::array::forcecast> checkedRows(const py::array& values, std::size_t n, int k,
                                                                           const char* what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!a || a.ndim() != 2 || static_cast<std::size_t>(a.shape(0)) != n || a.shape(1) != k) {
    throw py::value_error(std::string(what) + ": expected an array of shape (" + std::to_string(n) + ", " + std::to_string(k) + ")");
  }
  return a;
}

}  // namespace

void bindSimulation(py::module_& m) {
  py::register_exception<NumericalTrouble>(m, "NumericalTrouble", PyExc_RuntimeError);

  py::class_<ParticleViews>(m, "Particles",
                            "Zero-copy views of this process's particles in storage order, valid until the next step "
                            "(docs/python.md). position and velocity are writable; set orientations and angular "
                            "velocities with set_orientation / set_angular_velocity.")
      .def_property_readonly("id", [](ParticleViews& v) { return column(v.world.particles().id, v.world.particles().size(), v.owner, false); })
      .def_property_readonly("material", [](ParticleViews& v) { return column(v.world.particles().material, v.world.particles().size(), v.owner, false); },
                             "Index into Scene.materials.")
      .def_property_readonly("position", [](ParticleViews& v) { return rows(v.world.particles().position, v.world.particles().size(), 3, v.owner, true); },
                             "(N, 3) centres (m), writable.")
      .def_property_readonly("velocity", [](ParticleViews& v) { return rows(v.world.particles().velocity, v.world.particles().size(), 3, v.owner, true); },
                             "(N, 3) (m/s), writable.")
      .def_property_readonly("orientation", [](ParticleViews& v) { return rows(v.world.particles().orientation, v.world.particles().size(), 4, v.owner, false); },
                             "(N, 4) unit quaternions body -> world, scalar last (x, y, z, w), as scipy's Rotation.")
      .def_property_readonly("angular_velocity",
                             [](ParticleViews& v) { return rows(v.world.particles().angularVelocity, v.world.particles().size(), 3, v.owner, false); },
                             "(N, 3) world frame (rad/s).")
      .def_property_readonly("force", [](ParticleViews& v) { return rows(v.world.particles().force, v.world.particles().size(), 3, v.owner, false); },
                             "(N, 3) total force of the last step (N).")
      .def_property_readonly("torque", [](ParticleViews& v) { return rows(v.world.particles().torque, v.world.particles().size(), 3, v.owner, false); },
                             "(N, 3) world-frame torque about the centre (N m).")
      .def_property_readonly("semi_axes", [](ParticleViews& v) {
        py::array_t<double> out({static_cast<py::ssize_t>(v.world.particles().size()), py::ssize_t{3}});
        for (std::size_t i = 0; i < v.world.particles().size(); ++i) {
          for (int d = 0; d < 3; ++d) out.mutable_at(i, d) = semiAxes(v.world, i)(d);
        }
        return out;
      }, "(N, 3) semi-axes a, b, c (m), a copy.")
      .def_property_readonly("exponents", [](ParticleViews& v) {
        py::array_t<double> out({static_cast<py::ssize_t>(v.world.particles().size()), py::ssize_t{2}});
        for (std::size_t i = 0; i < v.world.particles().size(); ++i) {
          const Superquadric& s = v.world.shapes()[v.world.particles().shape[i]];
          out.mutable_at(i, 0) = s.n1();
          out.mutable_at(i, 1) = s.n2();
        }
        return out;
      }, "(N, 2) superquadric exponents n1, n2, a copy.")
      .def("__len__", [](ParticleViews& v) { return v.world.particles().size(); })
      .def("sorted_by_id", [](ParticleViews& v) { return sortedById(v.world); },
           "Every field as a copy, in id order (a dict of arrays).")
      .def("set_orientation", [](ParticleViews& v, const py::array& q) {
        ParticleStore& p = v.world.particles();
        const auto rowsOf = checkedRows(q, p.size(), 4, "set_orientation");
        for (std::size_t i = 0; i < p.size(); ++i) {
          const Vec3 spin = p.angularVelocity[i];
          p.orientation[i] = Quat(rowsOf.at(i, 3), rowsOf.at(i, 0), rowsOf.at(i, 1), rowsOf.at(i, 2)).normalized();
          p.setAngularVelocity(i, spin);  // the momentum follows the new orientation
        }
      }, py::arg("quaternions"), "Sets every orientation from (N, 4) quaternions (x, y, z, w), normalised; keeps the angular velocities.")
      .def("set_angular_velocity", [](ParticleViews& v, const py::array& w) {
        ParticleStore& p = v.world.particles();
        const auto rowsOf = checkedRows(w, p.size(), 3, "set_angular_velocity");
        for (std::size_t i = 0; i < p.size(); ++i) p.setAngularVelocity(i, Vec3(rowsOf.at(i, 0), rowsOf.at(i, 1), rowsOf.at(i, 2)));
      }, py::arg("angular_velocities"), "Sets every angular velocity (N, 3) (rad/s, world frame) and the momentum with it.");

  py::class_<ContactViews>(m, "Contacts",
                           "Zero-copy views of the contact store, one row per candidate pair of the neighbour list "
                           "(valid until the next step); `acting` marks the pairs in contact.")
      .def_property_readonly("id_a", [](ContactViews& v) { return column(v.world.interactions().store().idA, v.owner); })
      .def_property_readonly("id_b", [](ContactViews& v) { return column(v.world.interactions().store().idB, v.owner); },
                             "B's id; a wall's is wall_flag | its index.")
      .def_property_readonly("acting", [](ContactViews& v) { return column(v.world.interactions().store().acting, v.owner); })
      .def_property_readonly("point", [](ContactViews& v) { return rows(v.world.interactions().store().point, 3, v.owner); },
                             "(M, 3) contact points (m).")
      .def_property_readonly("normal", [](ContactViews& v) { return rows(v.world.interactions().store().normal, 3, v.owner); },
                             "(M, 3) unit normals from A to B.")
      .def_property_readonly("overlap", [](ContactViews& v) { return column(v.world.interactions().store().overlap, v.owner); },
                             "(M,) overlaps (m); negative: a gap.")
      .def_property_readonly("force", [](ContactViews& v) { return rows(v.world.interactions().store().force, 3, v.owner); },
                             "(M, 3) force on B (N); A receives its opposite.")
      .def_property_readonly("area", [](ContactViews& v) {
        const auto& loads = v.world.interactions().store().load;
        py::array_t<double> out(static_cast<py::ssize_t>(loads.size()));
        for (std::size_t k = 0; k < loads.size(); ++k) out.mutable_at(k) = loads[k].area;
        return out;
      }, "(M,) contact areas (m^2), a copy.")
      .def("__len__", [](ContactViews& v) { return v.world.interactions().store().size(); });
  m.attr("wall_flag") = py::int_(wallFlag);

  py::class_<PySimulation>(m, "Simulation", "A scene set up to run (docs/python.md).")
      .def(py::init([](const Scene& scene, int threads, std::optional<std::string> out, bool overwrite, std::optional<std::string> name,
                       std::optional<std::string> resume, std::optional<std::string> simd) {
             RunOptions options;
             options.threads = threads;
             options.overwrite = overwrite;
             if (out) options.out = *out;
             if (name) options.name = *name;
             if (resume) options.resume = *resume;
             if (simd) {
               options.simd = simdPathNamed(*simd);
               if (!options.simd || !runsHere(*options.simd)) throw py::value_error("simd: '" + *simd + "' is not a path this CPU runs");
             }
             if (threads < 0) throw py::value_error("threads: a count >= 0 (0: OpenMP's default)");
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
      .def_property_readonly("particles", [](py::object self) { return ParticleViews{self, self.cast<PySimulation&>().world()}; })
      .def_property_readonly("contacts", [](py::object self) { return ContactViews{self, self.cast<PySimulation&>().world()}; })
      .def_property_readonly("time", [](PySimulation& s) { return s.world().time(); }, "Simulated time (s).")
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
      .def_property_readonly("time_step", [](PySimulation& s) { return s.world().timeStep(); }, "(s)")
      .def_property_readonly("threads", [](PySimulation& s) { return s.world().threads(); })
      .def("measures", [](PySimulation& s) {
             const World& w = s.world();
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
             const World& w = s.world();
             if (wall >= w.walls().size() || w.walls()[wall].shape != WallShape::Plane) {
               throw py::value_error("plate: walls[" + std::to_string(wall) + "] is not a plane wall of the scene");
             }
             const PlateMeasures m = measurePlate(w, wall);
             py::dict out;
             out["gap"] = m.gap;
             out["pressure"] = m.pressure;
             out["porosity"] = m.porosity;
             return out;
           },
           py::arg("wall"),
           "A plate (a plane wall) pressing the bed onto the floor: its gap to the floor (m), its pressure (Pa) and "
           "the porosity between them.")
      .def("write_particles", [](PySimulation& s, const std::string& path) {
             writeParticleFile(path, s.world(), s.simulation().scene().materials);
           },
           py::arg("path"), "Writes the particle file of the current state (the CLI's *_final_particles.csv).");
}

}  // namespace sqdem::python
