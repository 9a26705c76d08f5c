#pragma once
// Cattaneo-Mindlin-Deresiewicz tangential force on an elliptic contact (004 Eqs. 56-69), along a
// fixed tangential direction at angle theta to the contact ellipse's major axis, at constant
// normal force F_n.
//
//   chi(theta) = {[(1 - nu) K + nu D]^2 cos^2 theta + [K - nu D]^2 sin^2 theta}^-1/2   (Eq. 57)
//   Phi(theta) = 4 / (pi (2 - nu) chi(theta))   (equals Eq. 61 at theta = 0 and pi/2; 1 for e = 0)
//   no-slip stiffness  k_t = 8 G* a_c / Phi     (Eq. 56 with G = (2 - nu) G*; e = 0: 8 G* a)
//   slip displacement  delta_L = 3 mu F_n Phi / (16 G* a_c)                         (Eq. 62)
//   virgin loading     F = mu F_n [1 - (1 - delta/delta_L)^3/2]                     (Eqs. 59-60)
//   after a reversal at (delta_r, F_r), moving in direction s = -1 (unloading) or +1 (reloading):
//                      F = F_r + s 2 mu F_n [1 - (1 - s (delta - delta_r)/(2 delta_L))^3/2]
//                      (Masing's rule; Eq. 67 is its inverse for unloading from F_t*)
//   full slip          |F| = mu F_n (Coulomb)
//   energy per cycle between +-F*: E_d = 9 (mu F_n)^2 Phi/(10 G* a_c) [1 - (1 - F*/(mu F_n))^5/3
//                      - 5 F*/(6 mu F_n) (1 + (1 - F*/(mu F_n))^2/3)]   (Eq. 69 with G = (2 - nu) G*)
// G* = ((2 - nu_A)/G_A + (2 - nu_B)/G_B)^-1 (Pa, 004 after Eq. 61); nu is the common Poisson ratio
// the elliptic formulas assume (use the mean of the two bodies'); a_c the semi-major axis (m).
// The history keeps only the last turning point (nested loops are not remembered).

namespace sqdem {

struct MindlinDeresiewiczHistory {
  double displacement = 0.0;         ///< last tangential displacement (m)
  double force = 0.0;                ///< last tangential force (N)
  double turningDisplacement = 0.0;  ///< delta_r (m)
  double turningForce = 0.0;         ///< F_r (N)
  int direction = 0;                 ///< +1 increasing, -1 decreasing, 0 not moved yet
  bool virgin = true;                ///< no reversal yet: the virgin loading curve applies
};

class MindlinDeresiewicz {
 public:
  /// G* (Pa), semi-major axis a_c (m), e^2 of the contact ellipse, nu, theta (rad), mu, F_n (N).
  MindlinDeresiewicz(double shearModulus, double semiMajorAxis, double e2, double poisson, double theta,
                     double friction, double normalForce);

  double phi() const { return phi_; }
  double noSlipStiffness() const { return 8.0 * G_ * a_ / phi_; }
  double slipDisplacement() const { return 3.0 * limit_ * phi_ / (16.0 * G_ * a_); }
  /// Force at a new displacement (m), updating the history's turning point on reversals.
  double force(double displacement, MindlinDeresiewiczHistory& history) const;
  /// Eq. 69: energy dissipated per cycle between -F* and +F* (J).
  double dissipationPerCycle(double amplitude) const;

 private:
  double G_, a_, phi_, limit_;
};

/// Phi along the contact ellipse's axes, from K(e), D(e) (Eq. 57 at theta = 0 and pi/2):
/// Phi(0) = 4 [(1 - nu) K + nu D] / (pi (2 - nu)), Phi(pi/2) = 4 [K - nu D] / (pi (2 - nu));
/// in between Phi(theta) = sqrt(Phi(0)^2 cos^2 theta + Phi(pi/2)^2 sin^2 theta). 1 for a circle.
struct MindlinPhi {
  double major = 1.0, minor = 1.0;
};
MindlinPhi mindlinPhi(double K, double D, double poisson);

/// Semi-major axis of the Hertz contact ellipse, a_c = sqrt(A / (pi sqrt(1 - e^2))) for area A.
double contactSemiMajorAxis(double area, double e2);

}  // namespace sqdem
