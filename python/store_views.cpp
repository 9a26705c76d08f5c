// sqdem.Particles and sqdem.Contacts: zero-copy, read-only NumPy views of the particle and
// contact stores (views.hpp), valid until the next step; copies where a field is not stored as
// such (semi-axes, exponents, areas, ellipses, sorted_by_id); the particles' state set through
// the library's checked setters (scene/particle_edits.hpp), not by writing into a view: a write
// must also reset what the world derived from the old state, and a view kept past a step points
// at memory a step may have freed (docs/python.md).

#include <pybind11/numpy.h>

#include <algorithm>
#include <numeric>
#include <string>

#include "bindings.hpp"
#include "sqdem/scene/particle_edits.hpp"
#include "store_views.hpp"
#include "views.hpp"

namespace py = pybind11;

namespace sqdem::python {
namespace {

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The rows of a caller's array as one span (the library checks their count and values).
std::span<const double> values(const Rows& rows) { return {rows.data(), static_cast<std::size_t>(rows.size())}; }

/// (n, k) doubles, a new array.
py::array_t<double> table(std::size_t n, int k) { return py::array_t<double>({static_cast<py::ssize_t>(n), py::ssize_t{k}}); }

/// The particles' state as copies, in id order.
py::dict sortedById(const World& world) {
  const ParticleStore& p = world.particles();
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  const auto n = static_cast<py::ssize_t>(p.size());
  py::array_t<std::uint32_t> id(n), material(n);
  py::array_t<double> position = table(p.size(), 3), orientation = table(p.size(), 4), velocity = table(p.size(), 3),
                      spin = table(p.size(), 3), force = table(p.size(), 3), torque = table(p.size(), 3),
                      axes = table(p.size(), 3), exponents = table(p.size(), 2);
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

/// A setter of the library (particle_edits.hpp) taking an (N, K) array.
template <void (*Set)(Simulation&, std::span<const double>), int K>
void set(ParticleViews& v, const Rows& rows) {
  v.state.requireIdle("set");
  if (rows.ndim() != 2 || rows.shape(1) != K) {
    throw py::value_error("expected an array of shape (N, " + std::to_string(K) + "), one row per particle");
  }
  Set(v.simulation, values(rows));
}

}  // namespace

void bindStoreViews(py::module_& m) {
  const auto particles = [](ParticleViews& v) -> ParticleStore& {
    v.state.requireIdle("particles");
    return v.simulation.world().particles();
  };
  py::class_<ParticleViews>(m, "Particles",
                            "Read-only zero-copy views of this process's particles in storage order, valid until the "
                            "next step (docs/python.md); state is set with set_position, set_velocity, "
                            "set_orientation and set_angular_velocity.")
      .def_property_readonly("id", [=](ParticleViews& v) { return column(particles(v).id, particles(v).size(), v.owner); })
      .def_property_readonly("material", [=](ParticleViews& v) { return column(particles(v).material, particles(v).size(), v.owner); },
                             "Index into Scene.materials.")
      .def_property_readonly("position", [=](ParticleViews& v) { return rows(particles(v).position, particles(v).size(), 3, v.owner); },
                             "(N, 3) centres (m).")
      .def_property_readonly("velocity", [=](ParticleViews& v) { return rows(particles(v).velocity, particles(v).size(), 3, v.owner); },
                             "(N, 3) (m/s).")
      .def_property_readonly("orientation", [=](ParticleViews& v) { return rows(particles(v).orientation, particles(v).size(), 4, v.owner); },
                             "(N, 4) unit quaternions body -> world, scalar last (x, y, z, w), as scipy's Rotation.")
      .def_property_readonly("angular_velocity",
                             [=](ParticleViews& v) { return rows(particles(v).angularVelocity, particles(v).size(), 3, v.owner); },
                             "(N, 3) world frame (rad/s).")
      .def_property_readonly("force", [=](ParticleViews& v) { return rows(particles(v).force, particles(v).size(), 3, v.owner); },
                             "(N, 3) total force of the last step (N).")
      .def_property_readonly("torque", [=](ParticleViews& v) { return rows(particles(v).torque, particles(v).size(), 3, v.owner); },
                             "(N, 3) world-frame torque about the centre (N m).")
      .def_property_readonly("semi_axes", [=](ParticleViews& v) {
        const World& world = v.simulation.world();
        py::array_t<double> out = table(particles(v).size(), 3);
        for (std::size_t i = 0; i < particles(v).size(); ++i) {
          for (int d = 0; d < 3; ++d) out.mutable_at(i, d) = world.shapes()[particles(v).shape[i]].halfExtents()(d);
        }
        return out;
      }, "(N, 3) semi-axes a, b, c (m), a copy.")
      .def_property_readonly("exponents", [=](ParticleViews& v) {
        const World& world = v.simulation.world();
        py::array_t<double> out = table(particles(v).size(), 2);
        for (std::size_t i = 0; i < particles(v).size(); ++i) {
          const Superquadric& s = world.shapes()[particles(v).shape[i]];
          out.mutable_at(i, 0) = s.n1();
          out.mutable_at(i, 1) = s.n2();
        }
        return out;
      }, "(N, 2) superquadric exponents n1, n2, a copy.")
      .def("__len__", [=](ParticleViews& v) { return particles(v).size(); })
      .def("sorted_by_id", [=](ParticleViews& v) {
        particles(v);  // the state check
        return sortedById(v.simulation.world());
      },
           "Every field as a copy, in id order (a dict of arrays).")
      .def("set_position", &set<setPositions, 3>, py::arg("positions"),
           "Sets every centre from (N, 3) values (m), in storage order.")
      .def("set_velocity", &set<setVelocities, 3>, py::arg("velocities"), "Sets every velocity from (N, 3) values (m/s).")
      .def("set_orientation", &set<setOrientations, 4>, py::arg("quaternions"),
           "Sets every orientation from (N, 4) quaternions (x, y, z, w), normalised; keeps the angular velocities.")
      .def("set_angular_velocity", &set<setAngularVelocities, 3>, py::arg("angular_velocities"),
           "Sets every angular velocity from (N, 3) values (rad/s, world frame), and the momentum with it.");

  const auto store = [](ContactViews& v) -> const ContactStore& {
    v.state.requireIdle("contacts");
    return v.world.interactions().store();
  };
  py::class_<ContactViews>(m, "Contacts",
                           "Read-only zero-copy views of the contact store, one row per candidate pair of the "
                           "neighbour list (valid until the next step); `acting` marks the pairs in contact.")
      .def_property_readonly("id_a", [=](ContactViews& v) { return column(store(v).idA, v.owner); })
      .def_property_readonly("id_b", [=](ContactViews& v) { return column(store(v).idB, v.owner); },
                             "B's id; a wall's is wall_flag | its index.")
      .def_property_readonly("acting", [=](ContactViews& v) { return column(store(v).acting, v.owner); })
      .def_property_readonly("point", [=](ContactViews& v) { return rows(store(v).point, 3, v.owner); }, "(M, 3) contact points (m).")
      .def_property_readonly("normal", [=](ContactViews& v) { return rows(store(v).normal, 3, v.owner); }, "(M, 3) unit normals from A to B.")
      .def_property_readonly("overlap", [=](ContactViews& v) { return column(store(v).overlap, v.owner); },
                             "(M,) overlaps (m); negative: a gap.")
      .def_property_readonly("force", [=](ContactViews& v) { return rows(store(v).force, 3, v.owner); },
                             "(M, 3) force on B (N); A receives its opposite.")
      .def_property_readonly("area", [=](ContactViews& v) {
        const auto& loads = store(v).load;
        py::array_t<double> out(static_cast<py::ssize_t>(loads.size()));
        for (std::size_t k = 0; k < loads.size(); ++k) out.mutable_at(k) = loads[k].area;
        return out;
      }, "(M,) contact areas (m^2), a copy.")
      .def("ellipses", [=](ContactViews& v) {
        store(v);  // the state check
        const std::vector<ContactEllipse> ellipses = v.world.contactEllipses();
        py::array_t<double> semiAxes = table(ellipses.size(), 2), axis = table(ellipses.size(), 3);
        for (std::size_t k = 0; k < ellipses.size(); ++k) {
          semiAxes.mutable_at(k, 0) = ellipses[k].major;
          semiAxes.mutable_at(k, 1) = ellipses[k].minor;
          for (int d = 0; d < 3; ++d) axis.mutable_at(k, d) = ellipses[k].majorAxis(d);
        }
        return py::make_tuple(semiAxes, axis);
      }, "The contact ellipses, computed now (copies): (M, 2) semi-axes a >= b (m; zero where not acting) with pi a b "
         "the law's area and b/a the Hertz ellipse's of the pair's relative radii, and (M, 3) unit major axes (zero "
         "for a circle).")
      .def("__len__", [=](ContactViews& v) { return store(v).size(); });
  m.attr("wall_flag") = py::int_(wallFlag);
}

}  // namespace sqdem::python
