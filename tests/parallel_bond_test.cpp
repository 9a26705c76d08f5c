// The parallel bond (mechanics/parallel_bond.hpp, bond_frame.hpp) against the beam formulas of
// Potyondy & Cundall (2004), Eqs. 10-11: a bond of radius R between two spheres, loaded by moving
// B alone in tension, shear, bending and twisting; its breakage at the strengths; a rigid motion
// of both bodies leaves it undeformed.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sqdem/mechanics/bond_frame.hpp"

namespace sqdem {
namespace {

constexpr double r = 5e-6;            // the spheres' radius (m)
constexpr double R = 0.8 * r;         // the bond's radius (lambda = 0.8)
const ParallelBond bond{.radiusMultiplier = 0.8, .normalStiffness = 2e16, .shearStiffness = 0.8e16, .tensileStrength = 30e6,
                        .shearStrength = 45e6};
const BondSection section(R);

// A at the origin, B touching it along n = (1, 2, 2)/3, both turned arbitrarily: the bond forms at
// the touching point.
struct Pair {
  Vec3 n = Vec3(1.0, 2.0, 2.0) / 3.0;
  Pose A{Vec3::Zero(), Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, -1.0, 0.5).normalized()))};
  Pose B{2.0 * r * n, Quat(Eigen::AngleAxisd(-1.1, Vec3(0.2, 1.0, 0.3).normalized()))};
  Vec3 point = r * n;
  BondRest rest = BondRest::formed(A, B, point, n);
  /// Two unit vectors normal to n.
  Vec3 s = n.unitOrthogonal(), t = n.cross(n.unitOrthogonal());

  /// B turned by the rotation vector theta about the bond's point (the point stays).
  void turnB(const Vec3& theta) {
    const Quat q(Eigen::AngleAxisd(theta.norm(), theta.normalized()));
    B.position = point + q * (B.position - point);
    B.orientation = (q * B.orientation).normalized();
  }
  BondLoads loads() const { return bondLoads(bond, section, bondPlace(rest, A, B).deformation); }
};

TEST(ParallelBond, SectionIsACircleOfRadiusR) {
  EXPECT_DOUBLE_EQ(section.area, std::numbers::pi * R * R);
  EXPECT_DOUBLE_EQ(section.inertia, std::numbers::pi * std::pow(R, 4) / 4.0);
  EXPECT_DOUBLE_EQ(section.polar, 2.0 * section.inertia);
}

TEST(ParallelBond, FreshBondCarriesNothing) {
  const Pair p;
  const BondPlace place = bondPlace(p.rest, p.A, p.B);
  EXPECT_LT((place.centre - p.point).norm(), 1e-15 * r);
  EXPECT_LT((place.deformation.axis - p.n).norm(), 1e-15);
  // Round-off of the bodies' positions only: a stretch of 1e-15 r at most.
  const double u = 1e-15 * r, F = bond.normalStiffness * section.area * u;
  const BondLoads l = p.loads();
  EXPECT_LT(l.force.norm(), F);
  EXPECT_LT(l.energy, 0.5 * F * u);
}

// Tension: F = -k_n A u n on B, sigma = k_n u, energy k_n A u^2 / 2.
TEST(ParallelBond, TensionIsKnAu) {
  Pair p;
  const double u = 1e-10;
  p.B.position += u * p.n;
  const BondLoads l = p.loads();
  const double F = bond.normalStiffness * section.area * u;
  EXPECT_NEAR((l.force + F * p.n).norm(), 0.0, 1e-9 * F);
  EXPECT_NEAR(l.normalForce, F, 1e-9 * F);
  EXPECT_NEAR(l.tensileStress, bond.normalStiffness * u, 1e-9 * bond.normalStiffness * u);
  EXPECT_NEAR(l.shearStress, 0.0, 1e-9 * bond.shearStiffness * u);
  EXPECT_NEAR(l.energy, 0.5 * F * u, 1e-9 * F * u);
  EXPECT_LT(l.moment.norm(), 1e-9 * F * R);
}

// Shear: F_s = -k_s A u_s, tau = |F_s| / A = k_s |u_s|; no normal stress.
TEST(ParallelBond, ShearIsKsAu) {
  Pair p;
  const Vec3 u = 1e-10 * (0.6 * p.s + 0.8 * p.t);
  p.B.position += u;
  const BondLoads l = p.loads();
  const double F = bond.shearStiffness * section.area * u.norm();
  EXPECT_NEAR((l.force + bond.shearStiffness * section.area * u).norm(), 0.0, 1e-9 * F);
  EXPECT_NEAR(l.shearStress, bond.shearStiffness * u.norm(), 1e-9 * bond.shearStiffness * u.norm());
  EXPECT_NEAR(l.tensileStress, 0.0, 1e-9 * bond.normalStiffness * u.norm());
}

// Bending by theta about an axis normal to n through the bond's point: M_b = -k_n I theta,
// sigma = |M_b| R / I = k_n R theta (the outer fibre's stretch R theta), no force.
TEST(ParallelBond, BendingIsKnITheta) {
  Pair p;
  const double theta = 1e-5;
  p.turnB(theta * p.s);
  const BondLoads l = p.loads();
  const double M = bond.normalStiffness * section.inertia * theta;
  EXPECT_NEAR((l.moment + M * p.s).norm(), 0.0, 1e-8 * M);
  EXPECT_NEAR(l.tensileStress, bond.normalStiffness * R * theta, 1e-8 * bond.normalStiffness * R * theta);
  EXPECT_NEAR(l.force.norm(), 0.0, 1e-9 * M / R);
  EXPECT_NEAR(l.energy, 0.5 * M * theta, 1e-8 * M * theta);
}

// Twisting by theta about n: M_t = -k_s J theta, tau = |M_t| R / J = k_s R theta.
TEST(ParallelBond, TwistIsKsJTheta) {
  Pair p;
  const double theta = 1e-5;
  p.turnB(theta * p.n);
  const BondLoads l = p.loads();
  const double M = bond.shearStiffness * section.polar * theta;
  EXPECT_NEAR((l.moment + M * p.n).norm(), 0.0, 1e-9 * M);
  EXPECT_NEAR(l.shearStress, bond.shearStiffness * R * theta, 1e-9 * bond.shearStiffness * R * theta);
  EXPECT_NEAR(l.tensileStress, 0.0, 1e-9 * bond.normalStiffness * R * theta);
}

// Tension and bending together: sigma = F_n / A + |M_b| R / I (Eq. 11) adds the two.
TEST(ParallelBond, TensileStressAddsStretchAndBending) {
  Pair p;
  const double u = 5e-11, theta = 2e-5;
  p.turnB(theta * p.t);
  p.B.position += u * p.n;
  const double expected = bond.normalStiffness * (u + R * theta);
  EXPECT_NEAR(p.loads().tensileStress, expected, 1e-8 * expected);
}

// A bond breaks at its strength: stretched to u_c (1 - 1e-9) it holds, to u_c (1 + 1e-9) it breaks,
// u_c = sigma_c / k_n; twisted, at theta_c = tau_c / (k_s R).
TEST(ParallelBond, BreaksAtItsStrengths) {
  const double uc = bond.tensileStrength / bond.normalStiffness;
  for (const double f : {1.0 - 1e-9, 1.0 + 1e-9}) {
    Pair p;
    p.B.position += f * uc * p.n;
    EXPECT_EQ(p.loads().breaks(bond), f > 1.0) << "stretched to " << f << " u_c";
  }
  const double thetac = bond.shearStrength / (bond.shearStiffness * R);
  for (const double f : {1.0 - 1e-9, 1.0 + 1e-9}) {
    Pair p;
    p.turnB(f * thetac * p.n);
    EXPECT_EQ(p.loads().breaks(bond), f > 1.0) << "twisted to " << f << " theta_c";
  }
}

// Objectivity: both bodies moved and turned together leave the bond as it was.
TEST(ParallelBond, RigidMotionLeavesItUndeformed) {
  Pair p;
  p.B.position += 1e-10 * p.n;
  p.turnB(1e-5 * p.s);
  const BondDeformation before = bondPlace(p.rest, p.A, p.B).deformation;
  const Quat q(Eigen::AngleAxisd(2.3, Vec3(-0.4, 0.1, 1.0).normalized()));
  const Vec3 shift(3e-6, -1e-6, 7e-6);
  for (Pose* body : {&p.A, &p.B}) {
    body->position = q * body->position + shift;
    body->orientation = (q * body->orientation).normalized();
  }
  const BondDeformation after = bondPlace(p.rest, p.A, p.B).deformation;
  EXPECT_NEAR(after.extension, before.extension, 1e-9 * 1e-10);
  EXPECT_NEAR((after.bending - q * before.bending).norm(), 0.0, 1e-9 * 1e-5);
  EXPECT_NEAR(after.twist, before.twist, 1e-12);
  EXPECT_NEAR((after.axis - q * before.axis).norm(), 0.0, 1e-12);
}

TEST(ParallelBond, RotationVectorTakesTheShorterWay) {
  const Vec3 axis = Vec3(1.0, 2.0, -2.0) / 3.0;
  EXPECT_NEAR((rotationVector(Quat(Eigen::AngleAxisd(0.3, axis))) - 0.3 * axis).norm(), 0.0, 1e-15);
  const Quat q(Eigen::AngleAxisd(0.3, axis));
  EXPECT_NEAR((rotationVector(Quat(-q.w(), -q.x(), -q.y(), -q.z())) - 0.3 * axis).norm(), 0.0, 1e-15);
  EXPECT_NEAR((rotationVector(Quat(Eigen::AngleAxisd(3.0, axis))) - 3.0 * axis).norm(), 0.0, 1e-14);
}

TEST(ParallelBond, CheckNamesTheBadValue) {
  ParallelBond b = bond;
  b.shearStrength = 0.0;
  try {
    b.check();
    FAIL() << "a zero strength passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("shear_strength"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sqdem
