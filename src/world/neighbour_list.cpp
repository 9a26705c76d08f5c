#include "sqdem/world/neighbour_list.hpp"

namespace sqdem {

bool NeighbourList::needsRebuild(const ParticleStore& particles) const {
  if (reference_.size() != particles.size()) return true;
  const double limit = 0.25 * skin_ * skin_;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if ((particles.position[i] - reference_[i]).squaredNorm() > limit) return true;
  }
  return false;
}

void NeighbourList::rebuild(ParticleStore& particles, const std::vector<double>& boundingRadius) {
  for (Vec3& x : particles.position) x = domain_.wrap(x);
  reference_ = particles.position;
  const ParticleCloud cloud{reference_, boundingRadius, particles.id};
  pairs_ = search_ == BroadPhase::CellList ? cellListPairs(domain_, cloud, skin_) : aabbTreePairs(domain_, cloud, skin_);
  ++builds_;
}

}  // namespace sqdem
