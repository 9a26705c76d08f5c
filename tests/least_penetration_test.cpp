// Which common-normal pair the detector reports (issue 31; detector.hpp): the least penetration,
// bounded by the expanding polytope algorithm (penetration_depth.hpp), and the side check.

#include <gtest/gtest.h>

#include <cmath>

#include "contact/penetration_depth.hpp"
#include "sqdem/contact/detector.hpp"
#include "support/contact_checks.hpp"
#include "support/random_pairs.hpp"
#include "support/support_gap_search.hpp"

namespace sqdem {
namespace {

using testing::supportGap;

detail::PairFrame frameOf(const Superquadric& A, const Pose& pa, const Superquadric& B, const Pose& pb) {
  const Mat3 RA = pa.rotation();
  return {A, B, RA.transpose() * pb.rotation(), RA.transpose() * (pb.position - pa.position), referenceVolumeRadius(A, B)};
}

Pose pose(const Vec3& centre, double w, double x, double y, double z) { return {centre, Quat(w, x, y, z).normalized()}; }

// Two spheres overlap by rA + rB - d along the line of centres (closed form): EPA's bounds
// bracket it and agree to the tolerance; its normal is the line of centres.
TEST(LeastPenetration, EpaBracketsTwoSpheres) {
  const Superquadric A = Superquadric::sphere(1.0), B = Superquadric::sphere(0.5);
  const Vec3 d(0.7, -0.4, 0.6);
  const detail::PairFrame f = frameOf(A, Pose{}, B, Pose{d, Quat::Identity()});
  const std::optional<detail::Penetration> p = detail::penetrationDepth(f, 1e-8);
  ASSERT_TRUE(p);
  const double exact = 1.5 - d.norm();
  EXPECT_LE(p->lowerBound, exact + 1e-15);
  EXPECT_GE(p->upperBound, exact - 1e-15);
  EXPECT_LE(p->upperBound - p->lowerBound, 1e-8 * f.lengthScale);
  EXPECT_GT(p->normal.dot(d.normalized()), 1.0 - 1e-7);
}

// Nearly boxes (n = 50) stacked along z, their centres outside each other: the least
// penetration is along z, cA + cB - dz (a superquadric's support along a body axis is the
// semi-axis), against 2 a - dx = 2 along x.
TEST(LeastPenetration, EpaFindsTheFaceOfStackedBlocks) {
  const Superquadric block(1.0, 0.8, 0.6, 50.0, 50.0);
  const Pose above{Vec3(0.05, -0.03, 1.0), Quat::Identity()};
  const detail::PairFrame f = frameOf(block, Pose{}, block, above);
  const std::optional<detail::Penetration> p = detail::penetrationDepth(f, 1e-8);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->converged);
  EXPECT_NEAR(p->upperBound, 0.2, 1e-8);
  EXPECT_LE(p->lowerBound, 0.2 + 1e-15);
  EXPECT_LE(p->upperBound - p->lowerBound, 1e-8 * f.lengthScale);
  EXPECT_GT(p->normal.z(), 1.0 - 1e-6);
  const ContactGeometry g = detectContact(block, Pose{}, block, above);
  ASSERT_TRUE(g.converged());
  EXPECT_NEAR(g.overlap, 0.2, 1e-8);
}

// Planted contacts (random_pairs.hpp: any orientation, n up to 20, axes to 1:10) opened by a gap
// of 1e-9 .. 1e-3 L: EPA finds the separating plane every time.
TEST(LeastPenetration, EpaFindsNothingBetweenSeparatedBodies) {
  testing::PairGenerator generator(31);
  generator.maxExponent = 20.0;
  generator.minAxisRatio = 0.1;
  for (int k = 0; k < 500; ++k) {
    testing::PlantedPair p = generator.next();
    const double L = referenceVolumeRadius(p.A, p.B);
    p.poseB.position += (p.overlap + L * std::pow(10.0, generator.uniform(-9.0, -3.0))) * p.normal;
    EXPECT_FALSE(detail::penetrationDepth(frameOf(p.A, p.poseA, p.B, p.poseB), 1e-8)) << k;
  }
}

// Issue 31's pair: moved along its own normal to an overlap of 5e-12 R_vol, it was reported
// converged with an overlap of 1.763 m (a far-side stationary pair). Now: the least penetration,
// inside EPA's bounds and the common-normal conditions, overlapping by a few 1e-12 m.
const Superquadric issueA(0.3291293774088193, 1.7369970270982558, 3.2912937740881945, 14.92, 2.861);
const Superquadric issueB(0.2790246973542518, 1.0181840337749348, 0.5141693341749003, 9.483, 3.256);
const Pose issuePoseA = pose(Vec3::Zero(), -0.03978581319745961, -0.10727511341957581, -0.06962367983375943,
                             0.9909902533907385);
const Pose issuePoseB = pose(Vec3(-1.189048365605069, 0.896967465028223, -0.21711496857424606), -0.89389394759067,
                             0.19208483161275805, 0.07429822733101987, -0.3981668009020028);

TEST(LeastPenetration, IssuePairIsTheNearTouchNotTheFarSide) {
  DetectorSettings settings;
  settings.cutoff = 0.0005266535708168674;
  const ContactGeometry g = detectContact(issueA, issuePoseA, issueB, issuePoseB, settings);
  const double L = referenceVolumeRadius(issueA, issueB);
  ASSERT_TRUE(g.converged()) << describe(g.status);
  EXPECT_GT(g.overlap, 0.0);
  EXPECT_LT(g.overlap, 5e-12 * std::min(issueA.volumeEquivalentRadius(), issueB.volumeEquivalentRadius()));
  EXPECT_LT(testing::commonNormalError(issueA, issuePoseA, issueB, issuePoseB, g, L), 1e-8 * L);
  EXPECT_NEAR(supportGap(issueA, issuePoseA, issueB, issuePoseB, g.normal), g.overlap, 1e-14 * L);
  const std::optional<detail::Penetration> p =
      detail::penetrationDepth(frameOf(issueA, issuePoseA, issueB, issuePoseB), 1e-8);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->converged);
  EXPECT_LE(p->lowerBound, g.overlap + 1e-14 * L);
  EXPECT_GE(p->upperBound, g.overlap - 1e-14 * L);
}

// The far-side pair of issue 31 handed over as a warm start: Newton stays on it (it is a
// stationary pair), its overlap jumps from the previous 0 to 1.76 m, so it is judged as a new
// pair's and the near touch is found.
TEST(LeastPenetration, WarmAnswerThatJumpedIsChecked) {
  const Vec3 farA(0.006725826869506346, 1.7329339747865407, -0.017768181729727717);
  const Vec3 farB(-0.8915254233571103, 0.2730747001947115, -0.4312109824634134);
  const WarmStart previous{issuePoseA.toBody(farA), issuePoseB.toBody(farB), 0.0};
  DetectorSettings settings;
  settings.cutoff = 0.0005266535708168674;
  const ContactGeometry g = detectContact(issueA, issuePoseA, issueB, issuePoseB, settings, previous);
  ASSERT_TRUE(g.converged()) << describe(g.status);
  EXPECT_GT(g.overlap, 0.0);
  EXPECT_LT(g.overlap, 1e-11);
}

// A thin plate B (b = 0.094 m across the normal) in a block A: the least penetration, 0.2134 m
// (EPA's bounds, and no deeper than a brute-force direction search), pushes B out sideways, so
// A's point lies outside B; the descent from the line of centres alone stopped at 0.2228 m.
TEST(LeastPenetration, ThinPlateLeastPenetrationWithAPointOutside) {
  const Superquadric A(1.6285777741362593, 1.6055835137688539, 1.0942855530238915, 12.356431885023483, 19.59256321832607);
  const Superquadric B(0.9257433849841602, 0.093721713479652191, 0.48676766613739653, 12.726627573114294, 14.491761347624131);
  const Pose pa = pose(Vec3(-0.33413612816527738, 0.63978408866452363, 0.54352153215319898), 0.88920501452736456,
                       0.17543654140457721, 0.33155864390614542, -0.26192618756151026);
  const Pose pb = pose(Vec3(2.3466521439205783, 0.29732122234361696, -0.20543908136559652), -0.37344507700946905,
                       -0.1627875537124934, 0.69656586241182128, -0.59062254116835855);
  const ContactGeometry g = detectContact(A, pa, B, pb);
  const double L = referenceVolumeRadius(A, B);
  ASSERT_TRUE(g.converged()) << describe(g.status);
  const std::optional<detail::Penetration> p = detail::penetrationDepth(frameOf(A, pa, B, pb), 1e-8);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->converged);
  EXPECT_LE(p->upperBound - p->lowerBound, 1e-8 * L);
  EXPECT_GE(g.overlap, p->lowerBound - 1e-14 * L);
  EXPECT_LE(g.overlap, p->upperBound + 1e-8 * L);
  EXPECT_LE(g.overlap, testing::searchedLeastOverlap(A, pa, B, pb) + 1e-8 * L);
  EXPECT_GT(B.gauge(pb.toBody(g.pointA)), 1.1);  // A's point beyond the plate
  EXPECT_LT(testing::commonNormalError(A, pa, B, pb, g, L), 1e-8 * L);
}

// Two n = 8 cubes, B slid from above A (least penetration along z) to beside it (along x): a
// warm start from the z contact whose overlap jumped (0.5 -> 0.69 m: more than 1e-2 L) is judged
// as a new pair's, so the answer is the least penetration along x; one that continues its last
// overlap keeps its branch, the z face (detector.hpp: a warm pair follows its branch).
TEST(LeastPenetration, WarmPairJudgedWhenItJumpsFollowsItsBranchOtherwise) {
  const Superquadric cube(1.0, 1.0, 1.0, 8.0, 8.0);
  const Pose above{Vec3(1.2, 0.01, 1.5), Quat::Identity()}, beside{Vec3(1.41, 0.01, 1.29), Quat::Identity()};
  const ContactGeometry start = detectContact(cube, Pose{}, cube, above);
  ASSERT_TRUE(start.converged());
  ASSERT_GT(start.normal.z(), 0.9);
  const ContactGeometry zFace = detectContact(cube, Pose{}, cube, beside, {}, WarmStart{start.localPointA, start.localPointB, start.overlap + 0.2});
  ASSERT_TRUE(zFace.converged());
  EXPECT_GT(zFace.normal.z(), 0.9);  // continued: 0.69 m along z, though x is shallower
  const ContactGeometry jumped = detectContact(cube, Pose{}, cube, beside, {}, WarmStart{start.localPointA, start.localPointB, start.overlap});
  ASSERT_TRUE(jumped.converged()) << describe(jumped.status);
  EXPECT_GT(jumped.normal.x(), 0.9);
  const std::optional<detail::Penetration> p = detail::penetrationDepth(frameOf(cube, Pose{}, cube, beside), 1e-8);
  ASSERT_TRUE(p && p->converged);
  EXPECT_LT(jumped.overlap, zFace.overlap - 0.05);
  EXPECT_GE(jumped.overlap, p->lowerBound - 1e-12);
  EXPECT_LE(jumped.overlap, p->upperBound + 1e-8);
}

}  // namespace
}  // namespace sqdem
