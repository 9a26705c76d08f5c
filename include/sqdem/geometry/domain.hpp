#pragma once
// The simulation box: bounds (m) and which directions are periodic. Periodic directions wrap
// positions into [lo, hi); the others only size the cell grid (particles may leave them).

#include <array>

#include "sqdem/math/types.hpp"

namespace sqdem {

struct Domain {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Ones();
  std::array<bool, 3> periodic{false, false, false};

  Vec3 length() const { return hi - lo; }
  /// Wraps x into [lo, hi) along the periodic directions.
  Vec3 wrap(Vec3 x) const;
  /// The shortest periodic image of a separation d (d itself along the other directions).
  Vec3 minimumImage(Vec3 d) const;
  /// The first direction that is not periodic along which x lies outside [lo, hi] (0, 1, 2),
  /// or -1: where a particle's centre may not be put.
  int outsideAlong(const Vec3& x) const;
};

}  // namespace sqdem
