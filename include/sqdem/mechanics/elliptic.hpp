#pragma once
// Elliptic Hertz contact factors from the two surfaces' principal curvatures (004 §2.1).
//
//   relative radii      1/Ri, 1/Rj = ((k1A + k2A + k1B + k2B) +- sqrt((k1A - k2A)^2 + (k1B - k2B)^2
//                                     + 2 (k1A - k2A)(k1B - k2B) cos 2 omega)) / 2   (004 Eqs. 3-4)
//                       with Ri <= Rj (the printed Eqs. 3-4 swap the labels; Eqs. 13-14 need
//                       Ri/Rj <= 1), omega the angle between the k1 directions (Eq. 8);
//   radius cap          Ri, Rj <= capFactor * R_vol_ref, R_vol_ref = sqrt(R_vol,A R_vol,B)
//                       (a flat face has zero curvature; the review's Table 1 implies cap 10);
//   effective radius    Rc = Ri Rj / (Ri + Rj)                                       (Eq. 5);
//   eccentricity e^2    exact root of Eq. 13, explicit Eq. 14, or a table of Eq. 13;
//   correction factors  gamma(e^2) (Eq. 11), beta(e^2) (Eq. 12); sphere limit sqrt 2 and 2;
//   force and area      F = 4/3 E* Rc^1/2 delta^3/2 gamma (Eq. 1), A = pi Rc delta beta (Eq. 2).
//
// Becker & Kamlah's alternative (002 Eqs. 4-10): A = 1/(2 Rj), B = 1/(2 Ri) (Eq. 5),
// R_e = 1/(2 sqrt(AB)) = sqrt(Ri Rj) (Eq. 6), f = 1 - ((B/A)^p - 1)^q with (p, q) = (0.0602,
// 1.456) for f1 and (0.0684, 1.531) for f2 (Eq. 4 corrected: as printed, 1 - ((A/B)^p)^q,
// it gives f = 0 for spheres; the Greenwood form used here gives 1), and
// F = 4/3 E_e sqrt(R_e) delta^3/2 f2^-3/2 (Eq. 10). Valid while (B/A)^p < 2 (f >= 0),
// i.e. B/A up to ~1e5 for f1.

#include <cmath>
#include <numbers>

#include "sqdem/geometry/curvature.hpp"

namespace sqdem {

/// Relative principal radii of curvature at a contact (m), after the cap.
struct RelativeRadii {
  double Ri = 0.0;     ///< smaller relative radius (m)
  double Rj = 0.0;     ///< larger relative radius (m), Ri <= Rj
  double cosOmega = 1.0;  ///< |cos| of the angle between the k1 directions of the two surfaces
  double Rc = 0.0;     ///< effective radius Ri Rj / (Ri + Rj) (m)

  double ratio() const { return Ri / Rj; }  ///< Ri/Rj in (0, 1]
  double omega() const { return std::acos(cosOmega); }  ///< that angle (rad, [0, pi/2])
};

/// 004 Eqs. 3-5, 8 with every relative radius capped at radiusCap (m).
RelativeRadii relativeRadii(const PrincipalCurvatures& A, const PrincipalCurvatures& B,
                            double radiusCap);

enum class EccentricityMethod {
  Exact,      ///< root of 004 Eq. 13 (Carlson elliptic integrals + TOMS 748)
  Explicit,   ///< 004 Eq. 14, within ~1 % of Exact
  Tabulated,  ///< Eq. 13 tabulated in ln(Ri/Rj) and interpolated (cubic), ~1e-7 of Exact
};

/// Squared contact-ellipse eccentricity e^2 in [0, 1) for ratio = Ri/Rj in (0, 1].
double eccentricitySquaredExact(double ratio);
double eccentricitySquaredExplicit(double ratio);
double eccentricitySquaredTabulated(double ratio);
double eccentricitySquared(double ratio, EccentricityMethod method);

/// Hertz correction factors for the force (gamma, Eq. 11) and the area (beta, Eq. 12), with the
/// complete elliptic integrals K(e), D(e) of the tangential compliance (Eq. 57).
struct HertzFactors {
  double e2 = 0.0;
  double gamma = 0.0;
  double beta = 0.0;
  double K = 0.0;
  double D = 0.0;
};
HertzFactors hertzFactorsFromEccentricity(double e2);
/// The circle's factors (e = 0): gamma = sqrt 2, beta = 2, K = pi/2, D = pi/4, without evaluating them.
inline HertzFactors circularHertzFactors() {
  return {0.0, std::numbers::sqrt2, 2.0, 0.5 * std::numbers::pi, 0.25 * std::numbers::pi};
}
HertzFactors hertzFactors(double ratio, EccentricityMethod method);

/// Unit direction of the contact ellipse's major axis (the direction of the smaller relative
/// curvature, 004 Eqs. 3-5) in the plane normal to `normal`, from both surfaces' curvatures.
Vec3 contactMajorAxis(const PrincipalCurvatures& A, const PrincipalCurvatures& B, const Vec3& normal);

/// 004 Eq. 1: elliptic Hertz normal force (N); effectiveModulus E* (Pa), Rc and overlap (m).
double ellipticHertzForce(double effectiveModulus, double Rc, double overlap, double gamma);
/// 004 Eq. 2: contact area (m^2).
double ellipticHertzArea(double Rc, double overlap, double beta);

/// Becker & Kamlah's geometry (002 Eqs. 4-6, 10).
struct BeckerFactors {
  double A = 0.0, B = 0.0;  ///< half relative curvatures, A <= B (1/m)
  double Re = 0.0;          ///< effective contact radius (m)
  double f1 = 1.0, f2 = 1.0;
};
BeckerFactors beckerFactors(const RelativeRadii& radii);
/// 002 Eq. 10: F = 4/3 E_e sqrt(R_e) delta^3/2 f2^-3/2 (N).
double beckerHertzForce(double effectiveModulus, const BeckerFactors& f, double overlap);

/// E* = ((1 - nuA^2)/EA + (1 - nuB^2)/EB)^-1 (Pa), 004 after Eq. 2.
double effectiveModulus(double youngsA, double poissonA, double youngsB, double poissonB);
/// G* = ((2 - nuA)/GA + (2 - nuB)/GB)^-1 with G = E / (2 (1 + nu)) (Pa), 004 after Eq. 61 and
/// 001 Eq. 15: the shear modulus of the Mindlin tangential stiffness 8 G* a.
double effectiveShearModulus(double youngsA, double poissonA, double youngsB, double poissonB);

}  // namespace sqdem
