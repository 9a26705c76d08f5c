// Nan et al. linear elasto-plastic adhesive law and critical sticking velocity (000).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/dynamics/rayleigh_time.hpp"
#include "sqdem/mechanics/nan_adhesive.hpp"
#include "sqdem/mechanics/sticking_velocity.hpp"

namespace sqdem {
namespace {

using std::numbers::pi;

// 000 Table 5: ammonium fluorescein particle on a silicon wall.
StickingVelocityInput table5(double radius, double yieldPressure) {
  return {radius, 1350.0, 1.2e9, 0.33, 166e9, 0.28, 0.24, yieldPressure};
}

NanParameters table5Law(double yieldPressure) {
  NanParameters p;
  p.effectiveModulus = effectiveModulus(1.2e9, 0.33, 166e9, 0.28);
  p.effectiveRadius = 2.45e-6;
  p.workOfAdhesion = 0.24;
  p.yieldPressure = yieldPressure;
  return p;
}

// Work under the force-overlap line from alpha = 0 on the loading line to detachment equals
// W_JKR (000 Eq. 35 / A1 corrected): checks k_cl from Eqs. 36-38 numerically.
TEST(NanAdhesive, SeparationWorkBeforeYieldIsJkr) {
  const NanAdhesivePlastic law(table5Law(200e6));
  NanHistory h;
  const double top = 0.9 * law.yieldOverlap();
  const int n = 200000;
  for (int i = 0; i <= n; ++i) law.evaluate(top * i / n, h);  // load below yield
  ASSERT_EQ(h.maxOverlap, 0.0);
  double work = 0, previousForce = law.evaluate(0.0, h).force, alpha = 0.0;
  const double step = 1e-5 * law.alpha0();
  while (h.attached) {
    alpha -= step;
    const double f = law.evaluate(alpha, h).force;
    if (h.attached) work += -0.5 * (f + previousForce) * step;
    previousForce = f;
  }
  EXPECT_NEAR(work, law.separationWork(), 2e-4 * law.separationWork());
  // the printed closed form of Eq. 38 (for k_el/k_cl) with its rounded constants
  const NanParameters p = table5Law(200e6);
  const double eq38 = 0.92 * law.kEl() / std::cbrt(p.workOfAdhesion * std::pow(p.effectiveModulus * p.effectiveRadius, 2)) - 0.3;
  EXPECT_NEAR(law.kEl() / law.kCl(), eq38, 0.01 * eq38);
}

// Every branch of 000 Fig. 1/2: loading, yield, unloading with k_e(alpha_max), pull-off at
// alpha_cp with -f_cp, detachment at alpha_jp with -5/9 f_cp, reloading from alpha_c0 with
// -8/9 f_cp; force continuous wherever the figure's lines meet.
TEST(NanAdhesive, LoopVisitsEveryBranchContinuously) {
  const NanAdhesivePlastic law(table5Law(30e6));
  NanHistory h;
  EXPECT_EQ(law.evaluate(-1e-9, h).branch, NanBranch::Detached);
  const NanState snap = law.evaluate(0.0, h);
  EXPECT_NEAR(snap.force, -law.snapInForce(), 1e-12 * law.snapInForce());
  const double aY = law.yieldOverlap();
  EXPECT_NEAR(law.evaluate(aY, h).force, law.yieldForce(), 1e-9 * law.yieldForce());
  const double aMax = 5 * aY;
  const NanState peak = law.evaluate(aMax, h);
  EXPECT_EQ(peak.branch, NanBranch::Plastic);
  const NanUnloading u = law.unloadingFrom(aMax);
  EXPECT_NEAR(peak.force, u.fMax, 1e-12 * u.fMax);
  EXPECT_NEAR(u.kE, law.kEl() * std::sqrt(aMax / aY), 1e-9 * u.kE);
  EXPECT_GT(u.fCp, law.pullOffForceElastic());  // plastic flattening raises the pull-off (Eq. 59)
  const NanState unload = law.evaluate(aMax * (1 - 1e-12), h);
  EXPECT_EQ(unload.branch, NanBranch::Elastic);
  EXPECT_NEAR(unload.force, peak.force, 1e-9 * peak.force);
  const double fcp = law.evaluate(u.alphaCp, h).force;
  EXPECT_NEAR(fcp, -u.fCp, 1e-9 * u.fCp);
  EXPECT_NEAR(law.evaluate(u.alphaCp * (1 - 1e-12) - 1e-20, h).force, -u.fCp, 1e-9 * u.fCp);
  EXPECT_EQ(law.evaluate(u.alphaCp - 0.5 * (u.alphaCp - u.alphaJp), h).branch, NanBranch::Adhesive);
  EXPECT_NEAR(law.evaluate(u.alphaJp, h).force, -5.0 / 9.0 * u.fCp, 1e-9 * u.fCp);
  EXPECT_EQ(law.evaluate(u.alphaJp - 1e-15, h).branch, NanBranch::Detached);
  EXPECT_FALSE(h.attached);
  // reloading: nothing until alpha_c0, then -8/9 f_cp on the elastic line up to the old peak
  EXPECT_EQ(law.evaluate(u.alphaC0 - 1e-12, h).force, 0.0);
  EXPECT_NEAR(law.evaluate(u.alphaC0, h).force, -8.0 / 9.0 * u.fCp, 1e-9 * u.fCp);
  EXPECT_NEAR(law.evaluate(aMax, h).force, peak.force, 1e-9 * peak.force);
  EXPECT_EQ(law.evaluate(1.5 * aMax, h).branch, NanBranch::Plastic);
}

// Before yield the quantities reduce as 000 Section 2.1 states: alpha_p = alpha_0, f_cp = f_ce,
// alpha_c0 = 0 (Eq. 59 with k_e = k_el gives exactly 1).
TEST(NanAdhesive, ReducesToLinearJkrBeforeYield) {
  const NanAdhesivePlastic law(table5Law(30e6));
  const NanUnloading u = law.unloadingFrom(0.0);
  EXPECT_NEAR(u.alphaP, law.alpha0(), 1e-15);
  EXPECT_NEAR(u.fCp, law.pullOffForceElastic(), 1e-12 * u.fCp);
  EXPECT_NEAR(u.alphaC0, 0.0, 1e-12 * law.alpha0());
  // Eq. 28-29 vs Thornton-Ning Eqs. 30-31 with k_el = pi R* p_y: f_y = f_y0 sqrt(6/5)
  const NanParameters p = table5Law(30e6);
  const double fy0 = std::pow(pi, 3) * std::pow(p.effectiveRadius * p.yieldPressure, 2) * p.yieldPressure /
                     (6 * p.effectiveModulus * p.effectiveModulus);
  EXPECT_NEAR(law.yieldForce(), fy0 * std::sqrt(1.2), 1e-9 * fy0);
}

// 000 Eq. 73 closed form and Table 6 (Vs row; V_ys for p_y = 25 and 30 MPa, e_0 = 1). All eight
// V_ys entries follow from Eqs. 75, 78 and 79 to the table's printed digits once Eq. 75 keeps its
// sign in Eq. 79: for Table 5's particle f_y < f_0 (the contact yields at jump-in), and
// m V_y^2 / 2 = W_2 - W_1 < 0. Clipping V_y at 0 gave 3.0-4.3 % too much.
TEST(StickingVelocityValidation, Table6) {
  const std::array<double, 4> radii{3.445e-6, 2.45e-6, 1.72e-6, 1.29e-6};
  const std::array<double, 4> vs{0.49, 0.66, 0.88, 1.12};
  const std::array<double, 4> vys25{1.51, 2.25, 3.4, 4.76}, vys30{1.24, 1.86, 2.83, 3.96};
  for (int k = 0; k < 4; ++k) {
    const StickingVelocities v25 = stickingVelocities(table5(radii[k], 25e6));
    const StickingVelocities v30 = stickingVelocities(table5(radii[k], 30e6));
    const double E = effectiveModulus(1.2e9, 0.33, 166e9, 0.28);
    const double closed = 1.84 * std::pow(0.24 / radii[k], 5.0 / 6.0) / (std::sqrt(1350.0) * std::cbrt(E));
    EXPECT_NEAR(v25.Vs, closed, 2e-3 * closed);
    EXPECT_NEAR(v25.Vs, vs[k], 0.005 + 0.01 * vs[k]) << radii[k];
    std::printf("R = %.3f um: Vs %.3f (Table 6 %.2f); Vys(25 MPa) %.3f (%.2f, %+.1f %%); Vys(30 MPa) %.3f (%.2f, %+.1f %%)\n",
                radii[k] * 1e6, v25.Vs, vs[k], v25.Vys, vys25[k], 100 * (v25.Vys / vys25[k] - 1), v30.Vys,
                vys30[k], 100 * (v30.Vys / vys30[k] - 1));
    for (const auto& [computed, table] : {std::pair{v25.Vys, vys25[k]}, std::pair{v30.Vys, vys30[k]}}) {
      EXPECT_NEAR(computed, table, 0.01 * table) << radii[k];  // the bound
      EXPECT_NEAR(computed, table, 0.005) << radii[k];         // half a unit of the printed digit
    }
  }
}

// V_ys falls to V_s as p_y grows past the Eq. 77 criterion and stays there (000 Fig. 9).
TEST(StickingVelocity, ReachesAdhesiveLimitAtHighYieldPressure) {
  double previous = 1e9;
  for (double py : {10e6, 30e6, 100e6, 300e6, 1e9}) {
    const StickingVelocities v = stickingVelocities(table5(2.45e-6, py));
    EXPECT_LE(v.Vys, previous * (1 + 1e-12)) << py;
    EXPECT_GE(v.Vys, v.Vs * (1 - 1e-12));
    previous = v.Vys;
  }
  const StickingVelocities hard = stickingVelocities(table5(2.45e-6, 1e9));
  EXPECT_GE(hard.Vy, hard.Vs);
  EXPECT_DOUBLE_EQ(hard.Vys, hard.Vs);
  EXPECT_THROW(stickingVelocities(table5(-1.0, 30e6)), std::invalid_argument);
  // At 5 MPa, k_el = pi R p_y is so soft that the elastic triangle alone stores more than W_JKR:
  // Eq. 36 has no positive k_cl and the law refuses the parameters.
  EXPECT_THROW(stickingVelocities(table5(2.45e-6, 5e6)), std::invalid_argument);
}

// 000 Eq. 72: the spring time step 2 sqrt(m/k_e) with the Hertz bound k_e = 2 E R sqrt(alpha/R)
// (Eqs. 68-70) over the Rayleigh time step (Eq. 71) has the closed form of Eq. 72.
TEST(NanAdhesive, TimeStepRatioIsEq72) {
  const double R = 1e-5, rho = 2500, E = 7e10, nu = 0.25, alphaOverR = 0.1;
  const double m = 4.0 / 3.0 * pi * R * R * R * rho, ke = 2 * E * R * std::sqrt(alphaOverR);
  const double ratio = nanCriticalTimeStep(m, ke) / rayleighTimeStep(R, rho, E / (2 * (1 + nu)), nu);
  const double eq72 = (0.1631 * nu + 0.8766) / std::sqrt(1 + nu) * std::sqrt(4 / (3 * pi)) * std::pow(alphaOverR, -0.25);
  EXPECT_NEAR(ratio, eq72, 1e-12 * eq72);
}

}  // namespace
}  // namespace sqdem
