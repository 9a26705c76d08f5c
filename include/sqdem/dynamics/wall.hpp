#pragma once
// A wall: a kinematic body (docs/architecture.md, "Layers") whose surface is an infinite plane, the outside of a
// cylinder (a roller) or a triangle mesh (an STL file: mesh_features.hpp, held by the World),
// moved with a prescribed velocity or, a plane, under servo control; a cylinder may also spin
// about its axis and a mesh rotate about its origin. The particles' forces and torques on it
// are summed in the interaction layer's reduction.

#include <cstdint>
#include <optional>

#include "sqdem/geometry/cylinder.hpp"
#include "sqdem/geometry/plane.hpp"
#include "sqdem/geometry/pose.hpp"
#include "sqdem/math/types.hpp"

namespace sqdem {

/// Force control of a wall: before each step the wall moves along its normal with
///   v = max_speed clamp((p_target - p) / p_target, -1, 1),
/// limited to |v| <= |F_target - F| / (2 k dt) while it touches particles (proportional
/// control; the wall advances into the particles while p < p_target). p and F are the elastic
/// part of the wall's normal load: the contacts' damping depends on the wall's own velocity and
/// would feed the command back into the reading. k is the sum of the wall contacts' normal
/// stiffnesses, so one step closes at most half the force error the contacts see at once; this
/// keeps the loop stable however large max_speed is (without it, max_speed dt k / F_target > 2
/// made the wall chatter in and out of the bed).
struct WallServo {
  double pressure = 0.0;  ///< target normal pressure (Pa), > 0
  double maxSpeed = 0.0;  ///< (m/s), > 0
};

/// What a wall's surface is.
enum class WallShape : std::uint8_t {
  Plane,     ///< `plane`
  Cylinder,  ///< the outside of `cylinder`
  Mesh,      ///< the World's mesh `mesh`, its body frame at `origin` turned by `orientation`
};

/// A wall moving with a prescribed velocity or under servo control; `force` and `torque` are
/// what the particles exert on it.
struct Wall {
  Plane plane;                   ///< the surface of a Plane wall
  Vec3 velocity = Vec3::Zero();  ///< of its reference point (m/s)
  std::uint32_t material = 0;
  Vec3 force = Vec3::Zero();     ///< (N), from the last force computation
  Vec3 elasticForce = Vec3::Zero();  ///< the same without the contacts' normal damping (N)
  double stiffness = 0.0;        ///< sum of its contacts' normal stiffnesses S_n (N/m)
  std::optional<WallServo> servo;  ///< planes only
  WallShape shape = WallShape::Plane;
  Cylinder cylinder;             ///< the surface of a Cylinder wall
  /// About its reference point (rad/s): along a cylinder's axis (its spin), any for a mesh,
  /// zero for a plane.
  Vec3 angularVelocity = Vec3::Zero();
  Vec3 torque = Vec3::Zero();    ///< about its reference point (N m), from the last force computation
  std::uint32_t mesh = 0;        ///< a Mesh wall's index among the World's meshes
  Vec3 origin = Vec3::Zero();    ///< a Mesh wall's body-frame origin in the world (m)
  Quat orientation = Quat::Identity();  ///< a Mesh wall's body frame to the world

  /// The point its motion and torque refer to: the plane's point, the cylinder's axis point, or
  /// the mesh's origin.
  const Vec3& reference() const {
    return shape == WallShape::Plane ? plane.point : shape == WallShape::Cylinder ? cylinder.point : origin;
  }
  /// Where a Mesh wall's body frame is.
  Pose meshPose() const { return {origin, orientation}; }
  /// Velocity of its surface at x (m/s): translation and rotation.
  Vec3 surfaceVelocity(const Vec3& x) const {
    return shape == WallShape::Plane ? velocity : Vec3(velocity + angularVelocity.cross(x - reference()));
  }
  /// Signed distance of x from a plane's or a cylinder's surface, > 0 on the particles' side (m).
  double distance(const Vec3& x) const {
    return shape == WallShape::Plane ? (x - plane.point).dot(plane.normal) : cylinder.distance(x);
  }
  /// Moves it over a step h: translation, and a mesh's rotation exp(omega h) about its origin
  /// (a cylinder's spin leaves its surface where it is).
  void advance(double h) {
    if (shape == WallShape::Plane) plane.point += h * velocity;
    else if (shape == WallShape::Cylinder) cylinder.point += h * velocity;
    else {
      origin += h * velocity;
      const double angle = angularVelocity.norm() * h;
      if (angle > 0.0) orientation = (Quat(Eigen::AngleAxisd(angle, angularVelocity.normalized())) * orientation).normalized();
    }
  }
};

/// In a contact's body B: the wall index with this flag set, particles without.
inline constexpr std::uint32_t wallFlag = 0x80000000u;

}  // namespace sqdem
