#include "sqdem/mechanics/haervig.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sqdem/mechanics/damping.hpp"
#include "sqdem/mechanics/tangent_plane.hpp"

namespace sqdem {

using std::numbers::pi;

HaervigJkr::HaervigJkr(double effectiveModulus, double surfaceEnergy, double effectiveRadius)
    : jkr_{effectiveModulus, 2.0 * surfaceEnergy, effectiveRadius} {
  if (!(effectiveModulus > 0) || !(surfaceEnergy > 0) || !(effectiveRadius > 0)) {
    throw std::invalid_argument("Haervig JKR: E*, surface energy and radius must be positive");
  }
}

double HaervigJkr::contactRadius(double overlap) const { return jkr_.contactRadius(std::max(overlap, 0.0)); }

double HaervigJkr::normalForce(double overlap) const {
  return overlap < 0.0 ? 0.0 : jkr_.forceAt(contactRadius(overlap));
}

double HaervigJkr::equilibriumContactRadius() const {
  return std::cbrt(9.0 * pi * surfaceEnergy() * jkr_.radius * jkr_.radius / jkr_.effectiveModulus);
}

double HaervigJkr::criticalForce() const { return 3.0 * pi * surfaceEnergy() * jkr_.radius; }

double reducedStiffnessSurfaceEnergy(double surfaceEnergy, double youngs, double reducedYoungs) {
  return surfaceEnergy * std::pow(reducedYoungs / youngs, 0.4);
}

Vec3 HaervigTangential::force(Vec3& spring, const Vec3& increment, const Vec3& velocity, double overlap,
                              double normalForce, double criticalForce) const {
  if (overlap <= 0.0) {
    spring.setZero();
    return Vec3::Zero();
  }
  const double St = 8.0 * shearModulus * std::sqrt(radius * overlap);
  spring += increment;
  const Vec3 damping = -std::sqrt(5.0 / 6.0) * linearDampingForce(std::abs(beta), mass, St, 1.0) * velocity;  // Eq. 16
  Vec3 f = -St * spring + damping;
  const double cap = friction * std::abs(normalForce + 2.0 * criticalForce);
  const double magnitude = f.norm();
  if (magnitude > cap) {
    f *= cap / magnitude;
    spring = -(f - damping) / St;
  }
  return f;
}

double HaervigRolling::torque(double& xi, double radiusRatio) const {
  xi = std::clamp(xi, -criticalDistance, criticalDistance);
  return 4.0 * criticalForce * std::pow(radiusRatio, 1.5) * xi;
}

HaervigJkrLaw HaervigJkrLaw::read(const LawInput& in, const PairElasticity& pair) {
  const double gamma = in.positive("surface_energy", "J/m^2, gamma; W = 2 gamma");
  return {pair.reducedSurfaceEnergy(gamma), gamma};
}

HaervigJkr HaervigJkrLaw::at(const NormalContact& c) const {
  return HaervigJkr(c.effectiveModulus, surfaceEnergy, c.factors.gamma * c.factors.gamma * c.radii.Rc);
}

NormalResponse HaervigJkrLaw::force(const NormalContact& c, double overlap, History&) const {
  if (!(overlap > 0.0)) return {.acting = false};
  const HaervigJkr jkr = at(c);
  const double sqrtRc = std::sqrt(c.radii.Rc);
  return {.force = jkr.normalForce(overlap),
          .stiffness = 2.0 * c.effectiveModulus * c.factors.gamma * sqrtRc * std::sqrt(overlap),
          .area = std::numbers::pi * c.radii.Rc * c.factors.beta * overlap,
          .pullOff = jkr.criticalForce(),
          .regime = "attached"};
}

Vec3 HaervigRollingResistance::moment(const HaervigJkrLaw& law, const NormalContact& c, double overlap, const Vec3& n,
                                      const Vec3& vt, double radiusA, double radiusB, const Vec3& omegaA,
                                      const Vec3& omegaB, Vec3& xi, double dt) const {
  const HaervigJkr modified = law.at(c);
  const double R = c.factors.gamma * c.factors.gamma * c.radii.Rc;  // the Hertz-equivalent sphere
  const HaervigJkr real(realModulus, law.realSurfaceEnergy, R);
  const HaervigRolling rolling{real.criticalForce(), real.equilibriumContactRadius() / 12.0 * hysteresis};
  // Eq. 20; the radius ratio term tends to -1/2 for a wall (r_B -> infinity).
  const double ratio = radiusB > 0.0 ? (radiusA - radiusB) / (radiusA + radiusB) : -1.0;
  const Vec3 slidingAB = -vt;  // A relative to B at the contact
  const Vec3 vL = R * (omegaA - omegaB).cross(n) + 0.5 * ratio * slidingAB;
  keepInTangentPlane(xi, n);
  xi += vL * dt;
  double length = xi.norm();
  const double magnitude = rolling.torque(length, modified.contactRadius(overlap) / modified.equilibriumContactRadius());
  if (length < xi.norm()) xi *= length / xi.norm();  // Eq. 22: truncated at xi_crit
  return xi.norm() > 0.0 ? Vec3(magnitude * n.cross(xi.normalized())) : Vec3::Zero();
}

}  // namespace sqdem
