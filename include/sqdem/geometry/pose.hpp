#pragma once
// Rigid-body pose: position of the body centre (m) and unit quaternion body -> world.

#include "sqdem/math/types.hpp"

namespace sqdem {

struct Pose {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();

  Mat3 rotation() const { return orientation.toRotationMatrix(); }
  Vec3 toWorld(const Vec3& bodyPoint) const { return position + orientation * bodyPoint; }
  Vec3 toBody(const Vec3& worldPoint) const {
    return orientation.conjugate() * (worldPoint - position);
  }
};

}  // namespace sqdem
