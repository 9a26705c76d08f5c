// Haervig et al. simplified JKR, tangential cap, rolling resistance and reduced stiffness (001).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/mechanics/haervig.hpp"

namespace sqdem {
namespace {

using std::numbers::pi;

// Separation energy int_0^delta_0 F d(delta) (001 Eq. 23) by quadrature in delta.
double separationEnergy(const HaervigJkr& jkr, double R) {
  const double a0 = jkr.equilibriumContactRadius(), delta0 = a0 * a0 / (3 * R);
  const int n = 200000;
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += jkr.normalForce((i + 0.5) * delta0 / n);
  return sum * delta0 / n;
}

// Eq. 7 and the equilibrium overlap delta_0 = a_0^2/(3R) (after Eq. 23): F(delta_0) = 0.
TEST(Haervig, EquilibriumContact) {
  const double E = 1e9, gamma = 0.1, R = 1e-6;
  const HaervigJkr jkr(E, gamma, R);
  const double a0 = jkr.equilibriumContactRadius();
  EXPECT_NEAR(jkr.contactRadius(a0 * a0 / (3 * R)), a0, 1e-12 * a0);
  EXPECT_NEAR(jkr.normalForce(a0 * a0 / (3 * R)), 0.0, 1e-10 * jkr.criticalForce());
  // zero overlap: a = (4 pi gamma R^2/E)^1/3 (Eq. A.5), F = -8/9 F_C (001 Section 2.1)
  EXPECT_NEAR(jkr.contactRadius(0.0), std::cbrt(4 * pi * gamma * R * R / E), 1e-12 * a0);
  EXPECT_NEAR(jkr.normalForce(0.0), -8.0 / 9.0 * jkr.criticalForce(), 1e-10 * jkr.criticalForce());
  EXPECT_EQ(jkr.normalForce(-1e-12), 0.0);
}

// 001 Eq. 24 / A.11: the separation energy is unchanged when E -> E/10, E/100 with
// gamma_mod = gamma (E_mod/E)^2/5; without the rule it is not.
TEST(Haervig, ReducedStiffnessRuleKeepsTheSeparationEnergy) {
  const double E = 10e9, gamma = 0.1, R = 1e-6;
  const double reference = separationEnergy(HaervigJkr(E, gamma, R), R);
  for (double factor : {10.0, 100.0}) {
    const double Emod = E / factor;
    const double modified = separationEnergy(HaervigJkr(Emod, reducedStiffnessSurfaceEnergy(gamma, E, Emod), R), R);
    EXPECT_NEAR(modified, reference, 1e-6 * std::abs(reference)) << factor;
    const double unmodified = separationEnergy(HaervigJkr(Emod, gamma, R), R);
    EXPECT_GT(std::abs(unmodified / reference - 1), 0.5) << factor;
  }
}

// Eq. 17: the tangential force never exceeds mu |F_N + 2 F_C|, and after sliding the spring is
// consistent with the capped force; below the cap F_t = -S_t s (Eq. 14).
TEST(Haervig, TangentialForceIsCappedByAdhesiveCoulombLimit) {
  const HaervigTangential t{effectiveShearModulus(1e9, 0.3, 1e9, 0.3), 1e-6, 1e-12, 0.0, 0.3};
  const double overlap = 1e-9, normal = -2e-7, critical = 1e-6;
  Vec3 spring = Vec3::Zero();
  const Vec3 small = t.force(spring, Vec3(1e-12, 0, 0), Vec3::Zero(), overlap, normal, critical);
  EXPECT_NEAR(small.x(), -8 * t.shearModulus * std::sqrt(t.radius * overlap) * 1e-12, 1e-20);
  const Vec3 big = t.force(spring, Vec3(1e-6, 1e-6, 0), Vec3::Zero(), overlap, normal, critical);
  EXPECT_NEAR(big.norm(), 0.3 * std::abs(normal + 2 * critical), 1e-15);
  const Vec3 again = t.force(spring, Vec3::Zero(), Vec3::Zero(), overlap, normal, critical);
  EXPECT_NEAR((again - big).norm(), 0.0, 1e-15);
}

// Eqs. 21-22: linear up to xi_crit, then constant; xi is truncated in place.
TEST(Haervig, RollingTorqueSaturatesAtCriticalDistance) {
  const HaervigRolling r{1e-6, 1e-9};
  double xi = 0.5e-9;
  EXPECT_NEAR(r.torque(xi, 1.0), 4e-6 * 0.5e-9, 1e-25);
  xi = 3e-9;
  EXPECT_NEAR(r.torque(xi, 1.0), 4e-6 * 1e-9, 1e-25);
  EXPECT_DOUBLE_EQ(xi, 1e-9);
  xi = -3e-9;
  EXPECT_NEAR(r.torque(xi, 0.25), -4e-6 * 0.125 * 1e-9, 1e-25);
}

}  // namespace
}  // namespace sqdem
