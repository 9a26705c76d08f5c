// Detector sweep by construction (issue 31, item 3): random separated pairs of superquadrics
// (n1, n2 in [2, 20], semi-axis ratios down to 1:10, random orientations) are probed cold, then B
// is moved along the probe's own normal n to a chosen overlap delta: half nearly touching
// (|delta| from 1e-12 to 1e-4 of the smaller volume radius, either sign), half deep (0.05 to 0.5
// of it). The separated pairs are of two families: planted (a planted contact, random_pairs.hpp,
// opened by 0.01 to 1 L along its normal) and placed (B's centre 1 to 1.5 bounding-sphere reaches
// away in a random direction, so the moved pair's line of centres points anywhere). Moving B by
// (gap + delta) along -n makes the support gap h_A(n) + h_B(-n) the constructed overlap (computed
// here from the support maps), and the least penetration, the support gap's minimum over all
// directions (detector.hpp), is at most that.
//
// A converged answer is wrong when
//   - it overlaps more than the support gap at the constructed normal (not the least penetration),
//   - it overlaps more than the least support gap a brute-force direction search finds
//     (support_gap_search.hpp: 2000 directions, the best 8 refined),
//   - it is apart while a point lies inside the other body or while FCL's GJK finds the bodies'
//     inscribed tessellations overlapping (fcl_polytope.hpp), or further apart than they are,
//   - it breaks the common-normal conditions (contact_checks.hpp).
// An overlapping answer's points need not lie inside the other body: where B is thin across the
// normal, the least penetration pushes it out sideways and A's point lies beyond it (counted).
// Requirements: no wrong converged answer, every pair converged or degenerate, nothing
// non-finite, no overlap on an unsolved answer.
// SQDEM_CONSTRUCTION_PAIRS sets the number of pairs (default 10^5); the table goes to stdout.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "sqdem/contact/detector.hpp"
#include "support/contact_checks.hpp"
#include "support/fcl_polytope.hpp"
#include "support/random_pairs.hpp"
#include "support/support_gap_search.hpp"

namespace sqdem {
namespace {

using testing::allFinite;
using testing::commonNormalError;
using testing::supportGap;

/// The pair as `sqdem geometry` input (round-trip digits).
std::string probeInput(const testing::PlantedPair& p) {
  std::string out = "{\"particles\": [";
  for (int k = 0; k < 2; ++k) {
    const Superquadric& s = k ? p.B : p.A;
    const Pose& pose = k ? p.poseB : p.poseA;
    char buffer[512];
    std::snprintf(buffer, sizeof buffer,
                  "%s{\"a\": %.17g, \"b\": %.17g, \"c\": %.17g, \"n1\": %.17g, \"n2\": %.17g, "
                  "\"centre\": [%.17g, %.17g, %.17g], \"quaternion\": [%.17g, %.17g, %.17g, %.17g]}",
                  k ? ", " : "", s.a(), s.b(), s.c(), s.n1(), s.n2(), pose.position.x(), pose.position.y(),
                  pose.position.z(), pose.orientation.w(), pose.orientation.x(), pose.orientation.y(),
                  pose.orientation.z());
    out += buffer;
  }
  return out + "]}";
}

enum Wrong { DeeperThanConstructed, DeeperThanSearched, ApartYetInside, FurtherThanPolytopes, CommonNormal, wrongKinds };
constexpr const char* wrongNames[wrongKinds] = {
    "deeper than constructed", "deeper than the direction search", "apart, yet overlapping (a point inside, or FCL)",
    "further apart than FCL's polytopes", "common-normal conditions"};

/// One column of the table: a family of separated pairs (planted: opened from a planted contact;
/// placed: B's centre in a random direction beyond the bounding spheres, so the line of centres
/// says nothing of the contact) moved to nearly touching or deep.
struct Regime {
  const char* name;
  long pairs = 0, statuses[contactStatusCount] = {}, wrong[wrongKinds] = {}, wrongPairs = 0;
  long iterations = 0, nonFinite = 0, unsolvedWithOverlap = 0, pointOutside = 0, probesUnsettled = 0;
  int maxIterations = 0;
  double seconds = 0.0, worstBelowSearch = 0.0;
};

TEST(DetectorConstructionSweep, MovedAlongTheProbesNormal) {
  const char* env = std::getenv("SQDEM_CONSTRUCTION_PAIRS");
  const long pairs = env ? std::atol(env) : 100000;
  testing::PairGenerator generator(20261201);
  generator.maxExponent = 20.0;
  generator.minAxisRatio = 0.1;
  // A pool of shapes with their polytopes (a polytope's hull and FCL's set-up cost milliseconds,
  // a query tens of microseconds); each pair draws two of them.
  constexpr int poolSize = 1000, resolution = 24;  // tessellation: 6 x 24^2 quads a body
  std::vector<Superquadric> shapes;
  std::vector<std::shared_ptr<fcl::Convexd>> polytopes;
  for (int k = 0; k < poolSize; ++k) {
    shapes.push_back(generator.randomShape());
    polytopes.push_back(testing::fclPolytope(shapes.back(), resolution));
  }
  Regime regimes[4] = {{"planted, nearly touching"}, {"planted, deep"}, {"placed, nearly touching"}, {"placed, deep"}};
  for (long k = 0; k < pairs; ++k) {
    const bool deep = k % 2 == 1, placed = k % 4 >= 2;
    Regime& r = regimes[k % 4];
    const int a = static_cast<int>(generator.uniform(0.0, poolSize)), b = static_cast<int>(generator.uniform(0.0, poolSize));
    testing::PlantedPair p = generator.next(shapes[a], shapes[b]);
    const double L = referenceVolumeRadius(p.A, p.B);
    const double reach = p.A.boundingRadius() + p.B.boundingRadius();
    if (placed) {
      p.poseB.position = p.poseA.position + reach * generator.uniform(1.0, 1.5) * generator.randomUnit();
    } else {  // open a gap of 0.01 .. 1 L along the planted normal
      p.poseB.position += (p.overlap + L * std::pow(10.0, generator.uniform(-2.0, 0.0))) * p.normal;
    }
    DetectorSettings probeSettings;
    probeSettings.cutoff = 2.0 * reach;
    const ContactGeometry probe = detectContact(p.A, p.poseA, p.B, p.poseB, probeSettings);
    if (!probe.converged()) {
      ++r.probesUnsettled;
      continue;
    }
    const double R = std::min(p.A.volumeEquivalentRadius(), p.B.volumeEquivalentRadius());
    const double magnitude = R * (deep ? generator.uniform(0.05, 0.5) : std::pow(10.0, generator.uniform(-12.0, -4.0)));
    const double delta = deep || generator.uniform(0.0, 1.0) < 0.5 ? magnitude : -magnitude;
    p.poseB.position -= (delta - probe.overlap) * probe.normal;
    const double constructed = supportGap(p.A, p.poseA, p.B, p.poseB, probe.normal);

    DetectorSettings settings;
    settings.cutoff = 1e-3 * R;
    const auto start = std::chrono::steady_clock::now();
    const ContactGeometry g = detectContact(p.A, p.poseA, p.B, p.poseB, settings);
    r.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++r.pairs;
    ++r.statuses[static_cast<int>(g.status)];
    r.iterations += g.iterations;
    r.maxIterations = std::max(r.maxIterations, g.iterations);
    if (!allFinite(g)) ++r.nonFinite;
    if (!g.converged()) {
      if (g.status != ContactStatus::Degenerate && g.status != ContactStatus::Separated && g.overlap != 0.0) {
        ++r.unsolvedWithOverlap;
      }
      continue;
    }
    const double tolerance = 1e-8 * L;
    bool wrong[wrongKinds] = {};
    wrong[DeeperThanConstructed] = g.overlap > constructed + tolerance;
    const double insideB = p.B.gauge(p.poseB.toBody(g.pointA)) - 1.0;
    const double insideA = p.A.gauge(p.poseA.toBody(g.pointB)) - 1.0;
    const double side = 1e-8;  // gauge units: relative distance to the surface
    r.pointOutside += g.overlap > tolerance && (insideB > side || insideA > side);
    const double searched = testing::searchedLeastOverlap(p.A, p.poseA, p.B, p.poseB);
    wrong[DeeperThanSearched] = g.overlap > searched + tolerance;
    r.worstBelowSearch = std::max(r.worstBelowSearch, (searched - g.overlap) / L);
    const std::optional<double> apart = testing::fclDistance(polytopes[a], p.poseA, polytopes[b], p.poseB);
    wrong[ApartYetInside] = g.overlap < -tolerance && (insideB < -side || insideA < -side || !apart);
    wrong[FurtherThanPolytopes] = apart && g.overlap < -*apart - 1e-6 * L;  // GJK's own tolerance
    wrong[CommonNormal] = commonNormalError(p.A, p.poseA, p.B, p.poseB, g, L) > tolerance;
    bool any = false;
    for (int w = 0; w < wrongKinds; ++w) {
      r.wrong[w] += wrong[w];
      any = any || wrong[w];
    }
    r.wrongPairs += any;
    if (any && r.wrongPairs <= 2) {
      std::printf("wrong (%s): overlap %.6g L, constructed %.6g L, searched %.6g L, polytopes %s %.6g L, "
                  "gauge of A's point in B %.3g, of B's point in A %.3g; sqdem geometry input:\n%s\n",
                  r.name, g.overlap / L, constructed / L, searched / L, apart ? "apart by" : "overlap",
                  apart ? *apart / L : 0.0, insideB, insideA, probeInput(p).c_str());
    }
  }
  const auto row = [&](const std::string& label, const auto& cell) {
    std::printf("| %s |", label.c_str());
    for (const Regime& r : regimes) std::printf(" %s |", cell(r).c_str());
    std::printf("\n");
  };
  const auto count = [](long n) { return std::to_string(n); };
  const auto fixed = [](const char* format, double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, x);
    return std::string(buffer);
  };
  std::printf("construction sweep: %ld pairs\n", pairs);
  row("", [](const Regime& r) { return std::string(r.name); });
  row("---", [](const Regime&) { return std::string("---"); });
  row("probes not converged (skipped)", [&](const Regime& r) { return count(r.probesUnsettled); });
  row("solved pairs", [&](const Regime& r) { return count(r.pairs); });
  for (int s = 0; s < contactStatusCount; ++s) row(describe(ContactStatus(s)), [&](const Regime& r) { return count(r.statuses[s]); });
  row("**wrong converged answers**", [&](const Regime& r) { return count(r.wrongPairs); });
  for (int w = 0; w < wrongKinds; ++w) row(std::string("- ") + wrongNames[w], [&](const Regime& r) { return count(r.wrong[w]); });
  row("overlapping answers with a point outside the other body", [&](const Regime& r) { return count(r.pointOutside); });
  row("mean / max iterations", [&](const Regime& r) {
    return fixed("%.1f", double(r.iterations) / std::max(1L, r.pairs)) + " / " + count(r.maxIterations);
  });
  row("time per solve (us)", [&](const Regime& r) { return fixed("%.1f", 1e6 * r.seconds / std::max(1L, r.pairs)); });
  row("largest search minimum above the answer (L)", [&](const Regime& r) { return fixed("%.3g", r.worstBelowSearch); });
  for (const Regime& r : regimes) {
    EXPECT_EQ(r.wrongPairs, 0) << r.name;
    EXPECT_EQ(r.nonFinite, 0) << r.name;
    EXPECT_EQ(r.unsolvedWithOverlap, 0) << r.name;
    // Nothing lost either: every pair converged or was flagged degenerate (a centre inside).
    EXPECT_EQ(r.statuses[int(ContactStatus::Converged)] + r.statuses[int(ContactStatus::Degenerate)], r.pairs) << r.name;
    EXPECT_LE(r.probesUnsettled, pairs / 1000) << r.name;
  }
}

}  // namespace
}  // namespace sqdem
