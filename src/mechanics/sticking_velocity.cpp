#include "sqdem/mechanics/sticking_velocity.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/mechanics/nan_adhesive.hpp"

namespace sqdem {

StickingVelocities stickingVelocities(const StickingVelocityInput& in) {
  if (!(in.density > 0) || !(in.youngs > 0) || !(in.wallYoungs > 0) || !(in.poisson > -1 && in.poisson < 0.5) ||
      !(in.wallPoisson > -1 && in.wallPoisson < 0.5)) {
    throw std::invalid_argument("sticking velocity: need density > 0, Young's moduli > 0, Poisson ratios in (-1, 0.5)");
  }
  NanParameters p;
  p.effectiveModulus = effectiveModulus(in.youngs, in.poisson, in.wallYoungs, in.wallPoisson);
  p.effectiveRadius = in.radius;
  p.workOfAdhesion = in.workOfAdhesion;
  p.yieldPressure = in.yieldPressure;
  const NanAdhesivePlastic law(p);
  const double m = 4.0 / 3.0 * std::numbers::pi * std::pow(in.radius, 3) * in.density;
  const double kEl = law.kEl(), kP = law.kP(), fY = law.yieldForce(), f0 = law.snapInForce();

  StickingVelocities v;
  v.Vs = std::sqrt(2.0 * law.separationWork() / m);
  v.Vy0 = std::sqrt(2.0 * law.yieldWork() / m);
  // Eq. 75 keeps its sign in Eq. 79: where f_y < f_0 the contact yields at jump-in and
  // m V_y^2 / 2 = W_2 - W_1 < 0 is energy the impact need not supply (000 Fig. 9 shaded zone).
  const double VySquared = (fY * fY - f0 * f0) / (m * kEl);
  v.Vy = std::sqrt(std::max(0.0, VySquared));
  if (v.Vy >= v.Vs) {
    v.Vys = v.Vs;
    return v;
  }
  double fMax = fY;
  for (v.iterations = 1; v.iterations <= 100000; ++v.iterations) {
    const NanUnloading u = law.unloadingFrom(law.yieldOverlap() + (fMax - fY) / kP);  // Eq. 10
    const double next = u.fCp * std::sqrt(1.0 + 56.0 / 81.0 * u.kE / u.kC);           // Eq. 78
    const bool converged = std::abs(next - fMax) <= 1e-13 * next;
    fMax = next;
    if (converged) {
      v.Vys = std::sqrt(VySquared + (fMax * fMax - fY * fY) / (m * kP));              // Eq. 79
      return v;
    }
  }
  throw std::runtime_error("sticking velocity: the fixed point of Eqs. 78-79 did not converge");
}

}  // namespace sqdem
