// The reduction of the contacts' loads to particles, in key order per particle, and to walls, as
// exact sums (see interactions.hpp: independent of the thread count, the slots and the ranks).

#include <omp.h>

#include "sqdem/dynamics/integrator.hpp"
#include "sqdem/interaction/interactions.hpp"

namespace sqdem {
namespace {

/// Contact k's load on B as a torque about centre: its force's moment and the pure moment where
/// the store keeps one (`moments`: s.withMoment(), read once per loop), B's torque about its
/// centre; A's, about its own, with the sign reversed.
[[gnu::always_inline]] inline Vec3 torqueAbout(const ContactStore& s, std::uint32_t k, const Vec3& centre, bool moments) {
  return (s.point[k] - centre).cross(s.force[k]) + (moments ? s.moment[k] : Vec3::Zero());
}

}  // namespace

LoadOnB Interactions::loadOnB(std::uint32_t k, const ParticleStore& p) const {
  if (!store_.acting[k]) return {};
  return {store_.force[k], torqueAbout(store_, k, p.position[store_.b[k]], store_.withMoment()), 1};
}

void Interactions::reduce(ParticleStore& p, const Vec3& gravity, double drag, const std::vector<Wall>& walls,
                          std::vector<WallLoadSum>& wallLoads, std::span<const LoadOnB> remote, double halfStep,
                          const TeamSplit& split) {
  const ContactStore& s = store_;
  const bool moments = s.withMoment();
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  const Share particles = split.share(n);
  for (std::ptrdiff_t i = particles.begin; i < particles.end; ++i) {
    // Summed in registers (the stores' arrays might alias for the compiler), in the same order.
    Vec3 force = p.mass[i] * (gravity - drag * p.velocity[i]);
    Vec3 torque = Vec3::Zero();
    for (std::uint32_t m = involvementStart_[i]; m < involvementStart_[i + 1]; ++m) {
      if ((involvement_[m] & remoteFlag) != 0) {  // computed where its A is owned (loadOnB)
        const LoadOnB& load = remote[involvement_[m] & contactMask];
        if (!load.acting) continue;
        force += load.force;
        torque += load.torque;
        continue;
      }
      const std::uint32_t k = involvement_[m] & contactMask;
      if (!s.acting[k]) continue;
      if ((involvement_[m] & bodyBFlag) == 0) {  // i is body A
        force -= s.force[k];
        torque -= torqueAbout(s, k, p.position[i], moments);
      } else {
        force += s.force[k];
        const Vec3& centre = (involvement_[m] & imageFlag) != 0 ? p.position[s.b[k]] : p.position[i];  // i's image
        torque += torqueAbout(s, k, centre, moments);
      }
    }
    p.force[i] = force;
    p.torque[i] = torque;
    if (halfStep > 0.0) kick(p, static_cast<std::size_t>(i), halfStep);
  }
  // The walls' shares: each thread sums the wall contacts it computed (memberShare: their records
  // are in its core's cache), then adds its sums to the walls' (exact sums: in any order and any
  // split, the same bits).
  std::vector<WallLoadSum>& mine = threadWallLoads_[static_cast<std::size_t>(omp_get_thread_num())];
  for (WallLoadSum& load : mine) load.clear();  // (sized by beginCompute)
  for (const Group& group : groups_) {
    if (!withWall(group.kind)) continue;
    for (const std::uint32_t k : memberShare(group, n, &split)) {
      if (!s.acting[k]) continue;
      const std::uint32_t w = s.b[k] & ~wallFlag;
      const Vec3 torque = (s.point[k] - s.wallImage[k] - walls[w].reference()).cross(s.force[k]) +
                          (moments ? s.moment[k] : Vec3::Zero());
      const Vec3 elastic = s.force[k] - s.load[k].damping * s.normal[k];
      std::array<ExactSum, 10>& part = mine[w].part;
      for (int d = 0; d < 3; ++d) {
        part[WallLoadSum::force + d].add(s.force[k](d));
        part[WallLoadSum::torque + d].add(torque(d));
        part[WallLoadSum::elasticForce + d].add(elastic(d));
      }
      part[WallLoadSum::stiffness].add(s.load[k].stiffness);
    }
  }
#pragma omp critical(sqdem_wall_loads)
  for (std::size_t w = 0; w < walls.size(); ++w) {
    for (std::size_t j = 0; j < mine[w].part.size(); ++j) wallLoads[w].part[j] += mine[w].part[j];
  }
}

}  // namespace sqdem
