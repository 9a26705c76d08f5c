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
// continuous at delta_1 (mean Hertz pressure 2/3 K_v H there) and at delta_2 (tested).
//
// Unloading (the seed gives none; our choice, in the spirit of Thornton-Ning and 002's
// unloading): elastic Hertz recovery of the contact as last loaded. At the largest overlap
// delta_m the loading curve carries F_m over the area A_m; an elastic elliptic Hertz contact
// (factors gamma, beta of the contact) carrying both has the radius R' = A_m/(pi beta delta_e)
// and the elastic overlap delta_e = 3 F_m / (4 E* gamma sqrt(A_m/(pi beta))) (004 Eqs. 1-2), so
//   F = F_m ((delta - delta_p)/delta_e)^3/2, A = A_m (delta - delta_p)/delta_e,
//   delta_p = delta_m - delta_e (the residual overlap), F = 0 below delta_p;
// reloading follows the same curve back to delta_m. Below delta_1 it is the elastic loading
// curve itself (delta_e = delta_m, no hysteresis).

#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/mechanics/normal_law.hpp"

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
  double loadingArea(double overlap) const;   ///< A of Eq. 2, 46 or 43 (m^2)
  /// Force and area at `overlap` after the largest overlap `maxOverlap` (above).
  struct Point {
    double force, area;
  };
  Point at(double overlap, double maxOverlap) const;
  double yieldOverlap() const { return delta1_; }          ///< delta_1 (m)
  double fullyPlasticOverlap() const { return delta2_; }   ///< delta_2 (m)

 private:
  RelativeRadii r_;
  HertzFactors h_;
  JamariParameters p_;
  double delta1_, delta2_;
};

/// normal: jamari (normal_law.hpp component) on the detector's curvatures, with the unloading
/// above. Keys: hardness H (Pa), max_pressure_factor K_v (default 0.454 + 0.41 nu, 000 after
/// Eq. 33), mean_pressure_factor c_h (default 1: H is the fully plastic mean pressure),
/// plastic_overlap_factor c_A (default 220: delta_2 = 110 delta_1 for a circle, Eq. 44). No
/// reduced_stiffness. S_n = 2 E* sqrt(A/pi). History: the largest overlap.
struct JamariLaw {
  struct History {
    double maxOverlap = 0.0;  ///< (m)
  };
  static constexpr std::array<std::string_view, 4> keys{"hardness", "max_pressure_factor", "mean_pressure_factor",
                                                        "plastic_overlap_factor"};
  JamariParameters parameters;  ///< effectiveModulus is taken from each contact

  static JamariLaw read(const LawInput& in, const PairElasticity& pair);
  NormalResponse force(const NormalContact& c, double overlap, History& h) const;
  double range(const History&) const { return 0.0; }
  double reach(double, double) const { return 0.0; }
  /// The law at this contact (its E*).
  JamariElasticPlastic at(const NormalContact& c) const {
    JamariParameters p = parameters;
    p.effectiveModulus = c.effectiveModulus;
    return {c.radii, c.factors, p};
  }
  /// (delta_1, F(delta_1)) at this contact.
  YieldPoint yieldPoint(const NormalContact& c) const {
    const JamariElasticPlastic law = at(c);
    return {law.yieldOverlap(), law.loadingForce(law.yieldOverlap())};
  }
  /// delta_1 (first yield) and delta_2 (fully plastic), m.
  std::vector<LawConstant> constants(const NormalContact& c) const {
    const JamariElasticPlastic law = at(c);
    return {{"delta_1", law.yieldOverlap()}, {"delta_2", law.fullyPlasticOverlap()}};
  }
};

}  // namespace sqdem
