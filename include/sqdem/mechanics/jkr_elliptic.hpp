#pragma once
// Elliptic JKR contact, Johnson & Greenwood's approximation (004 Eqs. 19-28).
//
// The contact ellipse has axis ratio g = b_c/a_c <= 1, e^2 = 1 - g^2, and the load-dependent g
// parametrises the whole force-overlap curve. With lambda = sqrt(Ri/Rj) <= 1 (Ri <= Rj the
// relative principal radii, 004 Eqs. 3-4), R_c1 = sqrt(Ri Rj), and the integrals B, C, D of
// Eqs. 24-26 at e^2:
//   Pi_2 = ((lambda^2 + 1) C + D) / (lambda [(D + C)(B + g^2 C) - g^2 C^2])          (Eq. 23)
//   Pi_1 = (lambda + 1/lambda - B Pi_2) / D                                           (Eq. 22)
//   F/(3 pi R_c1 W)          = F_bar(g)                                               (Eq. 19)
//   delta (4E*/(9 pi W R_c1^1/2))^2/3 = delta_bar(g)                                  (Eq. 20)
//   A (4E*/(9 pi^5/2 W R_c1^2))^2/3  = A_bar(g)                                       (Eq. 21)
//   gamma_JG = F_bar / delta_bar^3/2 (Eq. 27), beta_JG = A_bar / delta_bar            (Eq. 28)
// so that F = 4/3 E* R_c1^1/2 delta^3/2 gamma_JG and A = pi R_c1 delta beta_JG (Eqs. 1-2 with
// R_c1 for R_c). Eq. 28 as printed has K X in the denominator; A_bar/delta_bar from Eqs. 20-21
// gives 2 K X (the same bracket as Eq. 20), which is what is used (and what makes beta_JG tend
// to the Hertz beta R_c/R_c1 as W -> 0, tested).
//
// g runs from the Hertz axis ratio g_H (Pi_2 g^2 = Pi_1, infinite dimensionless load; the
// Hertz limit W -> 0) to 1 (vanishing contact). Under displacement control the stable branch
// is g_H < g <= g_d, where delta_bar has its minimum (the detachment overlap, negative); the
// most tensile force (pull-off under load control) is the minimum of F_bar. For lambda -> 1 the
// curve tends to the classical circular JKR (pull-off 3/2 pi W R, tested); above
// lambda = 1 - 1e-6 the circular law (jkr_circular.hpp) is used directly.
//
// Parameters: effective modulus E* (Pa), work of adhesion W (J/m^2; W = 2 gamma for equal
// surface energies gamma), relative radii Ri <= Rj (m). Valid in the JKR regime (Tabor
// parameter > 3, 001 Eq. 1) and for small contact ellipses (Hertz assumptions).
//
// The dimensionless curve depends on lambda alone: JkrCurve::Tabulated reads it from a table
// (johnson_greenwood_table.hpp) for lambda >= 1e-2, JkrCurve::Exact solves it as above.

#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/mechanics/johnson_greenwood_table.hpp"
#include "sqdem/mechanics/jkr_circular.hpp"
#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/mechanics/normal_law.hpp"

namespace sqdem {

/// One point of the dimensionless Johnson-Greenwood curve (Eqs. 19-28) at axis ratio g.
struct JohnsonGreenwoodPoint {
  double g = 1.0;
  double force = 0.0;    ///< F_bar, Eq. 19
  double overlap = 0.0;  ///< delta_bar, Eq. 20
  double area = 0.0;     ///< A_bar, Eq. 21
  double gamma = 0.0;    ///< gamma_JG, Eq. 27
  double beta = 0.0;     ///< beta_JG, Eq. 28 (with 2 K, see above)
  double Pi1 = 0.0, Pi2 = 0.0;
};
JohnsonGreenwoodPoint johnsonGreenwoodPoint(double lambda, double g);

struct EllipticJkrState {
  double force = 0.0;       ///< normal force (N), > 0 repulsive
  double area = 0.0;        ///< contact area (m^2)
  double axisRatio = 1.0;   ///< g = b_c/a_c
  bool attached = true;     ///< false below the detachment overlap (force and area are 0)
};

/// Displacement-controlled JKR hysteresis: contact forms (snaps in) when the overlap reaches 0
/// and breaks below the detachment overlap (004 after Eq. 28; 001 Fig. 2 for the circular case).
struct JkrHistory {
  bool attached = false;
};

/// How EllipticJkr finds its point of the dimensionless curve.
enum class JkrCurve {
  Exact,      ///< the minimisations and the root solve of Eqs. 19-28 (~10-20 us per contact)
  Tabulated,  ///< the table (docs/contact_laws.md states its error); exact for lambda < 1e-2
};

class EllipticJkr {
 public:
  EllipticJkr(double effectiveModulus, double workOfAdhesion, const RelativeRadii& radii, JkrCurve method = JkrCurve::Exact);

  /// Force and area on the stable (displacement-controlled) branch at this overlap (m).
  EllipticJkrState evaluate(double overlap) const;
  /// The same along a displacement history: zero force until first contact at overlap 0.
  EllipticJkrState evaluate(double overlap, JkrHistory& history) const;
  double pullOffForce() const { return pullOffForce_; }            ///< most tensile force (N, < 0)
  double detachmentOverlap() const { return detachmentOverlap_; }  ///< (m, < 0)

 private:
  bool circular() const { return lambda_ >= 1.0 - 1e-6; }
  EllipticJkrState evaluateExact(double overlap) const;

  CircularJkr circle_;  ///< E*, W and R_c1; the law itself when circular()
  double lambda_;
  double forceScale_, overlapScale_, areaScale_;
  double gHertz_ = 1.0, gDetach_ = 1.0;
  double pullOffForce_ = 0.0, detachmentOverlap_ = 0.0;
  bool tabulated_ = false;  ///< the curve from the table (JkrCurve::Tabulated within its range)
  detail::JohnsonGreenwoodTable::Curve curve_;  ///< its place there
};

/// normal: elliptic_jkr (normal_law.hpp component): Johnson-Greenwood with the contact's relative
/// radii. Key: surface_energy gamma (J/m^2), W = 2 gamma; with reduced_stiffness gamma_mod of
/// 001 Eq. 24. Snap-in when the overlap first reaches 0, detachment below the detachment overlap;
/// while attached its range is unbounded (the law detaches). S_n = 2 E* sqrt(A/pi), the normal
/// stiffness of a contact of area A (flat punch): finite at detachment, where dF/d(delta) is not.
/// History: attached. A pull-off |F| of the contact counts as F_C in the Coulomb limit.
/// Key `tabulated` (default true): the curve from the table; false solves it per contact.
struct EllipticJkrLaw {
  using History = JkrHistory;
  double surfaceEnergy = 0.0;  ///< gamma (J/m^2) the law uses, W = 2 gamma
  JkrCurve curve = JkrCurve::Tabulated;

  static EllipticJkrLaw read(const LawInput& in, const PairElasticity& pair);
  EllipticJkr at(const NormalContact& c) const { return {c.effectiveModulus, 2.0 * surfaceEnergy, c.radii, curve}; }
  NormalResponse force(const NormalContact& c, double overlap, History& h) const;
  double range(const History& h) const;
  /// |detachment overlap| of the circular contact of radius R, times 2 (a bound for the elliptic
  /// ones of the same R_c1 = sqrt(Ri Rj) <= R; tests/jkr_test.cpp checks it over the ratios).
  double reach(double effectiveModulus, double R) const;
  bool adhesive() const { return true; }
  /// pull_off_force (N) and detachment_overlap (m).
  std::vector<LawConstant> constants(const NormalContact& c) const {
    const EllipticJkr law = at(c);
    return {{"pull_off_force", law.pullOffForce()}, {"detachment_overlap", law.detachmentOverlap()}};
  }
};

}  // namespace sqdem
