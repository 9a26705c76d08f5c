#pragma once
// A wall: a kinematic body (docs/architecture.md, "Layers") whose surface is one of the wall
// shapes (WallSurface: an infinite plane, the outside of a cylinder, a triangle mesh), moved with
// a prescribed velocity or, a plane, under servo control; a cylinder may also spin about its axis
// and a mesh rotate about its origin. The particles' forces and torques on it are summed in the
// interaction layer's reduction.

#include <concepts>
#include <cstdint>
#include <optional>
#include <variant>

#include "sqdem/dynamics/cylinder_wall.hpp"
#include "sqdem/dynamics/mesh_wall.hpp"
#include "sqdem/dynamics/plane_wall.hpp"
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

/// What a wall's surface must give: its kind for messages, its fields, the point its motion and
/// torque refer to, the velocity of its surface at x, and its motion over a step h.
template <class S>
concept WallSurfaceType = requires(S s, const S c, double h, const Vec3& x) {
  { S::kind } -> std::convertible_to<const char*>;
  { c.reference() } -> std::same_as<const Vec3&>;
  c.fields([](const auto&...) {});
  { c.surfaceVelocity(x, x, x) } -> std::convertible_to<Vec3>;
  s.advance(h, x, x);
};

/// The wall shapes: the one list of them. Each is its own type (plane_wall.hpp, ...); what a
/// layer does with a wall it does by visiting this variant, so the compiler names every place a
/// new shape must be handled.
using WallSurface = std::variant<PlaneWall, CylinderWall, MeshWall>;

/// One callable per wall shape, for std::visit on a WallSurface (a shape without one does not
/// compile).
template <class... F>
struct PerShape : F... {
  using F::operator()...;
};
template <class... F>
PerShape(F...) -> PerShape<F...>;

template <class... S>
constexpr bool allWallSurfaces(std::variant<S...>*) { return (WallSurfaceType<S> && ...); }
static_assert(allWallSurfaces(static_cast<WallSurface*>(nullptr)));

/// A wall moving with a prescribed velocity or under servo control; `force` and `torque` are
/// what the particles exert on it.
struct Wall {
  WallSurface surface;
  Vec3 velocity = Vec3::Zero();  ///< of its reference point (m/s)
  std::uint32_t material = 0;
  Vec3 force = Vec3::Zero();     ///< (N), from the last force computation
  Vec3 elasticForce = Vec3::Zero();  ///< the same without the contacts' normal damping (N)
  double stiffness = 0.0;        ///< sum of its contacts' normal stiffnesses S_n (N/m)
  std::optional<WallServo> servo;  ///< planes only
  /// About its reference point (rad/s): along a cylinder's axis (its spin), any for a mesh,
  /// zero for a plane.
  Vec3 angularVelocity = Vec3::Zero();
  Vec3 torque = Vec3::Zero();    ///< about its reference point (N m), from the last force computation

  template <WallSurfaceType S>
  bool is() const { return std::holds_alternative<S>(surface); }
  /// Its surface if it is an S, else null.
  template <WallSurfaceType S>
  const S* as() const { return std::get_if<S>(&surface); }
  template <WallSurfaceType S>
  S* as() { return std::get_if<S>(&surface); }
  /// Its surface, known to be an S (as a kernel chosen by the wall's kind knows it).
  template <WallSurfaceType S>
  const S& get() const { return *std::get_if<S>(&surface); }
  template <WallSurfaceType S>
  S& get() { return *std::get_if<S>(&surface); }
  const char* kind() const { return std::visit([](const auto& s) { return s.kind; }, surface); }
  /// The point its motion and torque refer to.
  const Vec3& reference() const { return std::visit([](const auto& s) -> const Vec3& { return s.reference(); }, surface); }
  /// Velocity of its surface at x (m/s): translation and rotation.
  Vec3 surfaceVelocity(const Vec3& x) const {
    return std::visit([&](const auto& s) { return Vec3(s.surfaceVelocity(x, velocity, angularVelocity)); }, surface);
  }
  /// Moves it over a step h.
  void advance(double h) {
    std::visit([&](auto& s) { s.advance(h, velocity, angularVelocity); }, surface);
  }
};

/// In a contact's body B: the wall index with this flag set, particles without.
inline constexpr std::uint32_t wallFlag = 0x80000000u;

}  // namespace sqdem
