// Elliptic Cattaneo-Mindlin-Deresiewicz tangential law (004 Eqs. 56-69).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sqdem/mechanics/mindlin_deresiewicz.hpp"

namespace sqdem {
namespace {

// e -> 0: Phi = 1 and the no-slip stiffness is Mindlin's 8 G* a for every direction.
TEST(MindlinDeresiewicz, CircularLimitIsMindlinStiffness) {
  for (double theta : {0.0, 0.7, std::numbers::pi / 2}) {
    const MindlinDeresiewicz md(3e9, 2e-6, 0.0, 0.3, theta, 0.4, 1e-3);
    EXPECT_NEAR(md.phi(), 1.0, 1e-14);
    EXPECT_NEAR(md.noSlipStiffness(), 8 * 3e9 * 2e-6, 1e-9 * 8 * 3e9 * 2e-6);
    const MindlinDeresiewicz nearly(3e9, 2e-6, 1e-8, 0.3, theta, 0.4, 1e-3);
    EXPECT_NEAR(nearly.noSlipStiffness() / md.noSlipStiffness(), 1.0, 1e-7);
  }
}

// Eq. 61: Phi at theta = 0 and pi/2 from K and D; an elongated contact is stiffer across its
// major axis than along it (Mindlin) and initial slope of Eq. 59 equals k_t.
TEST(MindlinDeresiewicz, EllipticPhiAndInitialSlope) {
  const double nu = 0.25, e2 = 0.8;
  const MindlinDeresiewicz along(3e9, 2e-6, e2, nu, 0.0, 0.4, 1e-3);
  const MindlinDeresiewicz across(3e9, 2e-6, e2, nu, std::numbers::pi / 2, 0.4, 1e-3);
  EXPECT_GT(along.phi(), 0.0);
  EXPECT_NE(along.phi(), across.phi());
  MindlinDeresiewiczHistory history;
  const double tiny = 1e-9 * along.slipDisplacement();
  EXPECT_NEAR(along.force(tiny, history) / tiny, along.noSlipStiffness(), 1e-6 * along.noSlipStiffness());
}

// Full slip at delta_L (Eq. 62) and Coulomb limit beyond it.
TEST(MindlinDeresiewicz, SlipsAtCoulombLimit) {
  const MindlinDeresiewicz md(3e9, 2e-6, 0.5, 0.3, 0.3, 0.4, 1e-3);
  MindlinDeresiewiczHistory h;
  EXPECT_NEAR(md.force(md.slipDisplacement(), h), 0.4e-3, 1e-15);
  EXPECT_NEAR(md.force(3 * md.slipDisplacement(), h), 0.4e-3, 1e-15);
}

// Hysteresis: cycling between -F* and +F* closes the loop (continuous at the turning points)
// and the enclosed area equals Eq. 69 (circular and elliptic, F* = 0.3..0.9 mu F_n).
TEST(MindlinDeresiewicz, DissipationPerCycleMatchesEq69) {
  for (double e2 : {0.0, 0.6}) {
    for (double ratio : {0.3, 0.6, 0.9}) {
      const MindlinDeresiewicz md(3e9, 2e-6, e2, 0.3, 0.0, 0.4, 1e-3);
      const double limit = 0.4e-3, dL = md.slipDisplacement();
      const double amplitude = dL * (1 - std::pow(1 - ratio, 2.0 / 3.0));  // virgin curve reaches F*
      MindlinDeresiewiczHistory h;
      const int n = 20000;
      for (int i = 0; i <= n; ++i) md.force(amplitude * i / n, h);
      EXPECT_NEAR(h.force, ratio * limit, 1e-12);
      double work = 0, previous = h.force, x = amplitude;
      for (int cycle = 0; cycle < 2; ++cycle) {
        for (int sign : {-1, 1}) {
          for (int i = 1; i <= 2 * n; ++i) {
            const double xi = -sign * amplitude + sign * 2 * amplitude * i / (2 * n);
            const double f = md.force(xi, h);
            if (cycle == 1) work += 0.5 * (f + previous) * (xi - x);
            previous = f;
            x = xi;
          }
          EXPECT_NEAR(h.force, sign * ratio * limit, 1e-9 * limit);  // loop closes at +-F*
        }
      }
      EXPECT_NEAR(work, md.dissipationPerCycle(ratio * limit), 1e-4 * md.dissipationPerCycle(ratio * limit))
          << "e2 " << e2 << " F*/muFn " << ratio;
    }
  }
}

TEST(MindlinDeresiewicz, ContactSemiMajorAxis) {
  EXPECT_NEAR(contactSemiMajorAxis(std::numbers::pi * 4e-12, 0.0), 2e-6, 1e-18);
  EXPECT_THROW(MindlinDeresiewicz(3e9, 2e-6, 1.0, 0.3, 0.0, 0.4, 1e-3), std::invalid_argument);
}

}  // namespace
}  // namespace sqdem
