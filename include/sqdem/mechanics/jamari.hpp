#pragma once
// Jamari & Schipper's elastic-plastic and fully plastic elliptic contact, loading curve
// (004 Eqs. 41-46), an alternative to Becker-Kamlah without an unloading model in the seed.
//
//   first yield        delta_1 = pi^2/4 R_c (beta/gamma)^2 (K_v H/E*)^2             (Eq. 41)
//   full plasticity    delta_2 = c_A lambda/(1 + lambda^2) (1 - e^2)^-1/2 E(e^2)/K(e^2) delta_1,
//                      lambda = sqrt(Ri/Rj)                                          (Eq. 44)
//   elastic            F = 4/3 E* R_c^1/2 delta^3/2 gamma                             (Eq. 1)
//   elastic-plastic    F = A_EP [c_h H - H (c_h - 2/3 K_v) (ln delta_2 - ln delta)/(ln delta_2 - ln delta_1)]
//                      A_EP = pi R_c delta beta + (2 pi sqrt(Ri Rj) delta - pi R_c delta beta)
//                             (3 x^2 - 2 x^3), x = (delta - delta_1)/(delta_2 - delta_1)  (Eqs. 45-46)
//   fully plastic      F = 2 pi delta sqrt(Ri Rj) c_h H                               (Eq. 43)
// H hardness (Pa), K_v maximum-pressure factor at first yield (p_max = K_v H), c_h mean-pressure
// factor in full plasticity, c_A the delta_2/delta_1 constant; E* (Pa), radii (m). The force is
// continuous at delta_1 (mean Hertz pressure 2/3 K_v H there) and at delta_2 (tested). Loading
// only: the seed gives no unloading branch, so it is not offered for cyclic use.

#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

struct JamariParameters {
  double effectiveModulus = 0.0;  ///< E* (Pa)
  double hardness = 0.0;          ///< H (Pa)
  double maxPressureFactor = 0.0; ///< K_v
  double meanPressureFactor = 1.0;///< c_h
  double plasticOverlapFactor = 0.0; ///< c_A (> 2 (1 + lambda^2)/lambda so delta_2 > delta_1)
};

class JamariElasticPlastic {
 public:
  JamariElasticPlastic(const RelativeRadii& radii, const HertzFactors& factors, const JamariParameters& p);
  double loadingForce(double overlap) const;  ///< (N)
  double yieldOverlap() const { return delta1_; }          ///< delta_1 (m)
  double fullyPlasticOverlap() const { return delta2_; }   ///< delta_2 (m)

 private:
  RelativeRadii r_;
  HertzFactors h_;
  JamariParameters p_;
  double delta1_, delta2_;
};

}  // namespace sqdem
