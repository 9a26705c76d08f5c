// Jamari elastic-plastic elliptic contact, loading curve (004 Eqs. 41-46).
#include <gtest/gtest.h>

#include "sqdem/mechanics/jamari.hpp"

namespace sqdem {
namespace {

// Continuity at delta_1 and delta_2 (relative jump < 1e-9) and monotone loading, for a circular
// and an elongated contact. Parameters: K_v = 0.454 + 0.41 nu (000 after Eq. 33), c_h = 1,
// c_A = 220, i.e. delta_2/delta_1 = 110 for a circular contact (Eq. 44 gives c_A/2 there).
TEST(Jamari, LoadingCurveIsContinuousAndMonotone) {
  for (double ratio : {1.0, 0.2}) {
    RelativeRadii r;
    r.Rj = 1e-5;
    r.Ri = ratio * r.Rj;
    r.Rc = r.Ri * r.Rj / (r.Ri + r.Rj);
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

}  // namespace
}  // namespace sqdem
