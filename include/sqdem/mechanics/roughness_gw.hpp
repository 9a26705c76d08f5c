#pragma once
// Greenwood-Williamson roughness on an elliptic contact (004 Eqs. 29-36).
//
// Asperity heights are Gaussian with standard deviation sigma_s; h = d/sigma_s is the
// standardised separation of the mean planes. Summing Hertzian asperity contacts gives
//   F_r = 4/3 N A_n E* R_c^1/2 sigma_s^3/2 gamma*_GW                                 (Eq. 33)
//   A_r = pi N A_n R_c sigma_s beta*_GW                                              (Eq. 34)
// with gamma*_GW = gamma F_3/2(h), beta*_GW = beta F_1(h) and the GW integrals
//   F_n(h) = int_h^inf (z - h)^n phi(z) dz, phi the standard normal density          (Eqs. 31-32)
//   F_3/2(h) = exp(-h^2/4) sqrt(h) [(h^2 + 1) K_1/4(h^2/4) - h^2 K_3/4(h^2/4)] / (4 sqrt(pi))
//                                                                           (Eq. 35, h > 0)
//   F_1(h)   = exp(-h^2/2)/sqrt(2 pi) - h/2 erfc(h/sqrt 2)                           (Eq. 36)
// K_nu is the modified Bessel function of the second kind (Boost.Math). Eq. 36 as printed has
// exp(-h^2/4) and erf; the integral of Eq. 32 it stands for is the form above (tested against
// quadrature, as is Eq. 35). For h <= 0 (mean planes interpenetrating) F_3/2 is integrated
// numerically (exp-sinh quadrature). gamma and beta come from the Hertz factors (004 Eqs.
// 11-12) or from the JKR ones (Eqs. 27-28), as the review states after Eq. 36.
//
// N asperity density (1/m^2), A_n nominal contact area (m^2), sigma_s (m), E* (Pa), R_c (m).

#include "sqdem/mechanics/jkr_elliptic.hpp"
#include "sqdem/mechanics/normal_law.hpp"

namespace sqdem {

double greenwoodWilliamsonForceIntegral(double h);  ///< F_3/2(h), dimensionless
double greenwoodWilliamsonAreaIntegral(double h);   ///< F_1(h), dimensionless

struct RoughContact {
  double asperityCount;  ///< N A_n, asperities on the nominal contact area (-)
  double sigma;          ///< sigma_s, standard deviation of asperity heights (m)

  /// Eq. 33 (N); gamma the smooth-contact force factor, h = d/sigma_s.
  double force(double effectiveModulus, double Rc, double gamma, double h) const;
  /// Eq. 34 (m^2); beta the smooth-contact area factor.
  double area(double Rc, double beta, double h) const;
};

/// normal: elliptic_hertz (or volume_sphere_hertz) with `roughness: {sigma, asperity_count}`
/// (normal_law.hpp component): Eqs. 33-34 in place of the smooth force, h = -delta/sigma_s the
/// separation of the mean surfaces (the detector's overlap, < 0 for a gap); it acts from a gap
/// of 4 sigma_s (F_3/2(4)/F_3/2(0) = 1.0e-5). S_n = dF/d(delta) by central differences.
struct GreenwoodWilliamsonLaw {
  struct History {};
  RoughContact rough;

  NormalResponse force(const NormalContact& c, double overlap, History&) const;
  double range(const History&) const { return 4.0 * rough.sigma; }
  double reach(double, double) const { return 4.0 * rough.sigma; }
};

/// normal: elliptic_jkr with `roughness` (normal_law.hpp component): Greenwood-Williamson with
/// adhesive asperities. The review lets the JKR factors (Eqs. 27-28) stand for gamma and beta in
/// Eqs. 35-36 (after Eq. 36); gamma_JG varies along the JKR curve, so it is taken at each
/// asperity's own overlap w: Eq. 29 with the asperity force of Eq. 27,
/// f(w) = 4/3 E* R_c1^1/2 w^3/2 gamma_JG(w), the elliptic JKR force (jkr_elliptic.hpp):
///   F = N A_n int_0^inf f(sigma s) phi(s + h) ds,  A = N A_n int_0^inf A_JG(sigma s) phi(s + h) ds
/// (fixed Gauss-Legendre rules over the Gaussian, roughness_gw.cpp; within 1e-11 of adaptive
/// exp-sinh quadrature, tests/roughness_test.cpp). Asperities snap into contact at w = 0 and
/// act on the stable JKR branch for w >= 0, as in Fuller & Tabor's loading curves (Proc. R.
/// Soc. A 345, 1975): no asperity history, hence no hysteresis. As W -> 0 it is
/// GreenwoodWilliamsonLaw with R_c1 and the JKR factors' Hertz limit (tested). Range 4 sigma;
/// S_n = dF/d(delta) by the same rules (phi's derivative in h). The Coulomb limit stays mu F_n
/// (no rule for the adhesion of a rough contact's asperities in friction).
struct RoughJkrLaw {
  struct History {};
  RoughContact rough;
  double surfaceEnergy = 0.0;  ///< gamma (J/m^2), W = 2 gamma
  JkrCurve curve = JkrCurve::Tabulated;  ///< of the asperities' JKR law (EllipticJkrLaw's key `tabulated`)

  NormalResponse force(const NormalContact& c, double overlap, History&) const;
  double range(const History&) const { return 4.0 * rough.sigma; }
  double reach(double, double) const { return 4.0 * rough.sigma; }
  bool adhesive() const { return true; }
};

}  // namespace sqdem
