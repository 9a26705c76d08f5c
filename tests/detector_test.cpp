// Common-normal detector (detector.hpp): closed forms, invariances (swap, rigid motion),
// planes, culling, warm starts and degenerate input; the Newton step's 4 x 4 LU against Eigen's.

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <random>

#include "contact/pivoted_lu.hpp"

#include "sqdem/contact/detector.hpp"
#include "support/random_pairs.hpp"

namespace sqdem {
namespace {

Pose at(const Vec3& position, const Quat& q = Quat::Identity()) { return {position, q}; }

// The hand-written fixed-size LU (pivoted_lu.hpp) solves as Eigen's PartialPivLU does, pivots
// included (the same row exchanges), and flags a singular matrix as not well-conditioned.
TEST(Detector, NewtonStepLuMatchesEigen) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Matrix4d m = Eigen::Matrix4d::NullaryExpr([&] { return u(rng); });
    const Eigen::Vector4d b = Eigen::Vector4d::NullaryExpr([&] { return u(rng); });
    const detail::PivotedLu<4> lu(m);
    const Eigen::PartialPivLU<Eigen::Matrix4d> eigen(m);
    const Eigen::Vector4d x = lu.solve(b), reference = eigen.solve(b);
    EXPECT_LE((x - reference).norm(), 1e-12 * (1.0 + reference.norm())) << m;
    EXPECT_LE((m * x - b).norm(), 1e-13 * (m.norm() * x.norm() + b.norm()));  // backward stable
    const Eigen::Vector4d pivots = eigen.matrixLU().diagonal().cwiseAbs();
    EXPECT_EQ(lu.wellConditioned(1e-6), pivots.minCoeff() > 1e-6 * pivots.maxCoeff());
  }
  Eigen::Matrix4d singular = Eigen::Matrix4d::Identity();
  singular.row(3) = singular.row(1) + 2.0 * singular.row(2);
  EXPECT_FALSE(detail::PivotedLu<4>(singular).wellConditioned(1e-6));
}

TEST(Detector, SphereSphereClosedForm) {
  const Superquadric A = Superquadric::sphere(1.0), B = Superquadric::sphere(0.5);
  const ContactGeometry g = detectContact(A, at(Vec3::Zero()), B, at(Vec3(0.9, 1.2, 0.0)));
  ASSERT_TRUE(g.converged());
  EXPECT_NEAR(g.overlap, 1.5 - 1.5, 1e-15);
  const ContactGeometry h = detectContact(A, at(Vec3::Zero()), B, at(Vec3(0.6, 0.8, 0.0)));
  EXPECT_NEAR(h.overlap, 0.5, 1e-15);
  EXPECT_NEAR((h.normal - Vec3(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((h.pointA - Vec3(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(h.curvatureA.k1, 1.0, 1e-15);
  EXPECT_NEAR(h.curvatureB.k2, 2.0, 1e-15);
  EXPECT_EQ(h.iterations, 0);
}

TEST(Detector, NearSpheresThroughTheIterativePathMatchSphereOverlap) {
  // An ellipsoid within 1e-12 of a sphere takes the general path; overlap must be r1 + r2 - d.
  const Superquadric A(1.0, 1.0, 1.0 + 1e-12, 2.0, 2.0), B(0.5, 0.5 + 1e-12, 0.5, 2.0, 2.0);
  const Vec3 d = Vec3(0.3, -0.4, 1.2).normalized() * 1.49;
  const ContactGeometry g = detectContact(A, at(Vec3::Zero()), B, at(d));
  ASSERT_TRUE(g.converged()) << describe(g.status);
  EXPECT_NEAR(g.overlap, 0.01, 1e-10);
  EXPECT_NEAR(g.normal.dot(d.normalized()), 1.0, 1e-10);
}

TEST(Detector, SwappingBodiesGivesSameOverlapAndOppositeNormal) {
  testing::PairGenerator gen(99);
  for (int k = 0; k < 300; ++k) {
    const testing::PlantedPair p = gen.next();
    const double L = referenceVolumeRadius(p.A, p.B);
    const ContactGeometry ab = detectContact(p.A, p.poseA, p.B, p.poseB);
    const ContactGeometry ba = detectContact(p.B, p.poseB, p.A, p.poseA);
    ASSERT_TRUE(ab.converged() && ba.converged());
    EXPECT_NEAR(ab.overlap, ba.overlap, 1e-9 * L);
    EXPECT_NEAR((ab.normal + ba.normal).norm(), 0.0, 1e-7);
    // Planted face-on-face pairs sit exactly at face centres, where the curvature of an
    // n1 = 2 < n2 pole is direction-dependent (superquadric.hpp): compare curvatures elsewhere.
    if (p.kind == testing::PairKind::FaceOnFace) continue;
    EXPECT_NEAR(ab.curvatureA.k1, ba.curvatureB.k1, 1e-6 * (1 + ab.curvatureA.k1));
    EXPECT_NEAR(ab.curvatureB.k2, ba.curvatureA.k2, 1e-6 * (1 + ab.curvatureB.k2));
  }
}

TEST(Detector, RigidMotionOfThePairChangesNothing) {
  testing::PairGenerator gen(5);
  for (int k = 0; k < 300; ++k) {
    const testing::PlantedPair p = gen.next();
    const double L = referenceVolumeRadius(p.A, p.B);
    const Quat q = gen.randomRotation();
    const Vec3 t(1e3, -2e3, 5e2);
    const auto move = [&](const Pose& pose) { return Pose{q * pose.position + t, q * pose.orientation}; };
    const ContactGeometry g = detectContact(p.A, p.poseA, p.B, p.poseB);
    const ContactGeometry h = detectContact(p.A, move(p.poseA), p.B, move(p.poseB));
    ASSERT_TRUE(g.converged() && h.converged());
    EXPECT_NEAR(g.overlap, h.overlap, 1e-9 * L);
    EXPECT_NEAR((q * g.normal - h.normal).norm(), 0.0, 1e-7);
    if (p.kind == testing::PairKind::FaceOnFace) continue;  // see the swap test
    EXPECT_NEAR(g.curvatureA.k1, h.curvatureA.k1, 1e-6 * (1 + g.curvatureA.k1));
    EXPECT_NEAR(g.curvatureA.k2, h.curvatureA.k2, 1e-6 * (1 + g.curvatureA.k1));
    EXPECT_NEAR(g.curvatureB.k1, h.curvatureB.k1, 1e-6 * (1 + g.curvatureB.k1));
    EXPECT_NEAR(g.curvatureB.k2, h.curvatureB.k2, 1e-6 * (1 + g.curvatureB.k1));
  }
}

TEST(Detector, EllipsoidOnPlaneClosedForm) {
  // Support function of an ellipsoid: h(n) = sqrt(n^T R diag(a^2,b^2,c^2) R^T n).
  const Superquadric e = Superquadric::ellipsoid(1.0, 0.5, 0.25);
  const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  const Plane floor{Vec3(0, 0, -0.2), Vec3::UnitZ()};
  const ContactGeometry g = detectContact(e, at(Vec3::Zero(), q), floor);
  const Mat3 R = q.toRotationMatrix();
  const Vec3 down(0, 0, -1);
  const double h = std::sqrt(down.dot(R * Vec3(1, 0.25, 0.0625).asDiagonal() * R.transpose() * down));
  ASSERT_TRUE(g.converged());
  EXPECT_NEAR(g.overlap, h - 0.2, 1e-14);
  EXPECT_NEAR((g.normal - down).norm(), 0.0, 1e-15);
  EXPECT_NEAR(g.pointB.z(), -0.2, 1e-14);
  EXPECT_EQ(g.curvatureB.k1, 0.0);
  // Axis-aligned: the lowest point is the c tip, curvatures c/a^2 and c/b^2.
  const ContactGeometry t = detectContact(e, at(Vec3::Zero()), floor);
  EXPECT_NEAR(t.curvatureA.k1, 0.25 / 0.25, 1e-12);
  EXPECT_NEAR(t.curvatureA.k2, 0.25 / 1.0, 1e-12);
  // Lifted clear of the plane: separated beyond the cut-off, a gap within it.
  EXPECT_EQ(detectContact(e, at(Vec3(0, 0, 0.5)), floor).status, ContactStatus::Separated);
  DetectorSettings s;
  s.cutoff = 1.0;
  const ContactGeometry gap = detectContact(e, at(Vec3(0, 0, 0.5)), floor, s);
  EXPECT_TRUE(gap.converged());
  EXPECT_NEAR(gap.overlap, -0.45, 1e-14);
}

TEST(Detector, SuperquadricFaceOnPlane) {
  const Superquadric cube(1.0, 1.0, 1.0, 10.0, 10.0);
  const ContactGeometry g = detectContact(cube, at(Vec3(0, 0, 0.99)), Plane{});
  ASSERT_TRUE(g.converged());
  EXPECT_NEAR(g.overlap, 0.01, 1e-14);
  EXPECT_NEAR(g.curvatureA.k1, 0.0, 1e-12);  // face centre is flat
}

TEST(Detector, CullsDistantPairsWithoutIterating) {
  const Superquadric A(1.0, 0.3, 0.3, 4.0, 4.0);
  const ContactGeometry far = detectContact(A, at(Vec3::Zero()), A, at(Vec3(10, 0, 0)));
  EXPECT_EQ(far.status, ContactStatus::Separated);
  EXPECT_EQ(far.iterations, 0);
  EXPECT_LE(far.overlap, -(10 - 2 * A.boundingRadius()) + 1e-12);
  // Parallel needles side by side: bounding spheres overlap, oriented boxes do not.
  const ContactGeometry side = detectContact(A, at(Vec3::Zero()), A, at(Vec3(0, 0.7, 0)));
  EXPECT_EQ(side.status, ContactStatus::Separated);
  EXPECT_EQ(side.iterations, 0);
}

TEST(Detector, WarmStartAfterSmallMotionNeedsAtMostTwoIterations) {
  testing::PairGenerator gen(17);
  DetectorSettings s;
  long iterations = 0, count = 0;
  for (int k = 0; k < 500; ++k) {
    const testing::PlantedPair p = gen.next();
    if (p.kind == testing::PairKind::FaceOnFace) continue;
    const double L = referenceVolumeRadius(p.A, p.B);
    s.cutoff = 0.1 * L;
    const ContactGeometry g = detectContact(p.A, p.poseA, p.B, p.poseB, s);
    Pose moved = p.poseB;  // a DEM-like step: 1e-5 rad and 1e-6 L
    moved.orientation = Quat(Eigen::AngleAxisd(1e-5, gen.randomUnit())) * moved.orientation;
    moved.position += 1e-6 * L * gen.randomUnit();
    const ContactGeometry w = detectContact(p.A, p.poseA, p.B, moved, s, g);
    ASSERT_TRUE(w.converged());
    iterations += w.iterations;
    ++count;
  }
  EXPECT_LE(double(iterations) / count, 2.0);
}

TEST(Detector, DegenerateInputNeverProducesNaN) {
  const Superquadric A(1.0, 0.5, 0.5, 6.0, 6.0);
  for (const ContactGeometry& g : {detectContact(A, at(Vec3::Zero()), A, at(Vec3::Zero())),
                                   detectContact(Superquadric::sphere(1), at(Vec3::Zero()),
                                                 Superquadric::sphere(1), at(Vec3::Zero()))}) {
    EXPECT_TRUE(g.pointA.allFinite() && g.normal.allFinite() && std::isfinite(g.overlap));
    EXPECT_TRUE(std::isfinite(g.curvatureA.k1) && std::isfinite(g.residual));
  }
}

}  // namespace
}  // namespace sqdem
