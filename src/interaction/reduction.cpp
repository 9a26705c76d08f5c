// The reduction of the contacts' loads to particles and walls, in key order per body (see
// interactions.hpp: independent of the thread count).

#include "sqdem/interaction/interactions.hpp"

namespace sqdem {

void Interactions::reduce(ParticleStore& p, const Vec3& gravity, double drag, std::vector<Wall>& walls) {
  const ContactStore& s = store_;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    p.force[i] = p.mass[i] * (gravity - drag * p.velocity[i]);
    p.torque[i].setZero();
    for (std::uint32_t m = involvementStart_[i]; m < involvementStart_[i + 1]; ++m) {
      const std::uint32_t k = involvement_[m] & ~bodyBFlag;
      if (!s.acting[k]) continue;
      const Vec3& force = s.force[k];
      const Vec3 moment = s.withRolling ? s.moment[k] : Vec3::Zero();
      if ((involvement_[m] & bodyBFlag) == 0) {  // i is body A
        p.force[i] -= force;
        p.torque[i] -= (s.point[k] - p.position[i]).cross(force) + moment;
      } else {
        p.force[i] += force;
        p.torque[i] += (s.point[k] - (p.position[i] + s.shift[k])).cross(force) + moment;
      }
    }
  }
  for (Wall& w : walls) {
    w.force.setZero();
    w.torque.setZero();
    w.elasticForce.setZero();
    w.stiffness = 0.0;
  }
  interacting_.clear();
  for (std::uint32_t k = 0; k < s.size(); ++k) {
    if (!s.acting[k]) continue;
    if (s.onWall(k)) {
      Wall& w = walls[s.b[k] & ~wallFlag];
      w.force += s.force[k];
      w.torque += (s.point[k] - s.shift[k] - w.reference()).cross(s.force[k]) + (s.withRolling ? s.moment[k] : Vec3::Zero());
      w.elasticForce += s.force[k] - s.load[k].damping * s.normal[k];
      w.stiffness += s.load[k].stiffness;
    }
    interacting_.push_back(k);
  }
}

}  // namespace sqdem
