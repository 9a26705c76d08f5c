#pragma once
// Verification against Table 1 of the review (004 §2.1): two superquadrics with
// eta1 = eta2 = 1/3 (n1 = n2 = 6), a = b, c = 2b, in three relative poses; the normalised force
// F / (4/3 E* R_vol^1/2 delta^3/2) = gamma sqrt(Rc / R_vol) from the accurate model (Eqs. 1-14)
// is compared with the review's accurate model, its FEM reference and its simplified model
// (1/R = sqrt(Gaussian curvature) per body, gamma = 1, radii capped at 10 R_vol, Eqs. 17-18).
//
// Poses (the source paper's set-up is not in the seeds; this convention reproduces the review's
// accurate-model values): particle I axis-aligned at the origin; particle II rotated by
// R_II = Rz(phi_f) Rx(theta_s) (body -> world) with its centre on u = (sin theta_L, 0, cos theta_L),
// moved along u until the surfaces touch, then by a small overlap.

#include <array>

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

struct Table1Case {
  int id;
  double thetaL, phiF, thetaS;  ///< pose angles (degrees)
  double accurate;              ///< review's accurate geometrical model (Table 1)
  double fem;                   ///< review's finite-element reference (Table 1)
};

inline constexpr std::array<Table1Case, 3> table1Cases{{
    {1, 10.0, 80.0, 50.0, 1.5911, 1.4855},
    {2, 70.0, 90.0, 40.0, 1.5923, 1.6306},
    {3, 40.0, 70.0, 50.0, 0.5345, 0.5460},
}};
/// The review's simplified model gives sqrt(5) in all three cases (both radii at the cap).
inline constexpr double table1Simplified = 2.2361;
inline constexpr double table1CapFactor = 10.0;

struct Table1Result {
  Table1Case reference;
  Pose second;                          ///< particle II's pose (particle I at the origin, unrotated)
  ContactGeometry contact;
  double volumeEquivalentRadius = 0.0;  ///< R_vol of either particle (m)
  RelativeRadii radii;                  ///< capped at 10 R_vol
  HertzFactors explicitFactors;         ///< e^2 from Eq. 14 (the review's choice)
  HertzFactors exactFactors;            ///< e^2 from Eq. 13
  double normalisedForce = 0.0;         ///< (i) gamma sqrt(Rc/R_vol), explicit e^2
  double normalisedForceExact = 0.0;    ///< the same with the exact e^2
  double simplifiedForce = 0.0;         ///< (iv) simplified model from sqdem's curvatures
};

/// The Table 1 particle: n1 = n2 = 6, a = b = 1, c = 2 (lengths in units of b).
Superquadric table1Shape();
/// Pose of particle II with its centre at `distance` along u.
Pose table1PoseOfSecond(const Table1Case& c, double distance);
/// Runs one case at overlap = overlapFraction * R_vol.
Table1Result runTable1Case(const Table1Case& c, double overlapFraction = 1e-4);

/// Normalised force F / (4/3 E* R_vol^1/2 delta^3/2) = gamma sqrt(Rc / R_vol) (004 Eq. 1).
double normalisedHertzForce(double gamma, double Rc, double Rvol);

}  // namespace sqdem
