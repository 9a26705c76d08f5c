#pragma once
// Infinite plane (a wall): the particles live on the side its unit normal points to.

#include "sqdem/math/types.hpp"

namespace sqdem {

struct Plane {
  Vec3 point = Vec3::Zero();     ///< any point of the plane (m)
  Vec3 normal = Vec3::UnitZ();   ///< unit normal pointing out of the wall, into the particles
};

}  // namespace sqdem
