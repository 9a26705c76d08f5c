// Jamari elastic-plastic elliptic contact, loading curve (004 Eqs. 41-46), and the elastic
// unloading chosen in jamari.hpp.
#include <gtest/gtest.h>

#include "sqdem/mechanics/jamari.hpp"

#include <cmath>
#include <numbers>

namespace sqdem {
namespace {

/// Relative radii Rj = 10 um and Ri = ratio Rj.
RelativeRadii radiiOfRatio(double ratio) {
  RelativeRadii r;
  r.Rj = 1e-5;
  r.Ri = ratio * r.Rj;
  r.Rc = r.Ri * r.Rj / (r.Ri + r.Rj);
  return r;
}

// Continuity at delta_1 and delta_2 (relative jump < 1e-9) and monotone loading, for a circular
// and an elongated contact. Parameters: K_v = 0.454 + 0.41 nu (000 after Eq. 33), c_h = 1,
// c_A = 220, i.e. delta_2/delta_1 = 110 for a circular contact (Eq. 44 gives c_A/2 there).
TEST(Jamari, LoadingCurveIsContinuousAndMonotone) {
  for (double ratio : {1.0, 0.2}) {
    const RelativeRadii r = radiiOfRatio(ratio);
    const HertzFactors h = hertzFactors(ratio, EccentricityMethod::Exact);
    const JamariElasticPlastic law(r, h, {1e11, 2e9, 0.454 + 0.41 * 0.3, 1.0, 220.0});
    for (double boundary : {law.yieldOverlap(), law.fullyPlasticOverlap()}) {
      const double below = law.loadingForce(boundary * (1 - 1e-13)), above = law.loadingForce(boundary * (1 + 1e-13));
      EXPECT_NEAR(below, above, 1e-9 * above) << ratio;
    }
    double previous = 0;
    for (int i = 1; i <= 1000; ++i) {
      const double f = law.loadingForce(1.2 * law.fullyPlasticOverlap() * i / 1000);
      EXPECT_GT(f, previous) << ratio << " " << i;
      previous = f;
    }
  }
}

// The unloading of jamari.hpp: continuous with the loading curve at the largest overlap, carrying
// there both F_m and the area A_m; below first yield it retraces the elastic loading curve (no
// residual overlap); past it a residual overlap delta_p > 0 remains and the unloading follows
// F_m ((delta - delta_p)/delta_e)^3/2 with A proportional to delta - delta_p (004 Eqs. 1-2).
TEST(Jamari, UnloadingIsTheElasticRecoveryOfTheLoadedContact) {
  const double ratio = 0.2;
  const RelativeRadii r = radiiOfRatio(ratio);
  const HertzFactors h = hertzFactors(ratio, EccentricityMethod::Exact);
  const JamariElasticPlastic law(r, h, {1e11, 2e9, 0.454 + 0.41 * 0.3, 1.0, 220.0});
  const double elastic = 0.5 * law.yieldOverlap();
  for (double d : {0.2, 0.6, 0.99}) {
    const auto p = law.at(d * elastic, elastic);
    EXPECT_NEAR(p.force, law.loadingForce(d * elastic), 1e-12 * law.loadingForce(elastic));
    EXPECT_NEAR(p.area, law.loadingArea(d * elastic), 1e-12 * law.loadingArea(elastic));
  }
  const double top = 10.0 * law.yieldOverlap();
  const double Fm = law.loadingForce(top), Am = law.loadingArea(top);
  const auto justBelow = law.at(top * (1.0 - 1e-12), top);
  EXPECT_NEAR(justBelow.force, Fm, 1e-9 * Fm);
  EXPECT_NEAR(justBelow.area, Am, 1e-9 * Am);
  // Residual overlap: the largest overlap with zero force.
  double lo = 0.0, hi = top;
  for (int k = 0; k < 200; ++k) (law.at(0.5 * (lo + hi), top).force > 0.0 ? hi : lo) = 0.5 * (lo + hi);
  const double residual = lo, elasticPart = top - residual;
  EXPECT_GT(residual, 0.0);
  // delta_e from 004 Eqs. 1-2: the Hertz contact carrying F_m over A_m.
  EXPECT_NEAR(elasticPart, 3.0 * Fm / (4.0 * 1e11 * h.gamma * std::sqrt(Am / (std::numbers::pi * h.beta))), 1e-9 * top);
  const auto half = law.at(residual + 0.5 * elasticPart, top);
  EXPECT_NEAR(half.force, Fm * std::pow(0.5, 1.5), 1e-9 * Fm);
  EXPECT_NEAR(half.area, 0.5 * Am, 1e-9 * Am);
  std::printf("loaded to 10 delta_1: residual overlap %.4f of the largest\n", residual / top);
}

}  // namespace
}  // namespace sqdem
