#pragma once
// Haervig et al.'s adhesive JKR contact, tangential and rolling models for reduced-stiffness DEM
// (001 Eqs. 7-24, A.1-A.11). gamma is the surface energy density (J/m^2), W = 2 gamma.
//
//   contact radius   a^4 - 2 R delta a^2 - 4 pi gamma R^2 a / E* + R^2 delta^2 = 0  (Eq. 10),
//                    stable root as in jkr_circular.hpp; a_0 = (9 pi gamma R^2/E*)^1/3 (Eq. 7)
//   normal force     F = 4 E* a^3/(3 R) - 4 sqrt(pi gamma E* a^3) (Eqs. 8-9, > 0 repulsive);
//                    simplified JKR: the contact breaks as soon as delta < 0 on separation
//   tangential       F_t = -S_t s - 2 sqrt(5/6) beta sqrt(S_t m) v_t, S_t = 8 G* sqrt(R delta),
//                    1/G* = (2 - nu_i)/G_i + (2 - nu_j)/G_j (effectiveShearModulus in elliptic.hpp),
//                    |F_t| <= mu |F_N + 2 F_C|                                       (Eqs. 14-17)
//   rolling          xi_crit = a_0/12 (dgamma/gamma), k_r = 4 F_C (a/a_0)^3/2, M_r = k_r xi,
//                    |xi| <= xi_crit, F_C = 3 pi gamma R                              (Eqs. 18-22)
//   reduced stiffness  gamma_mod = gamma (E_mod/E)^2/5 keeps the separation energy (Eq. 23,
//                    A.11); in the rolling model F_C and xi_crit keep their unmodified values and
//                    only a/a_0 is taken from the modified contact (001 Section 3.2).

#include "sqdem/math/types.hpp"
#include "sqdem/mechanics/jkr_circular.hpp"
#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/mechanics/normal_law.hpp"

namespace sqdem {

class HaervigJkr {
 public:
  HaervigJkr(double effectiveModulus, double surfaceEnergy, double effectiveRadius);

  double contactRadius(double overlap) const;      ///< a(delta) (m), delta >= 0
  double normalForce(double overlap) const;        ///< Eqs. 8-9 (N); 0 for delta < 0
  double equilibriumContactRadius() const;         ///< a_0, Eq. 7 (m)
  double criticalForce() const;                    ///< F_C = 3 pi gamma R (N)

 private:
  double surfaceEnergy() const { return 0.5 * jkr_.workOfAdhesion; }  ///< gamma = W/2

  CircularJkr jkr_;
};

/// Eq. 24: the surface energy that keeps the separation energy when E is replaced by E_mod.
double reducedStiffnessSurfaceEnergy(double surfaceEnergy, double youngs, double reducedYoungs);


/// Eqs. 14-17 with the spring displacement s as history (m). Adds the tangential displacement
/// increment, returns the force; on sliding, s is reset to the value consistent with the cap.
struct HaervigTangential {
  double shearModulus;  ///< G* (Pa), Eq. 15
  double radius;        ///< R (m)
  double mass;          ///< m (kg)
  double beta;          ///< damping coefficient of Eq. 12 (<= 0 as printed; |beta| is used)
  double friction;      ///< mu_s

  Vec3 force(Vec3& spring, const Vec3& increment, const Vec3& velocity, double overlap,
             double normalForce, double criticalForce) const;
};

/// Eqs. 18-22: rolling torque magnitude for rolling displacement xi (truncated in place, m).
struct HaervigRolling {
  double criticalForce;     ///< F_C of the unmodified material (N)
  double criticalDistance;  ///< xi_crit = a_0/12 dgamma/gamma of the unmodified material (m)

  /// k_r xi with k_r = 4 F_C (a/a_0)^3/2; a/a_0 from the (possibly modified) contact.
  double torque(double& xi, double radiusRatio) const;
};

/// normal: haervig_jkr (normal_law.hpp component): the simplified JKR of Eqs. 7-10 on the
/// Hertz-equivalent sphere R* = gamma^2 Rc of the elliptic contact (the sphere whose Hertz force
/// equals the elliptic one, 004 Eq. 1). Key: surface_energy gamma (J/m^2, W = 2 gamma); with
/// reduced_stiffness the law uses gamma_mod of Eq. 24. It acts for delta > 0 only (the simplified
/// model breaks the contact at delta = 0). A = pi Rc beta delta and S_n = 2 E* gamma (Rc delta)^1/2
/// as for elliptic Hertz; pull-off F_C = 3 pi gamma_mod R*. No history.
struct HaervigJkrLaw {
  struct History {};
  static constexpr std::array<std::string_view, 1> keys{"surface_energy"};
  double surfaceEnergy = 0.0;      ///< gamma_mod (J/m^2), what the law uses
  double realSurfaceEnergy = 0.0;  ///< gamma of the real material (J/m^2), for the rolling resistance

  static HaervigJkrLaw read(const LawInput& in, const PairElasticity& pair);
  /// The JKR contact of Eqs. 7-10 at this contact (modified material).
  HaervigJkr at(const NormalContact& c) const;
  NormalResponse force(const NormalContact& c, double overlap, History&) const;
  double range(const History&) const { return 0.0; }
  double reach(double, double) const { return 0.0; }
  bool adhesive() const { return true; }
  /// pull_off_force (N, < 0: a pull) and a_0, the contact radius at zero load (m).
  std::vector<LawConstant> constants(const NormalContact& c) const {
    const HaervigJkr law = at(c);
    return {{"pull_off_force", -law.criticalForce()}, {"a_0", law.equilibriumContactRadius()}};
  }
};

/// rolling_hysteresis, the engine's rolling component with normal: haervig_jkr (Eqs. 18-22):
/// rolling displacement xi integrated from
///   v_L = R (w_A - w_B) x n + 1/2 (r_A - r_B)/(r_A + r_B) v_S                          (Eq. 20)
/// (n from A to B, v_S the sliding velocity of A relative to B, R = gamma^2 Rc the
/// Hertz-equivalent radius, r_k volume radii, r_B -> infinity for a wall), kept in the tangent
/// plane, truncated at |xi| <= xi_crit = a_0/12 (dgamma/gamma) (Eqs. 18, 22); moment on A
/// -k_r n x xi, k_r = 4 F_C (a/a_0)^3/2 (Eq. 21). F_C and xi_crit use the real E* and gamma,
/// a/a_0 the law's (modified) contact (Section 3.2). History: xi (m).
struct HaervigRollingResistance {
  double hysteresis = 0.0;   ///< dgamma/gamma (-), Eq. 18
  double realModulus = 0.0;  ///< E* of the unreduced material (Pa)

  /// Moment on B (N m) at this overlap (m); vt the tangential velocity of B relative to A
  /// (m/s), radii r_A, r_B (m; r_B = 0 for a wall), angular velocities (rad/s). Updates xi.
  Vec3 moment(const HaervigJkrLaw& law, const NormalContact& c, double overlap, const Vec3& n, const Vec3& vt,
              double radiusA, double radiusB, const Vec3& omegaA, const Vec3& omegaB, Vec3& xi, double dt) const;
};

}  // namespace sqdem
