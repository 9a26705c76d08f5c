// Particle against an infinite cylinder (detector.hpp, cylinder_detector.cpp): the sphere's
// closed form, the common-normal conditions of every solution (normals antiparallel and normal
// to the axis, B's point on the cylinder, the points joined along the normal by the overlap),
// the overlap against an exhaustive scan of separating directions, warm = cold, the flat limit
// against the plane, the cylinder's curvatures, and the cut-off.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "sqdem/contact/detector.hpp"

namespace sqdem {
namespace {

Quat randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}

/// The largest signed distance from A to the cylinder over 20,000 directions normal to the
/// axis: a scan independent of the detector's search (the separating-axis definition).
double scannedGap(const Superquadric& A, const Pose& pose, const Cylinder& c) {
  const Vec3 d = -c.fromAxis(pose.position);
  const Vec3 e1 = c.axis.unitOrthogonal(), e2 = c.axis.cross(e1);
  const Mat3 R = pose.rotation();
  double best = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 20000; ++k) {
    const double t = 2.0 * std::numbers::pi * k / 20000.0;
    const Vec3 n = std::cos(t) * e1 + std::sin(t) * e2;
    best = std::max(best, n.dot(d - R * A.supportPoint(R.transpose() * n)) - c.radius);
  }
  return best;
}

void expectCommonNormal(const ContactGeometry& g, const Superquadric& A, const Pose& pose, const Cylinder& c) {
  ASSERT_TRUE(g.converged());
  const Vec3 nA = pose.rotation() * A.outwardNormal(g.localPointA);
  EXPECT_LT((nA - g.normal).norm(), 1e-7) << "A's normal at its point is the contact normal";
  EXPECT_LT(std::abs(g.normal.dot(c.axis)), 1e-15) << "the normal is normal to the axis";
  EXPECT_LT((c.outwardNormal(g.pointB) + g.normal).norm(), 1e-7) << "B's normal is antiparallel";
  EXPECT_NEAR(c.distance(g.pointB), 0.0, 1e-12 * c.radius) << "B's point on the cylinder";
  EXPECT_LT((g.pointB - g.pointA + g.overlap * g.normal).norm(), 1e-14) << "pB - pA = -overlap n";
  EXPECT_LT((pose.toWorld(g.localPointA) - g.pointA).norm(), 1e-14);
  EXPECT_LT(std::abs(A.gauge(g.localPointA) - 1.0), 1e-12) << "A's point on A";
}

TEST(CylinderDetector, SphereClosedForm) {
  const Superquadric A = Superquadric::sphere(0.5);
  const Cylinder c{Vec3(0.0, 3.0, 2.0), Vec3::UnitY(), 1.5};
  const ContactGeometry g = detectContact(A, Pose{Vec3(1.2, -4.0, 0.4), Quat::Identity()}, c);
  ASSERT_TRUE(g.converged());
  const Vec3 d(-1.2, 0.0, 1.6);  // from the centre to the axis, normal to it: |d| = 2
  EXPECT_NEAR(g.overlap, 0.5 + 1.5 - 2.0, 1e-15);
  EXPECT_LT((g.normal - d / 2.0).norm(), 1e-15);
  EXPECT_LT((g.pointA - (Vec3(1.2, -4.0, 0.4) + 0.5 * d / 2.0)).norm(), 1e-15);
  EXPECT_EQ(g.iterations, 0);
  const ContactGeometry h = detectContact(A, Pose{Vec3(1.2, -4.0, 0.45), Quat::Identity()}, c);
  ASSERT_TRUE(h.converged());
  EXPECT_NEAR(h.overlap, 2.0 - std::hypot(1.2, 1.55), 1e-15);
  EXPECT_NEAR(h.curvatureA.k1, 2.0, 1e-12);
  EXPECT_NEAR(h.curvatureA.k2, 2.0, 1e-12);
  // A warm start changes nothing for a sphere: the closed form does not search.
  const WarmStart old{Vec3(0.5, 0.0, 0.0), Vec3::Zero(), 0.01};
  const ContactGeometry w = detectContact(A, Pose{Vec3(1.2, -4.0, 0.45), Quat::Identity()}, c, {}, &old);
  EXPECT_EQ(w.normal, h.normal);
  EXPECT_EQ(w.overlap, h.overlap);
  EXPECT_EQ(w.pointA, h.pointA);
}

// Ellipsoids and n = 2..8 superquadrics in random poses near random cylinders.
TEST(CylinderDetector, CommonNormalAndSeparatingAxisMaximum) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Superquadric shapes[] = {Superquadric(1.0, 0.6, 1.5, 2.0, 2.0), Superquadric(0.8, 1.0, 0.5, 4.0, 3.0),
                                 Superquadric(1.0, 1.0, 1.8, 8.0, 8.0), Superquadric(0.5, 0.7, 1.2, 2.0, 6.0)};
  int solved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Superquadric& A = shapes[trial % 4];
    const Vec3 axis = Vec3(u(rng), u(rng), u(rng)).normalized();
    const Cylinder c{Vec3(u(rng), u(rng), u(rng)), axis, 0.5 + 2.0 * (u(rng) + 1.0)};
    const Pose pose{Vec3::Zero(), randomRotation(rng)};
    // Put A's centre at a distance from the axis that gives a gap or an overlap up to a third
    // of its smallest half-width.
    const Vec3 off = axis.unitOrthogonal();
    Pose placed = pose;
    placed.position = c.point + (c.radius + A.boundingRadius()) * off;
    const double gap0 = scannedGap(A, placed, c);
    placed.position -= (gap0 + 0.33 * A.halfExtents().minCoeff() * u(rng)) * off;
    const ContactGeometry g = detectContact(A, placed, c, {.cutoff = 1.0});
    expectCommonNormal(g, A, placed, c);
    // f is Lipschitz in theta with |d - s_A| <= |d| + A's bounding radius: the scan's step
    // bounds how far below the maximum it may stay.
    const double lipschitz = c.fromAxis(placed.position).norm() + A.boundingRadius();
    const double scanned = scannedGap(A, placed, c);
    EXPECT_NEAR(-g.overlap, scanned, lipschitz * std::numbers::pi / 20000.0) << "trial " << trial;
    EXPECT_GT(-g.overlap + 1e-15, scanned) << "the scan never beats the search";
    EXPECT_LT(g.iterations, 60);
    ++solved;
  }
  EXPECT_EQ(solved, 200);
}

TEST(CylinderDetector, WarmStartFindsTheColdSolution) {
  std::mt19937_64 rng(3);
  const Superquadric A(1.0, 0.6, 1.5, 4.0, 4.0);
  const Cylinder c{Vec3::Zero(), Vec3::UnitX(), 2.0};
  Pose pose{Vec3(0.3, 0.0, -3.2), randomRotation(rng)};
  const ContactGeometry first = detectContact(A, pose, c, {.cutoff = 1.0});
  ASSERT_TRUE(first.converged());
  // Move and turn A a little, as one step does; the warm search starts at the last normal.
  pose.position += Vec3(0.01, 0.02, -0.01);
  pose.orientation = (Quat(Eigen::AngleAxisd(0.02, Vec3(1, 2, 3).normalized())) * pose.orientation).normalized();
  const WarmStart warm{first.localPointA, first.localPointB, first.overlap};
  const ContactGeometry w = detectContact(A, pose, c, {.cutoff = 1.0}, &warm);
  const ContactGeometry cold = detectContact(A, pose, c, {.cutoff = 1.0});
  ASSERT_TRUE(w.converged());
  EXPECT_NEAR(w.overlap, cold.overlap, 1e-12);
  EXPECT_LT((w.normal - cold.normal).norm(), 1e-7);
  EXPECT_LT(w.iterations, cold.iterations);
}

// A cylinder of radius 1e6 R seen by a particle is its tangent plane to O(R / radius).
TEST(CylinderDetector, FlatLimitIsThePlane) {
  std::mt19937_64 rng(9);
  const Superquadric A(1.0, 0.6, 1.5, 2.0, 2.0);
  const double radius = 1e6;
  const Cylinder c{Vec3(0.0, 0.0, -radius - 1.0), Vec3::UnitY(), radius};
  const Plane top{Vec3(0.0, 0.0, -1.0), Vec3::UnitZ()};
  const Pose pose{Vec3(0.0, 0.0, 0.2), randomRotation(rng)};
  const ContactGeometry g = detectContact(A, pose, c), p = detectContact(A, pose, top);
  ASSERT_TRUE(g.converged());
  ASSERT_TRUE(p.converged());
  EXPECT_NEAR(g.overlap, p.overlap, 1e-5);
  EXPECT_LT((g.normal - p.normal).norm(), 1e-5);
  EXPECT_LT((g.pointA - p.pointA).norm(), 1e-5);
}

TEST(CylinderDetector, TheCylindersCurvatures) {
  const Superquadric A(1.0, 0.6, 1.5, 2.0, 2.0);
  const Cylinder c{Vec3(5.0, 0.0, 0.0), Vec3(0.0, 0.6, 0.8), 2.5};
  const ContactGeometry g = detectContact(A, Pose{Vec3(1.8, 0.0, 0.0), Quat::Identity()}, c);
  ASSERT_TRUE(g.converged());
  EXPECT_DOUBLE_EQ(g.curvatureB.k1, 1.0 / 2.5);
  EXPECT_EQ(g.curvatureB.k2, 0.0);
  EXPECT_LT(std::abs(g.curvatureB.d1.dot(c.axis)), 1e-15);
  EXPECT_LT((g.curvatureB.d2 - c.axis).norm(), 1e-15);
  EXPECT_LT((g.curvatureB.d1.cross(g.curvatureB.d2) + g.normal).norm(), 1e-15) << "d1 x d2 = B's outward normal";
  EXPECT_GT(g.curvatureA.k1, 0.0);  // A's own, from its surface
}

TEST(CylinderDetector, CutOff) {
  const Superquadric A = Superquadric::sphere(1.0);
  const Cylinder c{Vec3::Zero(), Vec3::UnitZ(), 1.0};
  const Pose pose{Vec3(2.5, 0.0, 0.0), Quat::Identity()};
  EXPECT_EQ(detectContact(A, pose, c, {.cutoff = 0.4}).status, ContactStatus::Separated);
  const ContactGeometry within = detectContact(A, pose, c, {.cutoff = 0.6});
  ASSERT_TRUE(within.converged());
  EXPECT_NEAR(within.overlap, -0.5, 1e-15);
  EXPECT_EQ(detectContact(A, Pose{Vec3(0.5, 0.0, 0.0), Quat::Identity()}, c).status, ContactStatus::Degenerate);
}

// A finite cylinder (rounded ends, halfLength 2 along y): beside the barrel it is the infinite
// one bit for bit; beyond an end a sphere meets the end's hemisphere in closed form (the sphere
// pair: overlap r + R - |x - c|, normal towards the end's centre c, the hemisphere's curvatures
// 1/R); a body far beyond the end, which the infinite cylinder would hold, is separated.
TEST(CylinderDetector, FiniteCylinderHasRoundedEnds) {
  Cylinder c{Vec3(0.0, 1.0, 0.0), Vec3::UnitY(), 1.0};
  const Cylinder infinite = c;
  c.halfLength = 2.0;
  const Superquadric ellipsoid(0.6, 0.4, 0.3, 2.0, 2.0);
  const Pose beside{Vec3(1.1, 1.5, 0.5), Quat(0.9, 0.1, 0.3, -0.2).normalized()};
  const ContactGeometry onBarrel = detectContact(ellipsoid, beside, c), reference = detectContact(ellipsoid, beside, infinite);
  ASSERT_TRUE(onBarrel.converged());
  EXPECT_EQ(onBarrel.overlap, reference.overlap);
  EXPECT_EQ(onBarrel.normal, reference.normal);
  EXPECT_EQ(onBarrel.pointB, reference.pointB);

  const Superquadric ball = Superquadric::sphere(0.5);
  const Vec3 x(0.3, 3.8, 0.9), end(0.0, 3.0, 0.0);  // beyond the end at y = 1 + 2
  const ContactGeometry g = detectContact(ball, Pose{x, Quat::Identity()}, c);
  ASSERT_TRUE(g.converged());
  EXPECT_NEAR(g.overlap, 1.5 - (x - end).norm(), 1e-12);
  EXPECT_LT((g.normal - (end - x).normalized()).norm(), 1e-10);
  EXPECT_LT((g.pointB - (end + (x - end).normalized())).norm(), 1e-10);
  EXPECT_EQ(g.localPointB, g.pointB);  // a wall keeps world-frame points
  EXPECT_NEAR(g.curvatureB.k1, 1.0, 1e-9);
  EXPECT_NEAR(g.curvatureB.k2, 1.0, 1e-9);
  EXPECT_EQ(detectContact(ball, Pose{Vec3(1.2, 4.5, 0.0), Quat::Identity()}, infinite).status, ContactStatus::Converged);
  EXPECT_EQ(detectContact(ball, Pose{Vec3(1.2, 4.5, 0.0), Quat::Identity()}, c).status, ContactStatus::Separated);
}

// The overlap of an ellipsoid sliding along the axis across the barrel's end is continuous: the
// barrel's and the hemisphere's solutions agree where they meet.
TEST(CylinderDetector, FiniteCylinderBarrelMeetsItsEnd) {
  Cylinder c{Vec3::Zero(), Vec3::UnitY(), 1.0};
  c.halfLength = 2.0;
  const Superquadric A(0.6, 0.4, 0.3, 2.0, 2.0);
  const Quat q = Quat(0.9, 0.1, 0.3, -0.2).normalized();
  double previous = NAN, largestJump = 0.0, largest = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const double y = 1.5 + 1.0 * k / 400.0;  // the centre from 0.5 inside to 0.5 beyond the end
    const ContactGeometry g = detectContact(A, Pose{Vec3(1.2, y, 0.3), q}, c);
    ASSERT_TRUE(g.converged()) << "y = " << y;
    if (k > 0) largestJump = std::max(largestJump, std::abs(g.overlap - previous));
    largest = std::max(largest, g.overlap);
    previous = g.overlap;
  }
  std::printf("across the end: largest overlap %.4f, largest change between neighbours %.2e\n", largest, largestJump);
  EXPECT_LT(largestJump, 2e-3);  // 1/400 of the travel: a smooth change, no jump at the switch
}

// A flat-ended finite cylinder (radius 1, barrel y in [-1, 3]): a sphere anywhere around it
// meets it with overlap r - dist(centre, solid cylinder) (closed form: the radial and axial
// excesses over the barrel, max(rho - R, 0) and max(|y - 1| - 2, 0), combined by Pythagoras),
// on the barrel, a disc or a rim; an ellipsoid at a rim meets the common-normal conditions.
TEST(CylinderDetector, FlatEndsAreDiscsWithRims) {
  Cylinder c{Vec3(0.0, 1.0, 0.0), Vec3::UnitY(), 1.0};
  c.halfLength = 2.0;
  c.flatEnds = true;
  const double r = 0.4;
  const Superquadric ball = Superquadric::sphere(r);
  const auto distance = [&](const Vec3& x) {
    const double rho = std::hypot(x.x(), x.z()), axial = std::abs(x.y() - 1.0);
    return std::hypot(std::max(rho - 1.0, 0.0), std::max(axial - 2.0, 0.0));
  };
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5), v(-1.5, 3.5);
  int barrel = 0, disc = 0, rim = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vec3 x(u(rng), v(rng), u(rng));
    const double d = distance(x);
    if (d < 0.05 || d > 0.95 * r) continue;
    const ContactGeometry g = detectContact(ball, Pose{x, Quat::Identity()}, c);
    ASSERT_TRUE(g.converged()) << x.transpose();
    EXPECT_NEAR(g.overlap, r - d, 1e-12) << x.transpose();
    EXPECT_NEAR(distance(g.pointB), 0.0, 1e-12);
    const double rho = std::hypot(x.x(), x.z()), axial = std::abs(x.y() - 1.0);
    barrel += axial <= 2.0;
    disc += rho <= 1.0;
    rim += axial > 2.0 && rho > 1.0;
  }
  EXPECT_GT(barrel, 50);
  EXPECT_GT(disc, 50);
  EXPECT_GT(rim, 50);

  const Superquadric A(0.6, 0.4, 0.3, 2.0, 2.0);
  const Pose atRim{Vec3(1.15, 3.2, 0.1), Quat(0.9, 0.1, 0.3, -0.2).normalized()};
  const ContactGeometry g = detectContact(A, atRim, c);
  ASSERT_TRUE(g.touching());
  EXPECT_NEAR(g.pointB.y(), 3.0, 1e-12);  // on the rim: the end's plane, at the radius
  EXPECT_NEAR(std::hypot(g.pointB.x(), g.pointB.z()), 1.0, 1e-12);
  EXPECT_NEAR(g.normal.dot(Vec3(-g.pointB.z(), 0.0, g.pointB.x())), 0.0, 1e-7);  // normal to the rim (Brent's angle: ~1.5e-8)
  EXPECT_NEAR((atRim.rotation() * A.outwardNormal(g.localPointA)).dot(g.normal), 1.0, 1e-12);
  EXPECT_LT(((g.pointB - g.pointA) + g.overlap * g.normal).norm(), 1e-8);
}

}  // namespace
}  // namespace sqdem
