#pragma once
// Circular cylinder (a roller, or a roll section of a calender): the particles live outside it.
// Infinite along its axis, or finite: the barrel over the axis segment
// [point - halfLength axis, point + halfLength axis] closed by rounded ends (the points within
// `radius` of the segment: a capsule) or by flat ones (discs; their rims are edges). Its surface
// curvatures are 1/radius around the axis and 0 along it on the barrel, 1/radius both ways on a
// rounded end, 0 on a disc. distance() and fromAxis() are the capsule's: for flat ends a lower
// bound of the distance (the capsule holds the flat-ended cylinder), which is what candidate
// searches need.

#include <algorithm>
#include <limits>

#include "sqdem/geometry/curvature.hpp"
#include "sqdem/math/types.hpp"

namespace sqdem {

struct Cylinder {
  Vec3 point = Vec3::Zero();   ///< a point of the axis (m): the middle of a finite one
  Vec3 axis = Vec3::UnitY();   ///< unit direction of the axis
  double radius = 1.0;         ///< (m), > 0
  double halfLength = std::numeric_limits<double>::infinity();  ///< of the barrel (m)
  bool flatEnds = false;       ///< a finite one's ends: discs, not hemispheres

  bool finite() const { return halfLength < std::numeric_limits<double>::infinity(); }
  /// The station of x along the axis, clamped to the barrel (m).
  double station(const Vec3& x) const { return std::clamp((x - point).dot(axis), -halfLength, halfLength); }
  /// The vector to x from the nearest point of the axis segment (m): normal to the axis beside
  /// the barrel.
  Vec3 fromAxis(const Vec3& x) const { return x - point - station(x) * axis; }
  /// Signed distance of x from the surface, > 0 outside (m).
  double distance(const Vec3& x) const { return fromAxis(x).norm() - radius; }
  /// The unit normal from the axis to x (x off the axis).
  Vec3 outwardNormal(const Vec3& x) const { return fromAxis(x).normalized(); }
  /// The barrel's principal curvatures where the outward normal is m (normal to the axis):
  /// 1/radius around the axis (d1 = axis x m), 0 along it (d2 = axis); d1 x d2 = m.
  PrincipalCurvatures curvatures(const Vec3& m) const { return {1.0 / radius, 0.0, axis.cross(m), axis}; }
};

}  // namespace sqdem
