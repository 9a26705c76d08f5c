#pragma once
// Where a bond is and how it is deformed (docs/bonds.md, "Kinematics"): a bond forms at the
// middle of the two bodies' common-normal points along the contact normal, and is fixed in both
// bodies from then on (its point and axis in each body's frame, and the bodies' relative turn).
// Its deformation is measured in a frame that turns with the bodies (co-rotational):
//   c_A = x_A + R_A p_A,  c_B = x_B + R_B p_B,  u = c_B - c_A,  n = unit(R_A n_A + R_B n_B),
//   u_n = u . n,  u_s = u - u_n n,  theta = R_A rot(q_A^-1 q_B (q_A0^-1 q_B0)^-1),
//   theta_t = theta . n,  theta_b = theta - theta_t n,
// rot(q) the rotation vector of q. For small turns this is Potyondy & Cundall's incremental
// update summed (their Eq. 10), without its drift: a bond's deformation depends on the bodies'
// poses only, so a rigid motion of both leaves it undeformed and its history is fixed data.
// The loads act at the bond's centre (c_A + c_B) / 2: on B the force F and the moment
// (c - x_B) x F + M, on A their opposites about its own centre (momentum and angular
// momentum are kept exactly).

#include <cmath>

#include "sqdem/geometry/pose.hpp"
#include "sqdem/mechanics/parallel_bond.hpp"

namespace sqdem {

/// A bond's fixed data: its point and axis in A's and B's frames, and B's turn relative to A.
struct BondRest {
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();  ///< in each body's frame (m)
  Vec3 axisA = Vec3::UnitZ(), axisB = Vec3::UnitZ();  ///< unit, in each body's frame
  Quat relative = Quat::Identity();                   ///< q_A^-1 q_B when it formed

  /// The bond at `point` along the unit normal n (A to B) between A and B as they are now.
  static BondRest formed(const Pose& A, const Pose& B, const Vec3& point, const Vec3& n) {
    return {A.toBody(point), B.toBody(point), A.orientation.conjugate() * n, B.orientation.conjugate() * n,
            (A.orientation.conjugate() * B.orientation).normalized()};
  }
};

/// The rotation vector of a unit quaternion, the shorter way round (rad).
inline Vec3 rotationVector(const Quat& q) {
  const double s = q.vec().norm();
  if (s == 0.0) return Vec3::Zero();
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;  // q and -q are one rotation
  return (2.0 * std::atan2(s, sign * q.w()) / s * sign) * q.vec();
}

/// A bond's deformation between A and B at their poses, and its centre c (m).
struct BondPlace {
  BondDeformation deformation;
  Vec3 centre = Vec3::Zero();
};

inline BondPlace bondPlace(const BondRest& rest, const Pose& A, const Pose& B) {
  const Vec3 cA = A.toWorld(rest.pointA), cB = B.toWorld(rest.pointB), u = cB - cA;
  BondPlace p;
  BondDeformation& d = p.deformation;
  d.axis = (A.orientation * rest.axisA + B.orientation * rest.axisB).normalized();
  d.extension = u.dot(d.axis);
  d.shear = u - d.extension * d.axis;
  const Vec3 theta = A.orientation * rotationVector(A.orientation.conjugate() * B.orientation * rest.relative.conjugate());
  d.twist = theta.dot(d.axis);
  d.bending = theta - d.twist * d.axis;
  p.centre = 0.5 * (cA + cB);
  return p;
}

}  // namespace sqdem
