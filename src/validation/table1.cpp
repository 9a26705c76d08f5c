#include "sqdem/validation/table1.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sqdem/contact/detector.hpp"

namespace sqdem {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

/// 004 Eqs. 17-18: 1/R = sqrt(Gaussian curvature), capped.
double simplifiedRadius(const PrincipalCurvatures& k, double cap) {
  const double gaussian = k.gaussian();
  return gaussian > 1.0 / (cap * cap) ? 1.0 / std::sqrt(gaussian) : cap;
}

}  // namespace

Superquadric table1Shape() { return Superquadric(1.0, 1.0, 2.0, 6.0, 6.0); }

Pose table1PoseOfSecond(const Table1Case& c, double distance) {
  const double thetaL = radians(c.thetaL);
  Pose pose;
  pose.position = distance * Vec3(std::sin(thetaL), 0.0, std::cos(thetaL));
  pose.orientation = Quat(Eigen::AngleAxisd(radians(c.phiF), Vec3::UnitZ()) *
                          Eigen::AngleAxisd(radians(c.thetaS), Vec3::UnitX()));
  return pose;
}

Table1Result runTable1Case(const Table1Case& c, double overlapFraction) {
  const Superquadric shape = table1Shape();
  const double Rvol = shape.volumeEquivalentRadius();
  const Pose first;
  DetectorSettings settings;
  settings.cutoff = 4.0 * shape.boundingRadius();  // report gaps while sliding in

  // Slide particle II along u: Newton on overlap(t) = 0 (d overlap / dt = -n.u), warm-started.
  const Vec3 u = table1PoseOfSecond(c, 1.0).position;
  double distance = 2.0 * shape.boundingRadius();
  ContactGeometry contact = detectContact(shape, first, shape, table1PoseOfSecond(c, distance), settings);
  for (int k = 0; k < 100 && contact.converged() && std::abs(contact.overlap) > 1e-14 * Rvol; ++k) {
    distance += contact.overlap / contact.normal.dot(u);
    contact = detectContact(shape, first, shape, table1PoseOfSecond(c, distance), settings, contact);
  }
  if (contact.converged()) {
    distance -= overlapFraction * Rvol / contact.normal.dot(u);
    contact = detectContact(shape, first, shape, table1PoseOfSecond(c, distance), settings, contact);
  }
  if (!contact.converged()) {
    throw std::runtime_error(std::string("Table 1 case ") + std::to_string(c.id) +
                             ": contact detection failed: " + describe(contact.status));
  }

  Table1Result r;
  r.reference = c;
  r.second = table1PoseOfSecond(c, distance);
  r.contact = contact;
  r.volumeEquivalentRadius = Rvol;
  const double cap = table1CapFactor * Rvol;
  r.radii = relativeRadii(contact.curvatureA, contact.curvatureB, cap);
  r.explicitFactors = hertzFactors(r.radii.ratio(), EccentricityMethod::Explicit);
  r.exactFactors = hertzFactors(r.radii.ratio(), EccentricityMethod::Exact);
  r.normalisedForce = normalisedHertzForce(r.explicitFactors.gamma, r.radii.Rc, Rvol);
  r.normalisedForceExact = normalisedHertzForce(r.exactFactors.gamma, r.radii.Rc, Rvol);
  const double RI = simplifiedRadius(contact.curvatureA, cap);
  const double RII = simplifiedRadius(contact.curvatureB, cap);
  r.simplifiedForce = normalisedHertzForce(1.0, RI * RII / (RI + RII), Rvol);
  return r;
}

double normalisedHertzForce(double gamma, double Rc, double Rvol) {
  return gamma * std::sqrt(Rc / Rvol);
}

}  // namespace sqdem
