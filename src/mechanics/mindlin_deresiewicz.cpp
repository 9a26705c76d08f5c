#include "sqdem/mechanics/mindlin_deresiewicz.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sqdem/mechanics/elliptic_integrals.hpp"

namespace sqdem {

using std::numbers::pi;

MindlinDeresiewicz::MindlinDeresiewicz(double shearModulus, double semiMajorAxis, double e2, double poisson,
                                       double theta, double friction, double normalForce)
    : G_(shearModulus), a_(semiMajorAxis), limit_(friction * normalForce) {
  if (!(G_ > 0) || !(a_ > 0) || !(e2 >= 0 && e2 < 1) || !(friction > 0) || !(normalForce > 0)) {
    throw std::invalid_argument("Mindlin-Deresiewicz: need G* > 0, a_c > 0, 0 <= e^2 < 1, mu > 0, F_n > 0");
  }
  const EllipticIntegrals I = ellipticIntegrals(e2);
  const MindlinPhi axes = mindlinPhi(I.K, I.D, poisson);
  phi_ = std::hypot(axes.major * std::cos(theta), axes.minor * std::sin(theta));
}

MindlinPhi mindlinPhi(double K, double D, double poisson) {
  const double scale = 4.0 / (pi * (2.0 - poisson));
  return {scale * ((1.0 - poisson) * K + poisson * D), scale * (K - poisson * D)};  // 1/chi of Eq. 57
}

double MindlinDeresiewicz::force(double displacement, MindlinDeresiewiczHistory& h) const {
  const double dL = slipDisplacement();
  const double step = displacement - h.displacement;
  const int direction = step > 0 ? 1 : step < 0 ? -1 : h.direction;
  if (h.direction != 0 && direction != h.direction) {  // reversal: a new turning point
    h.turningDisplacement = h.displacement;
    h.turningForce = h.force;
    h.virgin = false;
  }
  double f;
  if (h.virgin) {
    const double x = std::min(std::abs(displacement) / dL, 1.0);
    f = std::copysign(limit_ * (1.0 - std::pow(1.0 - x, 1.5)), displacement);
  } else {
    const double x = std::clamp(direction * (displacement - h.turningDisplacement) / (2.0 * dL), 0.0, 1.0);
    f = std::clamp(h.turningForce + direction * 2.0 * limit_ * (1.0 - std::pow(1.0 - x, 1.5)), -limit_, limit_);
  }
  h.direction = direction;
  h.displacement = displacement;
  h.force = f;
  return f;
}

double MindlinDeresiewicz::dissipationPerCycle(double amplitude) const {
  const double r = amplitude / limit_;
  return 9.0 * limit_ * limit_ * phi_ / (10.0 * G_ * a_) *
         (1.0 - std::pow(1.0 - r, 5.0 / 3.0) - 5.0 * r / 6.0 * (1.0 + std::pow(1.0 - r, 2.0 / 3.0)));
}

double contactSemiMajorAxis(double area, double e2) {
  return std::sqrt(area / (pi * std::sqrt(1.0 - e2)));
}

}  // namespace sqdem
