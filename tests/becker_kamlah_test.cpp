// Becker & Kamlah ellipsoid elasto-plastic law (002 Eqs. 1-54) on the 002 Table 3-4 cases.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sqdem/mechanics/becker_kamlah.hpp"
#include "sqdem/validation/becker_cases.hpp"

namespace sqdem {
namespace {

BeckerFactors sphereFactors(double effectiveRadius) {
  RelativeRadii r;
  r.Ri = r.Rj = effectiveRadius;
  r.Rc = 0.5 * effectiveRadius;
  return beckerFactors(r);
}

BeckerKamlahParameters nmc(const BeckerFactors& f, double meanRadiusSum, bool transition = true) {
  BeckerCaseGeometry g;
  g.factors = f;
  g.meanRadiusSum = meanRadiusSum;
  return nmcBeckerKamlahParameters(g, transition);
}

// Below yield the law is Hertz: for spheres F = 4/3 E* sqrt(R*) delta^3/2 (002 Eq. 10, f = 1).
TEST(BeckerKamlah, SpheresBelowYieldAreHertz) {
  const double R = 2.3e-6;
  const BeckerKamlah law(sphereFactors(R), nmc(sphereFactors(R), 4 * R));
  const double E = effectiveModulus(nmcYoungsModulus, nmcPoissonRatio, nmcYoungsModulus, nmcPoissonRatio);
  BeckerKamlahHistory h;
  for (double f : {0.1, 0.5, 0.99}) {
    const double d = f * law.yieldOverlap();
    EXPECT_NEAR(law.evaluate(d, h).force, 4.0 / 3.0 * E * std::sqrt(R) * std::pow(d, 1.5), 1e-12 * law.yieldForce());
  }
  // p_0 = 1.6 Y exactly at delta_Y (002 Eq. 2): p_0 = 3 F / (2 pi c^2) for a circular contact.
  const double c2 = R * law.yieldOverlap();
  EXPECT_NEAR(3 * law.yieldForce() / (2 * std::numbers::pi * c2), 1.6 * nmcYieldStrength, 1e-9 * nmcYieldStrength);
}

// Continuity of the loading curve at delta_Y and delta_max (relative jump < 1e-9), and Eq. 35:
// the elastic - fully plastic slope pi R_e f1^2/f2 p_Y equals the Hertz slope at delta_Y.
TEST(BeckerKamlah, LoadingCurveIsContinuousAtRegimeBoundaries) {
  for (const auto& c : beckerValidationCases) {
    const BeckerCaseGeometry g = beckerCaseGeometry(c);
    for (bool transition : {true, false}) {
      const BeckerKamlah law(g.factors, nmcBeckerKamlahParameters(g, transition));
      for (double boundary : {law.yieldOverlap(), law.plasticLimitOverlap()}) {
        const double below = law.loadingForce(boundary * (1 - 1e-12)), above = law.loadingForce(boundary * (1 + 1e-12));
        EXPECT_NEAR(below, above, 1e-9 * above) << c.table;
      }
    }
    const BeckerKamlah efp(g.factors, nmcBeckerKamlahParameters(g, false));
    const double dY = efp.yieldOverlap(), h = 1e-6 * dY;
    const double hertzSlope = (efp.loadingForce(dY) - efp.loadingForce(dY - h)) / h;
    const double plasticSlope = (efp.loadingForce(dY + h) - efp.loadingForce(dY)) / h;
    EXPECT_NEAR(plasticSlope, hertzSlope, 1e-4 * hertzSlope) << c.table;
  }
}

// Load - unload - reload cycles: force continuous at every turning point, zero below delta_p,
// reloading retraces the unloading curve and rejoins the loading curve at delta_*.
TEST(BeckerKamlah, UnloadingAndReloadingKeepForceContinuous) {
  for (const auto& c : beckerValidationCases) {
    const BeckerCaseGeometry g = beckerCaseGeometry(c);
    for (bool transition : {true, false}) {
      const BeckerKamlah law(g.factors, nmcBeckerKamlahParameters(g, transition));
      BeckerKamlahHistory h;
      const double peak = c.peaks[0] * g.meanRadiusSum;
      const BeckerKamlahState atPeak = law.evaluate(peak, h);
      const BeckerKamlahState justAfter = law.evaluate(peak * (1 - 1e-12), h);
      EXPECT_NEAR(justAfter.force, atPeak.force, 1e-9 * atPeak.force) << c.table;
      EXPECT_EQ(justAfter.regime, PlasticRegime::Unloading);
      const double dp = justAfter.plasticOverlap;
      EXPECT_GT(dp, 0.0);
      EXPECT_LT(dp, peak);
      EXPECT_NEAR(law.evaluate(dp * (1 + 1e-12), h).force, 0.0, 1e-9 * atPeak.force);
      EXPECT_EQ(law.evaluate(0.5 * dp, h).force, 0.0);
      const double midUnload = law.evaluate(0.5 * (dp + peak), h).force;
      EXPECT_GT(midUnload, 0.0);
      EXPECT_LT(midUnload, law.loadingForce(0.5 * (dp + peak)));  // unloading lies below loading
      // reload: same curve back to the peak, then the loading curve beyond it
      EXPECT_DOUBLE_EQ(law.evaluate(0.5 * (dp + peak), h).force, midUnload);
      EXPECT_NEAR(law.evaluate(peak, h).force, atPeak.force, 1e-9 * atPeak.force);
      EXPECT_NEAR(law.evaluate(peak * 1.001, h).force, law.loadingForce(peak * 1.001), 1e-12 * atPeak.force);
      EXPECT_DOUBLE_EQ(h.maxOverlap, peak * 1.001);
    }
  }
}

// 002 Fig. 15: the elastic - fully plastic law lies below the full law past delta_Y; 002 Fig. 13:
// the sphere of the same mean radius lies above the ellipsoid (same normalisation delta_Y, F_pY).
TEST(BeckerKamlahValidation, OrderingOfFigures13And15) {
  const auto& c1 = beckerValidationCases[0];
  const BeckerCaseGeometry g = beckerCaseGeometry(c1);
  const BeckerKamlah ellipsoid(g.factors, nmcBeckerKamlahParameters(g, true));
  const BeckerFactors sphere = sphereFactors(0.5 * c1.meanRadius);
  const BeckerKamlah spheres(sphere, nmc(sphere, g.meanRadiusSum));
  const BeckerKamlah efp(g.factors, nmcBeckerKamlahParameters(g, false));
  for (double f = 0.002; f <= 0.13; f += 0.002) {
    const double d = f * g.meanRadiusSum;
    EXPECT_GT(spheres.loadingForce(d), ellipsoid.loadingForce(d)) << f;
    if (d > 1.01 * ellipsoid.yieldOverlap()) EXPECT_LT(efp.loadingForce(d), ellipsoid.loadingForce(d)) << f;
  }
}

// 002 Section 5 quotes e = 0.65 (Table 3 case) and e_max = 2.94, delta_max/delta_Y = 8.65 (Table 4
// case). With the contact at the x tips and Eq. 54, sqdem reports what it gets; the deviation is
// printed (the seed does not say which axes meet; see the issue note).
TEST(BeckerKamlahValidation, ReportsPaperQuotedParameters) {
  const BeckerCaseGeometry g3 = beckerCaseGeometry(beckerValidationCases[0]);
  const double e = std::sqrt(1 - std::pow(g3.factors.A / g3.factors.B, 4.0 / 3.0));  // 002 Eq. 7
  const BeckerCaseGeometry g4 = beckerCaseGeometry(beckerValidationCases[1]);
  const BeckerKamlahParameters p4 = nmcBeckerKamlahParameters(g4, true);
  std::printf("Table 3 case: e = %.3f (paper 0.65); Table 4 case: e_max = %.3f (paper 2.94), "
              "delta_max/delta_Y = %.2f (paper 8.65), R_e/r_IJ = %.4f\n",
              e, p4.epsilonMax, p4.epsilonMax * p4.epsilonMax, g4.factors.Re / g4.meanRadiusSum);
  // The Table 4 geometry is symmetric enough to check R_e by hand: I = 1:1:0.8, J = 1:1.25:1.25.
  const double aI = 10e-6 / std::cbrt(0.8), aJ = 10e-6 / std::cbrt(1.5625);
  const double kIy = 1 / aI, kIz = aI / std::pow(0.8 * aI, 2), kJ = aJ / std::pow(1.25 * aJ, 2);
  const double A = 0.25 * (kIy + kIz + 2 * kJ) - 0.25 * (kIz - kIy), B = A + 0.5 * (kIz - kIy);
  EXPECT_NEAR(g4.factors.Re, 0.5 / std::sqrt(A * B), 1e-6 * g4.factors.Re);
  EXPECT_GT(p4.epsilonMax, 1.0);
}

}  // namespace
}  // namespace sqdem
