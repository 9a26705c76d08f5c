#include "sqdem/mechanics/damping.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sqdem {

double restitutionDampingRatio(double restitution) {
  if (!(restitution > 0.0 && restitution <= 1.0)) {
    throw std::invalid_argument("coefficient of restitution must be in (0, 1], got " +
                                std::to_string(restitution));
  }
  const double l = std::log(restitution);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

double linearDampingForce(double zeta, double mass, double stiffness, double overlapRate) {
  return 2.0 * zeta * std::sqrt(mass * stiffness) * overlapRate;
}

double hertzDampingForce(double zeta, double mass, double effectiveModulus, double radius,
                         double overlap, double overlapRate) {
  if (overlap <= 0.0) return 0.0;
  const double Sn = 2.0 * effectiveModulus * std::sqrt(radius * overlap);  // Eq. 13
  return std::sqrt(5.0 / 6.0) * linearDampingForce(zeta, mass, Sn, overlapRate);
}

double viscoelasticConstant(double eta1, double eta2, double youngs, double poisson) {
  const double a = 3.0 * eta2 - eta1;
  return a * a / (3.0 * (3.0 * eta2 + 2.0 * eta1)) * (1.0 - poisson * poisson) *
         (1.0 - 2.0 * poisson) / (youngs * poisson * poisson);
}

double viscoelasticDampingForce(double A, double effectiveModulus, double Rc, double gamma,
                                double overlap, double overlapRate) {
  if (overlap <= 0.0) return 0.0;
  return 2.0 * A * effectiveModulus * std::sqrt(Rc * overlap) * overlapRate * gamma;
}

double adhesiveViscoelasticDampingForce(double B, double workOfAdhesion, double effectiveModulus,
                                        double Rc, double overlap, double overlapRate) {
  if (overlap <= 0.0) return 0.0;
  const double D = 3.0 / (4.0 * effectiveModulus);
  return 0.75 * B * std::sqrt(std::numbers::pi * workOfAdhesion / D) * std::pow(Rc, 0.75) *
         std::pow(overlap, -0.25) * overlapRate;
}

}  // namespace sqdem
