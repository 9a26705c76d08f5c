#pragma once
// A wall: an infinite plane, a kinematic body moved with a prescribed velocity or under servo
// control (DESIGN.md §2: walls are kinematic bodies; the particles' forces on it are summed in
// the interaction layer's reduction).

#include <cstdint>
#include <optional>

#include "sqdem/geometry/plane.hpp"
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

/// An infinite plane moving with a prescribed velocity or under servo control; `force` is what
/// the particles exert on it.
struct Wall {
  Plane plane;
  Vec3 velocity = Vec3::Zero();  ///< (m/s)
  std::uint32_t material = 0;
  Vec3 force = Vec3::Zero();     ///< (N), from the last force computation
  Vec3 elasticForce = Vec3::Zero();  ///< the same without the contacts' normal damping (N)
  double stiffness = 0.0;        ///< sum of its contacts' normal stiffnesses S_n (N/m)
  std::optional<WallServo> servo;
};

/// In a contact's body B: the wall index with this flag set, particles without.
inline constexpr std::uint32_t wallFlag = 0x80000000u;

}  // namespace sqdem
