#pragma once
// Nan, Goh & Rahman's improved linear elasto-plastic adhesive normal law (000 Eqs. 1-20, 27-67).
//
// Piecewise linear in the overlap alpha (000 Fig. 1-2), force f > 0 repulsive:
//   snap-in at alpha = 0 (first contact) to -f_0 = -8/9 f_ce, f_ce = 3/2 pi W R*      (Eqs. 4-5)
//   elastic line      f_e = k_e (alpha - alpha_p)                                     (Eq. 17)
//   plastic line      f_p = f_y + k_p (alpha - alpha_y)                               (Eq. 18)
//   adhesive line     f_c = -f_cp + k_c (alpha_cp - alpha), alpha_jp <= alpha <= alpha_cp (Eq. 19)
//   f = min(f_e, f_p) above alpha_cp, f_c down to alpha_jp, then detachment (f = 0)   (Eq. 20)
//   contact re-forms at alpha_c0 = alpha_p - 8/9 f_cp/k_e with f = -8/9 f_cp           (Eq. 12)
// History: the largest overlap alpha_max past yield. From it (Eqs. 10-16, 42-46, 59):
//   f_max = f_y + k_p (alpha_max - alpha_y), k_e = k_el sqrt(alpha_max/alpha_y) (Eq. 46),
//   alpha_p = (1 - k_p/k_e) alpha_max + (k_p alpha_y - f_y)/k_e (Eq. 16), k_c = k_e k_cl/k_el,
//   f_cp/f_ce = (-A + sqrt(A^2 + 4 k_e/k_el (A alpha_p/alpha_0 + 1)))/2,
//   A = 96 / (56 k_e/k_c + 17)                                         (Eqs. 56-59, see below),
//   alpha_cp = alpha_p - f_cp/k_e (13), alpha_jp = alpha_cp - 4/9 f_cp/k_c (14).
//   Before yield these reduce to k_e = k_el, alpha_p = alpha_0 = 8/9 f_ce/k_el, f_cp = f_ce.
// Parameters (Eqs. 27-38, 52):
//   yield work W_y = (pi R* p_y)^5 / (60 E*^4 R*^2), f_y = sqrt(2 k_el W_y),
//   alpha_y = alpha_0 + f_y/k_el                                                  (Eqs. 27-29);
//   k_el = pi R* p_y by default (Eq. 52), k_p = k_el by default (000 Section 3.6);
//   k_el/k_cl = 162/(56 x) - 17/56 with x = f_ce^2/(k_el W_JKR), W_JKR = 7.09 (W^5 R*^4/E*^2)^1/3.
// Corrections to the seed (each checked in tests/nan_adhesive_test.cpp):
//   - Eq. A1 has k_cl in its second term; the area it describes (alpha_ce to 0 on the elastic
//     line) gives 17/162 f_ce^2/k_el, which is what Eq. 36 uses. Likewise W_1 (A2) and W_2 (A3)
//     are areas under the elastic line: f^2/(2 k_el).
//   - Eq. 38 is printed as k_cl/k_el = 0.92 k_el/(W^1/3 E*^2/3 R*^2/3) - 0.3; solving Eq. 36 with
//     Eqs. 5 and 37 gives that expression for k_el/k_cl (the text after it: "k_el/k_cl ... is
//     larger than 1"); the unrounded form above is used.
//   - Table 4 prints A = 16/(56 k_e/k_cl + 162); Eq. 56 (and W_6 of Eq. A7) give 96/(56 r + 17).
// Non-spherical contacts: R* = gamma^2 R_c, the radius of the sphere whose Hertz force equals the
// elliptic Hertz force 4/3 E* sqrt(R_c) gamma delta^3/2 (004 Eq. 1); m* the reduced mass.
// Units: forces N, overlaps m, stiffnesses N/m, W (work of adhesion, the seed's Gamma) J/m^2,
// p_y (yield contact pressure, the softer body's) Pa.

#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/mechanics/normal_law.hpp"

namespace sqdem {

struct NanParameters {
  double effectiveModulus = 0.0;  ///< E* (Pa)
  double effectiveRadius = 0.0;   ///< R* (m)
  double workOfAdhesion = 0.0;    ///< Gamma (J/m^2)
  double yieldPressure = 0.0;     ///< p_y (Pa)
  double elasticStiffness = 0.0;  ///< k_el (N/m); 0 selects pi R* p_y (Eq. 52)
  double plasticStiffness = 0.0;  ///< k_p (N/m); 0 selects k_el
};

enum class NanBranch { Detached, Elastic, Plastic, Adhesive };
const char* describe(NanBranch branch);

struct NanHistory {
  bool attached = false;
  double maxOverlap = 0.0;  ///< alpha_max, the largest overlap reached past alpha_y (m)
};

struct NanState {
  double force = 0.0;
  double stiffness = 0.0;  ///< slope of the branch in use, k_e, k_p or k_c (N/m)
  NanBranch branch = NanBranch::Detached;
};

/// The unloading quantities that follow from alpha_max (Eqs. 10-16, 46, 59).
struct NanUnloading {
  double kE, kC, fMax, alphaP, fCp, alphaC0, alphaCp, alphaJp;
};

class NanAdhesivePlastic {
 public:
  explicit NanAdhesivePlastic(const NanParameters& parameters);

  NanState evaluate(double overlap, NanHistory& history) const;
  NanUnloading unloadingFrom(double maxOverlap) const;

  double pullOffForceElastic() const { return fCe_; }  ///< f_ce (N)
  double yieldForce() const { return fY_; }            ///< f_y (N)
  double yieldOverlap() const { return alphaY_; }      ///< alpha_y (m)
  double snapInForce() const { return 8.0 / 9.0 * fCe_; }  ///< f_0 (N)
  double kEl() const { return kEl_; }
  double kCl() const { return kCl_; }
  double kP() const { return kP_; }
  double alpha0() const { return alpha0_; }
  /// JKR separation work W_JKR (Eq. 37) (J) and the yield work W_y (Eq. 27) (J).
  double separationWork() const { return wJkr_; }
  double yieldWork() const { return wY_; }

 private:
  double kEl_, kP_, kCl_, fCe_, fY_, alpha0_, alphaY_, wJkr_, wY_;
};

/// 000 Eq. 68: 2 sqrt(m/k_e) (s) (the Rayleigh time of Eq. 71 is in dynamics/rayleigh_time.hpp).
double nanCriticalTimeStep(double mass, double stiffness);

/// normal: nan_adhesive (normal_law.hpp component) on R* = gamma^2 Rc (above). Keys:
/// surface_energy gamma (J/m^2, W = 2 gamma), yield_pressure p_y (Pa), elastic_stiffness k_el
/// and plastic_stiffness k_p (N/m, default Eq. 52 and k_el). No reduced_stiffness (000 gives no
/// rule). Snap-in at alpha = 0, detachment below alpha_jp; while attached its range is unbounded.
/// S_n = the slope of the branch in use (k_e, k_p or k_c). History: attached, alpha_max. A contact
/// whose R* the parameters do not admit (Eq. 36 gives k_cl < 0: too small an R* for this k_el)
/// answers valid = false; the engine counts it (ContactStatistics::lawFailures).
struct NanAdhesiveLaw {
  using History = NanHistory;
  static constexpr std::array<std::string_view, 4> keys{"surface_energy", "yield_pressure", "elastic_stiffness",
                                                        "plastic_stiffness"};
  double surfaceEnergy = 0.0;     ///< gamma (J/m^2)
  double yieldPressure = 0.0;     ///< p_y (Pa)
  double elasticStiffness = 0.0;  ///< k_el (N/m), 0: Eq. 52
  double plasticStiffness = 0.0;  ///< k_p (N/m), 0: k_el

  static NanAdhesiveLaw read(const LawInput& in, const PairElasticity& pair);
  /// The law at this contact; throws std::invalid_argument when its parameters admit none.
  NanAdhesivePlastic at(const NormalContact& c) const;
  NormalResponse force(const NormalContact& c, double overlap, History& h) const;
  double range(const History& h) const;
  /// 2 |alpha_jp| before yield for R* = R; throws like at().
  double reach(double effectiveModulus, double R) const;
  bool adhesive() const { return true; }
  void check(const NormalContact& c) const { at(c); }
  /// (alpha_y, f_y) at this contact.
  YieldPoint yieldPoint(const NormalContact& c) const {
    const NanAdhesivePlastic law = at(c);
    return {law.yieldOverlap(), law.yieldForce()};
  }
  /// alpha_y, f_y, f_ce, k_el, k_cl, k_p at this contact.
  std::vector<LawConstant> constants(const NormalContact& c) const {
    const NanAdhesivePlastic law = at(c);
    return {{"alpha_y", law.yieldOverlap()}, {"f_y", law.yieldForce()}, {"f_ce", law.pullOffForceElastic()},
            {"k_el", law.kEl()},             {"k_cl", law.kCl()},       {"k_p", law.kP()}};
  }
};

}  // namespace sqdem
