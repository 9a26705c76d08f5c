#pragma once
// The two validation cases of Becker & Kamlah (002 Section 5, Tables 3-4) with the NMC material
// of 002 Table 1: two ellipsoids with given aspect ratios a:b:c and mean radius r_k = (a b c)^1/3,
// aligned, touching at their x tips ("compressed in x-direction"); displacement-driven to peak
// overlaps given as fractions of r_IJ = r_I + r_J (Eq. 50), unloaded in between.
//
// The paper quotes e = 0.65 for the Table 3 case and epsilon_max = 2.94 (delta_max/delta_Y = 8.65)
// for the Table 4 case. With the x tips in contact (the text's "compressed in x-direction", a
// along x) this geometry gives e = 0.806 and epsilon_max = 2.787 (7.77). Trying every pairing
// of tips and tangent alignments of the two ellipsoids: Table 3's e = 0.65 matches only the
// y tips with aligned axes (e = 0.652, but then epsilon_max = 2.27), and no pairing gives
// epsilon_max = 2.94 for Table 4 (closest 2.907, x tip against z tip). The quoted values are
// therefore not consistent with one stated geometry; the literal x-tip reading is used.

#include <array>

#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/mechanics/becker_kamlah.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

/// 002 Table 1 (NMC).
inline constexpr double nmcYoungsModulus = 142e9;  // Pa
inline constexpr double nmcPoissonRatio = 0.25;
inline constexpr double nmcDensity = 4750.0;       // kg/m^3
inline constexpr double nmcYieldStrength = 7.9e9;  // Pa

struct BeckerValidationCase {
  int table;                       ///< 002 table number
  std::array<double, 3> ratiosI;   ///< a:b:c of particle I
  std::array<double, 3> ratiosJ;   ///< a:b:c of particle J
  double meanRadius;               ///< r_I = r_J (m)
  std::array<double, 2> peaks;     ///< peak overlaps / r_IJ of the two load cycles
};

inline constexpr std::array<BeckerValidationCase, 2> beckerValidationCases{{
    {3, {1.0, 1.25, 1.5}, {1.0, 0.5, 0.8}, 4.675e-6, {0.045, 0.10}},
    {4, {1.0, 1.0, 0.8}, {1.0, 1.25, 1.25}, 10.0e-6, {0.10, 0.13}},
}};

/// The ellipsoid with these aspect ratios and (a b c)^1/3 = meanRadius.
Superquadric ellipsoidWithMeanRadius(const std::array<double, 3>& ratios, double meanRadius);

struct BeckerCaseGeometry {
  RelativeRadii radii;   ///< from the detector's curvatures at the x tips (no cap in effect)
  BeckerFactors factors; ///< 002 Eqs. 4-6
  double meanRadiusSum;  ///< r_IJ (m)
};
BeckerCaseGeometry beckerCaseGeometry(const BeckerValidationCase& c);

/// NMC parameters with the Eq. 54 fits for this geometry.
BeckerKamlahParameters nmcBeckerKamlahParameters(const BeckerCaseGeometry& g, bool transition);

}  // namespace sqdem
