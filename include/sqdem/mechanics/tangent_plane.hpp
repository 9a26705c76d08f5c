#pragma once
// A history vector that lives in the contact's tangent plane (tangential spring, rolling
// displacement) is turned with the contact: projected onto the current plane, length kept.

#include <cmath>

#include "sqdem/math/types.hpp"

namespace sqdem {

inline void keepInTangentPlane(Vec3& x, const Vec3& n) {
  const double length2 = x.squaredNorm();
  x -= x.dot(n) * n;
  const double projected2 = x.squaredNorm();
  if (projected2 > 0.0) x *= std::sqrt(length2 / projected2);
}

}  // namespace sqdem
