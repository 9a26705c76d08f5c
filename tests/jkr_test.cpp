// Elliptic JKR (Johnson-Greenwood, 004 Eqs. 19-28) and circular JKR (001 Eqs. 7-10).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>

#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/mechanics/elliptic_integrals.hpp"
#include "sqdem/mechanics/jkr_circular.hpp"
#include "sqdem/mechanics/jkr_elliptic.hpp"

namespace sqdem {
namespace {

using std::numbers::pi;

RelativeRadii radiiOf(double Ri, double Rj) {
  RelativeRadii r;
  r.Ri = Ri;
  r.Rj = Rj;
  r.Rc = Ri * Rj / (Ri + Rj);
  return r;
}

// 004 Eqs. 24-26 against their definitions by midpoint quadrature of the integrands
// B = int cos^2/Delta, C = int sin^2 cos^2/Delta^3, D = int sin^2/Delta.
TEST(EllipticIntegrals, MatchQuadratureOfTheirDefinitions) {
  for (double m : {0.0, 0.05, 0.2499, 0.25, 0.6, 0.95}) {
    const int n = 20000;
    double B = 0, C = 0, D = 0;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * (pi / 2) / n, s2 = std::sin(t) * std::sin(t), c2 = 1 - s2;
      const double delta = std::sqrt(1 - m * s2);
      B += c2 / delta;
      C += s2 * c2 / (delta * delta * delta);
      D += s2 / delta;
    }
    const double h = (pi / 2) / n;
    const EllipticIntegrals I = ellipticIntegrals(m);
    EXPECT_NEAR(I.B, B * h, 1e-8) << m;
    EXPECT_NEAR(I.C, C * h, 1e-8) << m;
    EXPECT_NEAR(I.D, D * h, 1e-8) << m;
    EXPECT_NEAR(I.K, I.B + I.D, 1e-14);
  }
}

// Classical JKR: F(a) at the pull-off radius is -3/2 pi W R, and F = 0 at a_0 (001 Eq. 7).
TEST(CircularJkr, PullOffAndEquilibriumRadius) {
  const CircularJkr jkr{1e9, 0.2, 1e-5};
  const double aPull = std::cbrt(9 * pi * 0.2 * 1e-10 / (8 * 1e9));
  EXPECT_NEAR(jkr.forceAt(aPull), -jkr.pullOffForce(), 1e-12 * jkr.pullOffForce());
  const double a0 = std::cbrt(9 * pi * 0.2 * 1e-10 / (2 * 1e9));
  EXPECT_NEAR(jkr.forceAt(a0), 0.0, 1e-12 * jkr.pullOffForce());
  for (double overlap : {-1e-9, 0.0, 1e-9, 1e-7}) {
    EXPECT_NEAR(jkr.overlapAt(jkr.contactRadius(overlap)), overlap, 1e-15 + 1e-12 * std::abs(overlap));
  }
}

// The Hertz axis ratio g_H (root of Eq. 13) makes Pi_2 g^2 - Pi_1 vanish: Eqs. 22-23 and
// Eq. 13 describe the same Hertz limit.
TEST(EllipticJkr, HertzAxisRatioIsTheSingularityOfEqs19To21) {
  for (double ratio : {0.05, 0.25, 0.6, 0.95}) {
    const double gH = std::sqrt(1 - eccentricitySquaredExact(ratio));
    const JohnsonGreenwoodPoint p = johnsonGreenwoodPoint(std::sqrt(ratio), gH);
    EXPECT_NEAR(p.Pi2 * gH * gH - p.Pi1, 0.0, 1e-9 * std::abs(p.Pi1)) << ratio;
  }
}

// W -> 0 recovers elliptic Hertz (004 Eqs. 1-2): gamma_JG sqrt(R_c1) -> gamma sqrt(R_c) and
// beta_JG R_c1 -> beta R_c at fixed overlap.
TEST(EllipticJkr, VanishingAdhesionRecoversEllipticHertz) {
  const double E = 1e9, overlap = 1e-7;
  for (double ratio : {0.1, 0.25, 0.7}) {
    const RelativeRadii r = radiiOf(ratio * 1e-5, 1e-5);
    const HertzFactors h = hertzFactors(ratio, EccentricityMethod::Exact);
    const double hertzForce = ellipticHertzForce(E, r.Rc, overlap, h.gamma);
    const double hertzArea = ellipticHertzArea(r.Rc, overlap, h.beta);
    double previousError = 1.0;
    for (double W : {1e-3, 1e-6, 1e-9}) {
      const EllipticJkrState s = EllipticJkr(E, W, r).evaluate(overlap);
      const double error = std::abs(s.force / hertzForce - 1.0);
      EXPECT_LT(error, previousError) << ratio << " W=" << W;  // converges as W decreases
      previousError = error;
      if (W == 1e-9) {
        EXPECT_LT(error, 1e-4) << ratio;
        EXPECT_NEAR(s.area / hertzArea, 1.0, 1e-4) << ratio;
        EXPECT_NEAR(s.axisRatio, std::sqrt(1 - h.e2), 1e-4) << ratio;
      }
    }
  }
}

// g -> 1 (Ri -> Rj): classical JKR, pull-off 3/2 pi W R (R = R_c1 = Ri = Rj).
TEST(EllipticJkr, NearlyCircularContactRecoversClassicalJkr) {
  const double E = 1e9, W = 0.2, R = 1e-5;
  const CircularJkr circle{E, W, R};
  const double aUnit = std::cbrt(9 * pi * W * R * R / (4 * E));  // JKR length scale
  double previousError = 1.0;
  for (double ratio : {0.99, 0.999, 0.9999}) {
    const EllipticJkr nearly(E, W, radiiOf(ratio * R, R));
    double error = std::abs(nearly.pullOffForce() / -circle.pullOffForce() - 1.0);
    error = std::max(error, std::abs(nearly.detachmentOverlap() /
                                         circle.overlapAt(circle.minimumContactRadius()) - 1.0));
    for (double overlap : {0.5, 1.0, 4.0}) {
      const double d = overlap * aUnit * aUnit / R;
      const double expected = circle.forceAt(circle.contactRadius(d));
      error = std::max(error, std::abs(nearly.evaluate(d).force / expected - 1.0));
    }
    EXPECT_LT(error, 0.5 * previousError) << ratio;
    previousError = error;
  }
  EXPECT_LT(previousError, 1e-3);
  // Exactly circular radii take the closed form.
  const EllipticJkr exact(E, W, radiiOf(R, R));
  EXPECT_DOUBLE_EQ(exact.pullOffForce(), -1.5 * pi * W * R);
}

// More elongated contacts pull off at a smaller force in units of 3 pi W R_c1 (004 Fig. 4).
TEST(EllipticJkr, PullOffDecreasesWithEllipticity) {
  double previous = 0.5 + 1e-9;
  for (double ratio : {0.9, 0.5, 0.2, 0.05}) {
    const RelativeRadii r = radiiOf(ratio * 1e-5, 1e-5);
    const EllipticJkr jkr(1e9, 0.2, r);
    const double pullOff = -jkr.pullOffForce() / (3 * pi * std::sqrt(r.Ri * r.Rj) * 0.2);
    EXPECT_LT(pullOff, previous) << ratio;
    EXPECT_GT(pullOff, 0.0);
    previous = pullOff;
  }
}

// On the stable branch (displacement control) the area grows with the overlap; the force first
// falls from the detachment point to the pull-off minimum, then rises (as in classical JKR).
TEST(EllipticJkr, StableBranchShape) {
  const EllipticJkr jkr(1e9, 0.2, radiiOf(2e-6, 1e-5));
  const double start = jkr.detachmentOverlap(), span = -50 * start;
  EllipticJkrState previous = jkr.evaluate(start);
  bool pastPullOff = false;
  for (int i = 1; i <= 4000; ++i) {
    const EllipticJkrState s = jkr.evaluate(start + span * i / 4000.0);
    ASSERT_TRUE(s.attached);
    EXPECT_GT(s.area, previous.area) << i;
    EXPECT_GE(s.force, jkr.pullOffForce() * (1 + 1e-9)) << i;
    if (s.force > previous.force) pastPullOff = true;
    if (pastPullOff) EXPECT_GT(s.force, previous.force) << i;
    previous = s;
  }
  EXPECT_TRUE(pastPullOff);
  EXPECT_FALSE(jkr.evaluate(1.01 * start).attached);
}

// The two evaluation routes (F_bar for delta_bar <= 1, gamma_JG delta_bar^3/2 above) agree:
// relative jump across delta_bar = 1 below 1e-9.
TEST(EllipticJkr, ContinuousWhereTheEvaluationRouteChanges) {
  const double E = 1e9, W = 0.2;
  const RelativeRadii r = radiiOf(2e-6, 1e-5);
  const double scale = std::pow(9 * pi * W * std::sqrt(std::sqrt(r.Ri * r.Rj)) / (4 * E), 2.0 / 3.0);
  const EllipticJkr jkr(E, W, r);
  const double below = jkr.evaluate(scale * (1 - 1e-13)).force, above = jkr.evaluate(scale * (1 + 1e-13)).force;
  EXPECT_NEAR(below, above, 1e-9 * std::abs(above));
}

}  // namespace
}  // namespace sqdem

namespace sqdem {
namespace {

// EllipticJkrLaw::reach (the candidate search's bound of the gap an attached contact spans):
// 2 |delta_d| of the circle of radius R bounds the detachment overlap of every elliptic contact
// with R_c1 = sqrt(Ri Rj) <= R, here over Ri/Rj from 1 down to 1e-4 at R_c1 = R.
TEST(EllipticJkr, ReachBoundsTheDetachmentGapOfEveryEllipse) {
  const double E = 1e9, gamma = 0.05, R = 1e-5;
  const double reach = EllipticJkrLaw{gamma}.reach(E, R);
  double widest = 0.0;
  for (double ratio = 1.0; ratio >= 1e-4; ratio *= 0.5) {
    const double lambda = std::sqrt(ratio);
    const double Ri = R * lambda, Rj = R / lambda;
    const EllipticJkr law(E, 2.0 * gamma, RelativeRadii{Ri, Rj, 1.0, Ri * Rj / (Ri + Rj)});
    widest = std::max(widest, -law.detachmentOverlap());
  }
  std::printf("widest detachment gap %.4e m, reach %.4e m (%.2f x)\n", widest, reach, reach / widest);
  EXPECT_LE(widest, reach);
}

}  // namespace
}  // namespace sqdem

namespace sqdem {
namespace {

// The tabulated curve (johnson_greenwood_table.hpp) against the exact one at random points:
// lambda log-uniform in [1e-2, 1]; each curve's ends (detachment overlap and pull-off force),
// and its points at the same distance w^2 |delta_d| beyond each one's detachment overlap, w
// log-uniform in [1e-6, 1e3] (up to 1e6 |delta_d|). The same distance, because F rises as the
// square root of it at detachment: the ends' error (~1e-7 of delta_d) would show there as an
// error of ~3e-4 in F at a fixed overlap, while the curve is merely shifted by 1e-7 |delta_d|.
// Errors of the force in units of max(|F|, |F_pull-off|), of the area relative to it, of g absolute.
TEST(EllipticJkr, TabulatedCurveMatchesTheExactOne) {
  const double E = 1e9, W = 0.2, R = 1e-5;
  std::uint64_t state = 12345;
  const auto uniform = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  double forceError = 0, areaError = 0, ratioError = 0, endError = 0;
  for (int c = 0; c < 400; ++c) {
    const double lambda = std::pow(10.0, -2.0 * uniform());
    const RelativeRadii r = radiiOf(R * lambda, R / lambda);
    // Above lambda = 0.999 the exact route loses digits (1 - sqrt(g) -> 0 in Eqs. 19-21: its
    // pull-off is 5e-5 off at lambda = 1 - 5e-6); there the reference is the circle it tends
    // to, 1.4e-7 from the curve at lambda = 0.999.
    const EllipticJkr exact(E, W, lambda < 0.999 ? r : radiiOf(R, R), JkrCurve::Exact), table(E, W, r, JkrCurve::Tabulated);
    endError = std::max({endError, std::abs(table.pullOffForce() / exact.pullOffForce() - 1.0),
                         std::abs(table.detachmentOverlap() / exact.detachmentOverlap() - 1.0)});
    for (int k = 0; k < 50; ++k) {
      const double w = std::pow(10.0, -6.0 + 9.0 * uniform());
      const double d = exact.detachmentOverlap(), along = w * w * std::abs(d);
      const EllipticJkrState a = exact.evaluate(d + along), b = table.evaluate(table.detachmentOverlap() + along);
      ASSERT_TRUE(a.attached && b.attached) << lambda << " " << w;
      forceError = std::max(forceError, std::abs(b.force - a.force) / std::max(std::abs(a.force), -exact.pullOffForce()));
      areaError = std::max(areaError, std::abs(b.area / a.area - 1.0));
      if (lambda < 0.999) ratioError = std::max(ratioError, std::abs(b.axisRatio - a.axisRatio));  // the circle's g is 1
    }
  }
  std::printf("tabulated JKR curve, largest errors: force %.2e, area %.2e, axis ratio %.2e, pull-off and detachment %.2e\n",
              forceError, areaError, ratioError, endError);
  EXPECT_LT(forceError, 1e-6);
  EXPECT_LT(areaError, 3e-6);
  EXPECT_LT(ratioError, 3e-6);
  EXPECT_LT(endError, 6e-7);
}

}  // namespace
}  // namespace sqdem
