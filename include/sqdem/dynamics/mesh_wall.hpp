#pragma once
// A mesh wall's surface (dynamics/wall.hpp): one of the World's triangle meshes (an STL file,
// geometry/mesh_features.hpp), its body frame at `origin` turned by `orientation`. It translates
// and turns about its origin.

#include <cstdint>

#include "sqdem/geometry/pose.hpp"

namespace sqdem {

struct MeshWall {
  std::uint32_t mesh = 0;              ///< its index among the World's meshes
  Vec3 origin = Vec3::Zero();          ///< its body frame's origin in the world (m)
  Quat orientation = Quat::Identity();  ///< its body frame to the world

  static constexpr const char* kind = "a mesh";
  /// Calls f with every field (the scene's fingerprint reads them all).
  void fields(auto&& f) const { f(mesh, origin, orientation); }
  const Vec3& reference() const { return origin; }
  Pose pose() const { return {origin, orientation}; }
  Vec3 surfaceVelocity(const Vec3& x, const Vec3& velocity, const Vec3& angularVelocity) const {
    return velocity + angularVelocity.cross(x - origin);
  }
  /// Translation and the rotation exp(omega h) about its origin.
  void advance(double h, const Vec3& velocity, const Vec3& angularVelocity) {
    origin += h * velocity;
    const double angle = angularVelocity.norm() * h;
    if (angle > 0.0) orientation = (Quat(Eigen::AngleAxisd(angle, angularVelocity.normalized())) * orientation).normalized();
  }
};

}  // namespace sqdem
