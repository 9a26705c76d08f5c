#pragma once
// A plane wall's surface (dynamics/wall.hpp): an infinite plane, the particles on the side its
// normal points to. It translates; it does not turn.

#include "sqdem/geometry/plane.hpp"

namespace sqdem {

struct PlaneWall {
  Plane plane;

  static constexpr const char* kind = "a plane";
  /// A floor (the bed rests on it) faces +z, a pressing plate -z.
  bool facesUp() const { return plane.normal.z() > 0.999; }
  bool facesDown() const { return plane.normal.z() < -0.999; }
  /// Calls f with every field (the scene's fingerprint reads them all).
  void fields(auto&& f) const { f(plane.point, plane.normal); }
  const Vec3& reference() const { return plane.point; }
  /// Signed distance of x from the surface, > 0 on the particles' side (m).
  double distance(const Vec3& x) const { return (x - plane.point).dot(plane.normal); }
  Vec3 surfaceVelocity(const Vec3& /*x*/, const Vec3& velocity, const Vec3& /*angularVelocity*/) const { return velocity; }
  void advance(double h, const Vec3& velocity, const Vec3& /*angularVelocity*/) { plane.point += h * velocity; }
};

}  // namespace sqdem
