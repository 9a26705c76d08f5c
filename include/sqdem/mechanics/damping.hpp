#pragma once
// Normal dissipation: restitution-based damping and viscoelastic (Brilliantov-type) damping.
// Sign convention: overlapRate = d(delta)/dt (> 0 while approaching); a returned force > 0 is
// repulsive, so every damping force opposes the relative normal motion.
//
// Restitution-based (000 Eqs. 24-26, 001 Eqs. 11-13):
//   damping ratio     zeta = -ln e / sqrt(pi^2 + ln^2 e)            (000 Eq. 26, 001 Eq. 12)
//   linear spring     F_d = 2 zeta sqrt(m* k_n) d(delta)/dt        (000 Eq. 24; exact e for a
//                                                                   linear spring, tested)
//   Hertz spring      F_d = 2 sqrt(5/6) zeta sqrt(m* S_n) d(delta)/dt, S_n = 2 E* sqrt(R* delta)
//                     (001 Eqs. 11, 13; Eq. 11 prints "2 5/6", the tangential Eq. 16 and
//                     Tsuji et al. have sqrt(5/6)). With Hertz this e is velocity-independent
//                     but only approximately the prescribed one (tests report how close).
//   The tangential forms (000 Eq. 25, 001 Eq. 16) are the same functions with k_t or S_t.
//
// Viscoelastic (004 Eqs. 37-40):
//   F = E* R_c^1/2 delta^1/2 (4/3 delta + 2 A d(delta)/dt) gamma                   (Eq. 38)
//   A = 1/3 (3 eta2 - eta1)^2 / (3 eta2 + 2 eta1) (1 - nu^2)(1 - 2 nu)/(E nu^2)  (after Eq. 38;
//       eta1, eta2 bulk viscosities (Pa s), A in s)
//   adhesive extra term (Eq. 40): 3/4 B sqrt(pi W / D) R_c^3/4 delta^-1/4 d(delta)/dt,
//       D = 3/(4 E*); B (m s) is taken as a parameter because the printed expression for B
//       (with q0) is garbled in the seed.

#include <cmath>

namespace sqdem {

/// The engine's damping component (001 Eqs. 11, 13, 16): a force 2 sqrt(5/6) zeta sqrt(m* k)
/// times the rate, normal or per tangential axis, with k the stiffness the law reports there.
struct ViscousDamping {
  double ratio = 0.0;  ///< zeta (-), restitutionDampingRatio(e); 0 for e = 1
  double scale() const { return 2.0 * std::sqrt(5.0 / 6.0) * ratio; }
  /// The coefficient (N s/m) for mass m* (kg) and stiffness k (N/m).
  double coefficient(double mass, double stiffness) const { return scale() * std::sqrt(mass * stiffness); }
};

/// zeta(e) for a coefficient of restitution e in (0, 1] (000 Eq. 26 with beta = 1).
double restitutionDampingRatio(double restitution);

/// 000 Eq. 24: 2 zeta sqrt(m k) d(delta)/dt (N); mass (kg), stiffness (N/m), rate (m/s).
double linearDampingForce(double zeta, double mass, double stiffness, double overlapRate);

/// 001 Eqs. 11, 13: 2 sqrt(5/6) zeta sqrt(m S_n) d(delta)/dt with S_n = 2 E* sqrt(R delta).
double hertzDampingForce(double zeta, double mass, double effectiveModulus, double radius,
                         double overlap, double overlapRate);

/// The dissipative constant A (s) of 004 after Eq. 38 from the bulk viscosities (Pa s).
double viscoelasticConstant(double eta1, double eta2, double youngs, double poisson);

/// 004 Eq. 37: 2 A E* R_c^1/2 delta^1/2 d(delta)/dt gamma (N), the dissipative part only.
double viscoelasticDampingForce(double A, double effectiveModulus, double Rc, double gamma,
                                double overlap, double overlapRate);

/// 004 Eq. 40, adhesive term: 3/4 B sqrt(pi W/D) R_c^3/4 delta^-1/4 d(delta)/dt (N).
double adhesiveViscoelasticDampingForce(double B, double workOfAdhesion, double effectiveModulus,
                                        double Rc, double overlap, double overlapRate);

}  // namespace sqdem
