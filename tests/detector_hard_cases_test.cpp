// Adversarial detector sweep (issue 10, item 10): superquadrics with n1, n2 in [2, 20] and
// semi-axis ratios down to 1:10, random orientations; half the pairs nearly touching (planted
// overlap or gap of 1e-8 .. 1e-3 L), half deeply overlapping (up to half the smaller volume
// radius, the bound: thin bodies are then often cut through). Requirements: >= 99.99 %
// resolved — converged (and satisfying the common-normal conditions when re-checked from the
// shapes) or flagged degenerate (a centre inside the other body: no common normal to find; they
// get the penetration depth of the Minkowski difference) — 0 non-finite outputs, and no overlap
// on an unresolved answer.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "sqdem/contact/detector.hpp"
#include "support/contact_checks.hpp"
#include "support/random_pairs.hpp"

namespace sqdem {
namespace {

using testing::allFinite;
using testing::commonNormalError;

TEST(DetectorHardCases, AdversarialPairs) {
  const long pairs = std::getenv("SQDEM_HARD_PAIRS") ? std::atol(std::getenv("SQDEM_HARD_PAIRS")) : 100000;
  testing::PairGenerator generator(20261127);
  generator.maxExponent = 20.0;
  generator.minAxisRatio = 0.1;
  long converged[2] = {}, total[2] = {}, nonFinite = 0, recheck = 0, unconvergedWithOverlap = 0, degenerate = 0;
  long statuses[8] = {};
  int maxIterations = 0;
  for (long k = 0; k < pairs; ++k) {
    const bool deep = k % 2 == 1;
    testing::PlantedPair p = generator.next();
    const double L = referenceVolumeRadius(p.A, p.B);
    // Re-plant at the wanted overlap along the same normal.
    const double limit = 0.5 * std::min(p.A.volumeEquivalentRadius(), p.B.volumeEquivalentRadius());
    const double magnitude = deep ? generator.uniform(1e-3 * L, std::max(1e-3 * L, limit))
                                  : L * std::pow(10.0, generator.uniform(-8.0, -3.0));
    const double overlap = deep || generator.uniform(0.0, 1.0) < 0.5 ? magnitude : -magnitude;
    p.poseB.position -= (overlap - p.overlap) * p.normal;
    DetectorSettings settings;
    settings.cutoff = 0.01 * L;
    const ContactGeometry g = detectContact(p.A, p.poseA, p.B, p.poseB, settings);
    ++total[deep];
    ++statuses[static_cast<int>(g.status)];
    maxIterations = std::max(maxIterations, g.iterations);
    if (!allFinite(g)) ++nonFinite;
    if (g.status == ContactStatus::Degenerate) ++degenerate;
    if (g.converged()) {
      ++converged[deep];
      if (commonNormalError(p.A, p.poseA, p.B, p.poseB, g, L) > 1e-8 * L) ++recheck;
    } else if (g.status != ContactStatus::Degenerate && g.overlap != 0.0 && g.status != ContactStatus::Separated) {
      ++unconvergedWithOverlap;
    }
  }
  const double settled = 100.0 * (converged[0] + converged[1] + statuses[int(ContactStatus::Separated)] + degenerate) /
                         (total[0] + total[1]);
  std::printf("hard cases: %ld nearly touching, %ld deep; converged %ld / %ld, separated %ld, degenerate %ld; "
              "resolved %.4f %%, max iterations %d\n", total[0], total[1], converged[0], converged[1],
              statuses[int(ContactStatus::Separated)], degenerate, settled, maxIterations);
  std::printf("  statuses:");
  for (int s = 0; s < 8; ++s) if (statuses[s]) std::printf(" [%s: %ld]", describe(ContactStatus(s)), statuses[s]);
  std::printf("\n  re-check failures %ld, non-finite %ld, unconverged with an overlap %ld\n", recheck, nonFinite,
              unconvergedWithOverlap);
  EXPECT_EQ(nonFinite, 0);
  EXPECT_EQ(recheck, 0);
  EXPECT_EQ(unconvergedWithOverlap, 0);
  EXPECT_GE(settled, 99.99);
}

// Degenerate pairs have a defined answer: identical bodies with coincident centres overlap by the
// penetration depth of their Minkowski difference, 2 x the smallest semi-axis (the minimum width
// of a superquadric, n >= 2, is along its shortest axis); coincident spheres by rA + rB; a small
// body around the centre of a large one is flagged too, with a depth larger than its own size.
TEST(DetectorHardCases, DegeneratePairsHaveADefinedAnswer) {
  testing::PairGenerator generator(99);
  generator.maxExponent = 20.0;
  generator.minAxisRatio = 0.1;
  for (int k = 0; k < 200; ++k) {
    const Superquadric A = generator.randomShape();
    const Pose pose{Vec3(generator.uniform(-1, 1), 0.0, 0.0), generator.randomRotation()};
    Pose turned = pose;
    if (k % 2) turned.orientation = generator.randomRotation();  // same centre, another orientation
    const ContactGeometry g = detectContact(A, pose, A, turned);
    ASSERT_EQ(g.status, ContactStatus::Degenerate) << k;
    ASSERT_TRUE(allFinite(g)) << k;
    if (k % 2 == 0) EXPECT_NEAR(g.overlap, 2.0 * A.halfExtents().minCoeff(), 1e-6 * A.halfExtents().minCoeff()) << k;
    EXPECT_GE(g.overlap, 2.0 * A.halfExtents().minCoeff() * (1 - 1e-6)) << k;  // the other body still needs its width
  }
  const Superquadric sphere = Superquadric::ellipsoid(1.0, 1.0, 1.0), small = Superquadric::ellipsoid(0.5, 0.5, 0.5);
  const ContactGeometry spheres = detectContact(sphere, Pose{}, small, Pose{});
  EXPECT_EQ(spheres.status, ContactStatus::Degenerate);
  EXPECT_DOUBLE_EQ(spheres.overlap, 1.5);
  const Superquadric big(2.0, 1.5, 1.0, 6.0, 6.0), pebble(0.2, 0.15, 0.1, 4.0, 4.0);
  const ContactGeometry inside = detectContact(big, Pose{}, pebble, Pose{Vec3(0.3, 0.2, 0.1), generator.randomRotation()});
  EXPECT_EQ(inside.status, ContactStatus::Degenerate);
  EXPECT_GT(inside.overlap, 0.2);
  EXPECT_TRUE(allFinite(inside));
}

}  // namespace
}  // namespace sqdem
