#pragma once
// A history vector that lives in the contact's tangent plane (tangential spring, rolling
// displacement) is turned with the contact: projected onto the current plane, length kept.

#include "sqdem/math/types.hpp"

namespace sqdem {

inline void keepInTangentPlane(Vec3& x, const Vec3& n) {
  const double length = x.norm();
  x -= x.dot(n) * n;
  const double projected = x.norm();
  if (projected > 0.0) x *= length / projected;
}

}  // namespace sqdem
