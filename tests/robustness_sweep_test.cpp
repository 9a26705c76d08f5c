// Robustness sweep of the common-normal detector (issue 2, item 7): >= 1e5 random pairs of
// superquadrics (semi-axis ratios 1:[0.2..1]:[0.2..1], n1, n2 in [2, 10], random orientations,
// overlaps 1e-6..1e-1 of R_vol, 10 % flat face on flat face, 10 % near edges/corners), each with a
// planted exact common-normal contact (support_pairs.hpp). Requirements: >= 99.99 % converge to
// the detector tolerance, the rest return a non-converged status, and no output is NaN/inf.

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

struct Stats {
  long pairs = 0, converged = 0, nonFinite = 0, plantedFound = 0, recheckFailures = 0;
  long iterationSum = 0;
  int maxIterations = 0;
  void add(const ContactGeometry& g) {
    ++pairs;
    converged += g.converged();
    iterationSum += g.iterations;
    maxIterations = std::max(maxIterations, g.iterations);
  }
};

TEST(RobustnessSweep, RandomSuperquadricPairs) {
  const long pairs = std::getenv("SQDEM_SWEEP_PAIRS") ? std::atol(std::getenv("SQDEM_SWEEP_PAIRS")) : 100000;
  testing::PairGenerator generator(20261123);
  DetectorSettings settings;
  Stats cold, warm;
  long statusCounts[6] = {};
  for (long k = 0; k < pairs; ++k) {
    const testing::PlantedPair p = generator.next();
    const double L = referenceVolumeRadius(p.A, p.B);
    settings.cutoff = 0.05 * L;  // the warm-start motion may open a small gap
    const ContactGeometry g = detectContact(p.A, p.poseA, p.B, p.poseB, settings);
    cold.add(g);
    ++statusCounts[static_cast<int>(g.status)];
    if (!allFinite(g)) ++cold.nonFinite;
    if (!g.converged()) continue;
    if (commonNormalError(p.A, p.poseA, p.B, p.poseB, g, L) > 1e-8 * L) ++cold.recheckFailures;
    if (std::abs(g.overlap - p.overlap) <= 1e-6 * p.overlap + 1e-12 * L) ++cold.plantedFound;

    // Warm start after a small relative motion: B turns by ~1e-3 rad and moves by ~1e-4 L.
    Pose moved = p.poseB;
    moved.orientation = Quat(Eigen::AngleAxisd(1e-3, generator.randomUnit())) * moved.orientation;
    moved.position += 1e-4 * L * generator.randomUnit();
    const ContactGeometry w = detectContact(p.A, p.poseA, p.B, moved, settings, g);
    warm.add(w);
    if (!allFinite(w)) ++warm.nonFinite;
  }
  const double rate = 100.0 * cold.converged / cold.pairs;
  std::printf("robustness sweep: %ld pairs\n", cold.pairs);
  std::printf("  cold: converged %.4f %% (%ld), mean iterations %.2f, max %d\n", rate,
              cold.converged, double(cold.iterationSum) / cold.pairs, cold.maxIterations);
  std::printf("  cold: planted overlap recovered in %.3f %% of converged, re-check failures %ld\n",
              100.0 * cold.plantedFound / std::max(1L, cold.converged), cold.recheckFailures);
  std::printf("  warm: converged %.4f %%, mean iterations %.3f, max %d\n",
              100.0 * warm.converged / std::max(1L, warm.pairs),
              double(warm.iterationSum) / std::max(1L, warm.pairs), warm.maxIterations);
  std::printf("  statuses:");
  for (int s = 0; s < 6; ++s) {
    if (statusCounts[s]) std::printf(" [%s: %ld]", describe(ContactStatus(s)), statusCounts[s]);
  }
  std::printf("\n");
  EXPECT_EQ(cold.nonFinite, 0);
  EXPECT_EQ(warm.nonFinite, 0);
  EXPECT_EQ(cold.recheckFailures, 0);
  EXPECT_GE(rate, 99.99);
  EXPECT_GE(100.0 * warm.converged / std::max(1L, warm.pairs), 99.99);
}

}  // namespace
}  // namespace sqdem
