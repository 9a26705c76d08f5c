#pragma once
// The shape-class pair of a contact: which detector path it takes (DESIGN.md §2-3). Chosen once
// per candidate from the two shapes (spheres are ellipsoids are superquadrics: the most special
// class both bodies belong to).

#include <cstdint>

#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {

enum class PairKind : std::uint8_t {
  SphereSphere,      ///< closed form
  EllipsoidPair,     ///< common-normal solve on gauges without powers (n1 = n2 = 2)
  SuperquadricPair,  ///< common-normal solve, general exponents
  ParticleWall,      ///< closed form through the support map
};
inline constexpr int pairKindCount = static_cast<int>(PairKind::ParticleWall) + 1;

inline PairKind pairKind(const Superquadric& A, const Superquadric& B) {
  if (A.isSphere() && B.isSphere()) return PairKind::SphereSphere;
  if (A.isEllipsoid() && B.isEllipsoid()) return PairKind::EllipsoidPair;
  return PairKind::SuperquadricPair;
}

}  // namespace sqdem
