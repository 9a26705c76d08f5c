#pragma once
// A cylinder wall's surface (dynamics/wall.hpp): the outside of a roller, infinite or finite
// (geometry/cylinder.hpp). It translates and may spin about its axis; the spin moves its surface,
// not where the surface is.

#include "sqdem/geometry/cylinder.hpp"

namespace sqdem {

struct CylinderWall {
  Cylinder cylinder;

  static constexpr const char* kind = "a cylinder";
  /// Calls f with every field (the scene's fingerprint reads them all).
  void fields(auto&& f) const { f(cylinder.point, cylinder.axis, cylinder.radius, cylinder.halfLength, cylinder.flatEnds); }
  const Vec3& reference() const { return cylinder.point; }
  /// Signed distance of x from the surface, > 0 outside (m; Cylinder::distance).
  double distance(const Vec3& x) const { return cylinder.distance(x); }
  Vec3 surfaceVelocity(const Vec3& x, const Vec3& velocity, const Vec3& angularVelocity) const {
    return velocity + angularVelocity.cross(x - cylinder.point);
  }
  void advance(double h, const Vec3& velocity, const Vec3& /*angularVelocity*/) { cylinder.point += h * velocity; }
};

}  // namespace sqdem
