#pragma once
// normal: elliptic_hertz / volume_sphere_hertz (normal_law.hpp component): 004 Eqs. 1-2,
//   F = 4/3 E* Rc^1/2 gamma delta^3/2, A = pi Rc beta delta, S_n = dF/d(delta) = 2 E* gamma (Rc delta)^1/2,
// on the detector's curvatures (elliptic_hertz) or on the volume-equivalent spheres
// (volume_sphere_hertz: gamma = sqrt 2, beta = 2, Rc = R*/2). No parameters of its own, no history.

#include "sqdem/mechanics/normal_law.hpp"

namespace sqdem {

struct HertzLaw {
  struct History {};

  NormalResponse force(const NormalContact& c, double overlap, History&) const {
    if (!(overlap > 0.0)) return {.acting = false};
    const double gamma = c.factors.gamma, sqrtRc = std::sqrt(c.radii.Rc), sqrtDelta = std::sqrt(overlap);
    return {.force = 4.0 / 3.0 * c.effectiveModulus * sqrtRc * gamma * overlap * sqrtDelta,
            .stiffness = 2.0 * c.effectiveModulus * gamma * sqrtRc * sqrtDelta,
            .area = std::numbers::pi * c.radii.Rc * c.factors.beta * overlap};
  }
  /// The integral of F over the overlap: 2/5 F delta (J).
  bool storesEnergy() const { return true; }
  double storedEnergy(const NormalContact&, double overlap, const History&, double force) const { return 0.4 * force * overlap; }
  double range(const History&) const { return 0.0; }
  double reach(double, double) const { return 0.0; }
};

}  // namespace sqdem
