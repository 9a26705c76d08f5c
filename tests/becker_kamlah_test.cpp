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

// Becker-Kamlah with surface_energy (becker_kamlah.hpp: JKR on the law's elastic contact,
// Thornton-Ning style), on an ellipsoid pair's tip contact (Ri/Rj = 0.4) loaded to 20 delta_Y,
// unloaded and pulled apart:
//  - as W -> 0 it is Becker-Kamlah (W = 1e-12 J/m^2: within 1e-5 of the largest force);
//  - the force is continuous along the whole path, at first yield and at the turning point;
//  - the most tensile force on retraction is the JKR pull-off 3/2 pi W R of the flattened
//    contact's Hertz sphere R = R_e,pmax f2^-3, larger than the undeformed contact's;
//  - a contact loaded below yield pulls off at 3/2 pi W R_e f2^-3 (classical JKR).
TEST(BeckerKamlahAdhesive, ThorntonNingStyleJkrOnTheElasticContact) {
  const double E = 1e9, Y = 1e7, gamma = 0.05;
  RelativeRadii r;
  r.Ri = 4e-6;
  r.Rj = 1e-5;
  r.Rc = r.Ri * r.Rj / (r.Ri + r.Rj);
  const NormalContact contact{.radii = r, .factors = hertzFactors(r.ratio(), EccentricityMethod::Exact), .effectiveModulus = E};
  const BeckerKamlahParameters p{.yieldStrength = Y, .lambdaMax = 3.0, .epsilonMax = 10.0};
  const BeckerFactors g = beckerFactors(r);
  const BeckerKamlah plain(g, BeckerKamlahLaw{p}.at(contact, g));
  const double top = 20.0 * plain.yieldOverlap(), detach = 0.05 * top;
  std::vector<double> path;
  for (int k = 0; k <= 2000; ++k) path.push_back(-detach + (top + detach) * k / 2000.0);
  for (int k = 1; k <= 4000; ++k) path.push_back(top - (top + 2.0 * top) * k / 4000.0);
  const auto run = [&](const BeckerKamlahLaw& law, std::vector<double>& forces) {
    BeckerKamlahLaw::History h;
    for (double d : path) {
      const NormalResponse resp = law.force(contact, d, h);
      forces.push_back(resp.acting ? resp.force : 0.0);
    }
  };
  std::vector<double> reference, tiny, adhesive;
  run(BeckerKamlahLaw{p}, reference);
  run(BeckerKamlahLaw{p, 1e-12}, tiny);
  run(BeckerKamlahLaw{p, gamma}, adhesive);
  double largest = 0.0, worst = 0.0, tensile = 0.0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    largest = std::max(largest, std::abs(reference[k]));
    worst = std::max(worst, std::abs(tiny[k] - reference[k]));
    tensile = std::min(tensile, adhesive[k]);
  }
  // Continuity at first yield (loading) and at the turning point (loading -> unloading).
  const BeckerKamlahLaw law{p, gamma};
  const auto forceAt = [&](std::initializer_list<double> history) {
    BeckerKamlahLaw::History h;
    double f = 0.0;
    for (double d : history) f = law.force(contact, d, h).force;
    return f;
  };
  const double dY = plain.yieldOverlap();
  const double jump = std::max(std::abs(forceAt({0.0, dY * (1.0 - 1e-10)}) - forceAt({0.0, dY * (1.0 + 1e-10)})),
                               std::abs(forceAt({0.0, top}) - forceAt({0.0, top, top * (1.0 - 1e-12)})));
  const BeckerKamlahDent dent = plain.dentAfter(top);
  const double flattened = 1.5 * std::numbers::pi * 2.0 * gamma * plain.hertzSphereRadius(dent.radius);
  const double undeformed = 1.5 * std::numbers::pi * 2.0 * gamma * plain.hertzSphereRadius(g.Re);
  std::printf("W -> 0: %.2g of the largest force; jump at yield or at the turning point %.2g of it; pull-off %.6e N "
              "(JKR on the flattened contact %.6e N, undeformed %.6e N)\n",
              worst / largest, jump / largest, -tensile, flattened, undeformed);
  EXPECT_LT(worst, 1e-5 * largest);
  EXPECT_LT(jump, 1e-8 * largest);
  EXPECT_NEAR(-tensile, flattened, 1e-3 * flattened);
  EXPECT_GT(flattened, undeformed);

  BeckerKamlahLaw::History h;
  law.force(contact, 0.0, h);  // touch, then load below yield and pull apart
  const double below = 0.5 * dY;
  double elasticPullOff = 0.0;
  for (int k = 0; k <= 4000; ++k) {
    const NormalResponse resp = law.force(contact, below - (below + detach) * k / 4000.0, h);
    if (resp.acting) elasticPullOff = std::max(elasticPullOff, -resp.force);
  }
  EXPECT_NEAR(elasticPullOff, undeformed, 1e-3 * undeformed);
}

}  // namespace
}  // namespace sqdem
