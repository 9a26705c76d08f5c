// sqdem.contact (the single-contact driver, probe/contact_drive.hpp) and sqdem.geometry (the
// contact geometry probe, probe/pair_geometry.hpp): their inputs are the documents `sqdem
// contact` and `sqdem geometry` read, given as Python values (json_value.hpp): the library
// checks them.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <string>

#include "bindings.hpp"
#include "json_value.hpp"
#include "sqdem/probe/contact_drive.hpp"
#include "sqdem/probe/pair_geometry.hpp"

namespace py = pybind11;

namespace sqdem::python {
namespace {

py::object fromJson(const probe::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

py::array_t<double> array(const std::vector<double>& values) { return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data()); }

/// A particle of the geometry probe's document from a shape and a pose.
probe::json particle(const py::handle& semiAxes, const py::handle& exponents, const py::handle& centre,
                     const py::handle& quaternion, const std::string& where) {
  const probe::json axes = toJson(semiAxes, where + ".semi_axes"), n = toJson(exponents, where + ".exponents"),
                    q = toJson(quaternion, where + ".quaternion");
  if (!axes.is_array() || axes.size() != 3) throw py::value_error(where + ": semi_axes are three numbers (a, b, c)");
  if (!n.is_array() || n.size() != 2) throw py::value_error(where + ": exponents are two numbers (n1, n2)");
  if (!q.is_array() || q.size() != 4) throw py::value_error(where + ": a quaternion is four numbers (x, y, z, w)");
  return {{"a", axes[0]}, {"b", axes[1]}, {"c", axes[2]}, {"n1", n[0]}, {"n2", n[1]},
          {"centre", toJson(centre, where + ".centre")}, {"quaternion", {q[3], q[0], q[1], q[2]}}};
}

}  // namespace

void bindProbes(py::module_& m) {
  py::register_exception<probe::InputError>(m, "InputError", PyExc_ValueError);

  m.def(
      "contact",
      [](const py::dict& description) {
        const probe::ContactDrive drive = probe::driveContact(toJson(description, "description"), "contact");
        py::list curves;
        for (const probe::DrivenCurve& c : drive.curves) {
          py::dict curve;
          curve["label"] = c.label;
          curve["overlap"] = array(c.overlap);
          curve["normal_force"] = array(c.normalForce);
          std::vector<double> area;
          for (const auto& a : c.area) area.push_back(a ? *a : std::numeric_limits<double>::quiet_NaN());
          curve["contact_area"] = array(area);
          curve["regime"] = c.regime;
          if (!c.tangentialForce.empty()) curve["tangential_force"] = array(c.tangentialForce);
          curve["radii"] = py::make_tuple(c.radii.Ri, c.radii.Rj);
          curve["detector_failures"] = c.detectorFailures;
          curve["constants"] = fromJson(c.constants);
          curves.append(curve);
        }
        py::dict out;
        out["name"] = drive.name;
        out["displacement"] = array(drive.displacement);
        if (!drive.tangentialDisplacement.empty()) out["tangential_displacement"] = array(drive.tangentialDisplacement);
        out["curves"] = curves;
        return out;
      },
      py::arg("description"),
      "The single-contact driver: the description `sqdem contact` reads (README.md) as a dictionary; returns the "
      "path and, per curve, overlap (m), normal force (N), contact area (m^2, NaN where the law has none), regime, "
      "tangential force (N) as arrays.");

  m.def(
      "geometry",
      [](const py::handle& semiAxesA, const py::handle& exponentsA, const py::handle& centreA, const py::handle& quaternionA,
         const py::handle& semiAxesB, const py::handle& exponentsB, const py::handle& centreB, const py::handle& quaternionB,
         const py::handle& cutoff, const py::handle& effectiveModulus) {
        probe::json input{{"particles", {particle(semiAxesA, exponentsA, centreA, quaternionA, "particles[0]"),
                                         particle(semiAxesB, exponentsB, centreB, quaternionB, "particles[1]")}},
                          {"cutoff", toJson(cutoff, "cutoff")}};
        if (!effectiveModulus.is_none()) input["E_star"] = toJson(effectiveModulus, "E_star");
        return fromJson(probe::pairGeometry(input));
      },
      py::arg("semi_axes_a"), py::arg("exponents_a"), py::arg("centre_a"), py::arg("quaternion_a"), py::arg("semi_axes_b"),
      py::arg("exponents_b"), py::arg("centre_b"), py::arg("quaternion_b"), py::arg("cutoff") = 0.0,
      py::arg("effective_modulus") = py::none(),
      "The contact geometry probe of `sqdem geometry` on one pair: shapes by semi-axes (m) and exponents (n1, n2), "
      "poses by centre (m) and quaternion (x, y, z, w); cutoff (m): report gaps up to it; effective_modulus E* (Pa): "
      "adds the elliptic Hertz force. Returns its JSON object as a dict (README.md, `sqdem geometry`): status, "
      "converged, overlap; where it converged the normal, both points, both surfaces' principal curvatures (1/m) and "
      "directions, the relative radii and Hertz factors.");
}

}  // namespace sqdem::python
