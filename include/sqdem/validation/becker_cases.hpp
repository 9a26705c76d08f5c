#pragma once
// The two validation cases of Becker & Kamlah (002 Section 5, Tables 3-4) with the NMC material
// of 002 Table 1: two ellipsoids with given aspect ratios a:b:c and mean radius r_k = (a b c)^1/3,
// aligned, touching at their x tips ("compressed in x-direction"); displacement-driven to peak
// overlaps given as fractions of r_IJ = r_I + r_J (Eq. 50), unloaded in between.

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
