#pragma once
// Infinite circular cylinder (a roller, or a roll section of a calender): the particles live
// outside it. Its surface curvatures are 1/radius around the axis and 0 along it.

#include "sqdem/geometry/curvature.hpp"
#include "sqdem/math/types.hpp"

namespace sqdem {

struct Cylinder {
  Vec3 point = Vec3::Zero();   ///< any point of the axis (m)
  Vec3 axis = Vec3::UnitY();   ///< unit direction of the axis
  double radius = 1.0;         ///< (m), > 0

  /// The vector from the axis to x, normal to the axis (m).
  Vec3 fromAxis(const Vec3& x) const {
    const Vec3 r = x - point;
    return r - r.dot(axis) * axis;
  }
  /// Signed distance of x from the surface, > 0 outside (m).
  double distance(const Vec3& x) const { return fromAxis(x).norm() - radius; }
  /// The unit normal from the axis to x (x off the axis).
  Vec3 outwardNormal(const Vec3& x) const { return fromAxis(x).normalized(); }
  /// The principal curvatures where the outward normal is m (normal to the axis): 1/radius
  /// around the axis (d1 = axis x m), 0 along it (d2 = axis); d1 x d2 = m.
  PrincipalCurvatures curvatures(const Vec3& m) const { return {1.0 / radius, 0.0, axis.cross(m), axis}; }
};

}  // namespace sqdem
