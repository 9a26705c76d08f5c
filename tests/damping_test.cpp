// Normal damping (000 Eqs. 24-26, 001 Eqs. 11-13, 004 Eqs. 37-38).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sqdem/mechanics/damping.hpp"
#include "support/collision.hpp"

namespace sqdem {
namespace {

using testing::restitutionOf;

// A linear spring with 000 Eq. 24 damping and zeta from Eq. 26 restores e exactly (closed form
// of the damped oscillator: e = exp(-pi zeta / sqrt(1 - zeta^2))).
TEST(Damping, LinearSpringReproducesThePrescribedRestitution) {
  const double m = 1e-9, k = 1e3;
  const double period = 2 * std::numbers::pi * std::sqrt(m / k);
  for (double e : {0.1, 0.5, 0.9, 1.0}) {
    const double zeta = restitutionDampingRatio(e);
    const auto force = [&](double x, double rate) { return k * x + linearDampingForce(zeta, m, k, rate); };
    EXPECT_NEAR(restitutionOf(force, m, 0.3, period / 20000), e, 2e-4) << e;
  }
}

// Hertz with 001 Eq. 11 damping: e is independent of the impact velocity (both terms scale with
// the same power of the overlap) and close to the prescribed value (Tsuji's fit).
TEST(Damping, HertzDampingGivesVelocityIndependentRestitution) {
  const double m = 1e-12, E = 1e9, R = 1e-5;
  for (double e : {0.3, 0.6, 0.9}) {
    const double zeta = restitutionDampingRatio(e);
    const auto force = [&](double x, double rate) {
      return 4.0 / 3.0 * E * std::sqrt(R) * std::pow(std::max(x, 0.0), 1.5) +
             hertzDampingForce(zeta, m, E, R, x, rate);
    };
    const double slow = restitutionOf(force, m, 0.01, 1e-11);
    const double fast = restitutionOf(force, m, 1.0, 1e-12);
    EXPECT_NEAR(slow, fast, 2e-3) << e;
    std::printf("Hertz + 001 Eq. 11 damping: prescribed e = %.2f, obtained %.4f (v = 0.01 m/s), %.4f (v = 1 m/s)\n",
                e, slow, fast);
    EXPECT_NEAR(fast, e, 0.1 * (1 - e) + 0.02) << e;  // Tsuji's damping is approximate
  }
  EXPECT_THROW(restitutionDampingRatio(0.0), std::invalid_argument);
}

// 004 Eq. 38: viscoelastic spheres have 1 - e growing as v^(1/5) for weak dissipation
// (Brilliantov et al.); fitted exponent from two velocities a decade apart.
TEST(Damping, ViscoelasticRestitutionFollowsTheOneFifthLaw) {
  const double m = 1e-12, E = 1e9, Rc = 5e-6, gamma = std::numbers::sqrt2, A = 1e-10;
  const auto force = [&](double x, double rate) {
    const double elastic = 4.0 / 3.0 * E * std::sqrt(Rc) * std::pow(std::max(x, 0.0), 1.5) * gamma;
    return elastic + viscoelasticDampingForce(A, E, Rc, gamma, x, rate);
  };
  const double loss1 = 1 - restitutionOf(force, m, 0.01, 2e-11);
  const double loss2 = 1 - restitutionOf(force, m, 0.1, 1e-11);
  ASSERT_GT(loss1, 0.0);
  ASSERT_LT(loss2, 0.2);
  EXPECT_NEAR(std::log10(loss2 / loss1), 0.2, 0.02);
  EXPECT_GT(viscoelasticConstant(1.0, 2.0, 1e9, 0.3), 0.0);
}

}  // namespace
}  // namespace sqdem
