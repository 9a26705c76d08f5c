// sqdem.contact (the single-contact driver, probe/contact_drive.hpp) and sqdem.geometry (the
// detector on one posed pair): their inputs are the documents `sqdem contact` and `sqdem
// geometry` read, given as dictionaries (through their JSON text: the library checks them).

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>

#include "bindings.hpp"
#include "sqdem/contact/detector.hpp"
#include "sqdem/probe/contact_drive.hpp"

namespace py = pybind11;

namespace sqdem::python {
namespace {

probe::json toJson(const py::handle& value) {
  return probe::json::parse(py::module_::import("json").attr("dumps")(value).cast<std::string>());
}

py::object fromJson(const probe::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

py::array_t<double> array(const std::vector<double>& values) { return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data()); }

py::array_t<double> vec3(const Vec3& v) { return py::array_t<double>(3, v.data()); }

/// A superquadric from its semi-axes and exponents.
Superquadric shapeOf(const std::array<double, 3>& semiAxes, const std::array<double, 2>& exponents) {
  return Superquadric(semiAxes[0], semiAxes[1], semiAxes[2], exponents[0], exponents[1]);
}

}  // namespace

void bindProbes(py::module_& m) {
  py::register_exception<probe::InputError>(m, "InputError", PyExc_ValueError);

  m.def(
      "contact",
      [](const py::dict& description) {
        const probe::ContactDrive drive = probe::driveContact(toJson(description), "contact");
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
      [](std::array<double, 3> semiAxesA, std::array<double, 2> exponentsA, std::array<double, 3> centreA,
         std::array<double, 4> quaternionA, std::array<double, 3> semiAxesB, std::array<double, 2> exponentsB,
         std::array<double, 3> centreB, std::array<double, 4> quaternionB, double cutoff) {
        const Superquadric A = shapeOf(semiAxesA, exponentsA), B = shapeOf(semiAxesB, exponentsB);
        const auto pose = [](const std::array<double, 3>& c, const std::array<double, 4>& q) {
          return Pose{Vec3(c[0], c[1], c[2]), Quat(q[3], q[0], q[1], q[2]).normalized()};
        };
        DetectorSettings settings;
        settings.cutoff = cutoff;
        const ContactGeometry g = detectContact(A, pose(centreA, quaternionA), B, pose(centreB, quaternionB), settings);
        py::dict out;
        out["status"] = std::string(describe(g.status));
        out["converged"] = g.converged();
        out["overlap"] = g.overlap;
        out["normal"] = vec3(g.normal);
        out["point_a"] = vec3(g.pointA);
        out["point_b"] = vec3(g.pointB);
        out["curvatures_a"] = py::make_tuple(g.curvatureA.k1, g.curvatureA.k2);
        out["curvatures_b"] = py::make_tuple(g.curvatureB.k1, g.curvatureB.k2);
        out["directions_a"] = py::make_tuple(vec3(g.curvatureA.d1), vec3(g.curvatureA.d2));
        out["directions_b"] = py::make_tuple(vec3(g.curvatureB.d1), vec3(g.curvatureB.d2));
        out["iterations"] = g.iterations;
        return out;
      },
      py::arg("semi_axes_a"), py::arg("exponents_a"), py::arg("centre_a"), py::arg("quaternion_a"), py::arg("semi_axes_b"),
      py::arg("exponents_b"), py::arg("centre_b"), py::arg("quaternion_b"), py::arg("cutoff") = 0.0,
      "The common-normal detector on one pair: shapes by semi-axes (m) and exponents (n1, n2), poses by centre (m) "
      "and quaternion (x, y, z, w); returns status, overlap (m), normal, both contact points, both surfaces' "
      "principal curvatures (1/m) and directions. cutoff (m): report gaps up to it.");
}

}  // namespace sqdem::python
