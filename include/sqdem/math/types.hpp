#pragma once
// Small fixed-size linear algebra used everywhere in sqdem (Eigen, double precision).

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sqdem {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// A quaternion as the 4-vector (w, x, y, z), the ordering of NO_SQUISH's conjugate momentum
/// (Eigen's coeffs() is x, y, z, w), and back.
inline Vec4 asVector(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }
inline Quat asQuat(const Vec4& v) { return {v(0), v(1), v(2), v(3)}; }

/// Two unit vectors t1, t2 with (t1, t2, n) a right-handed orthonormal basis; n must be unit.
/// Continuous in n away from n = -z (Frisvad/Duff et al. 2017 branchless construction).
inline void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z());
  const double b = n.x() * n.y() * a;
  t1 = Vec3(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  t2 = Vec3(b, sign + n.y() * n.y() * a, -n.y());
}

}  // namespace sqdem
