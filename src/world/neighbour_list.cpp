#include "sqdem/world/neighbour_list.hpp"

#include <algorithm>
#include <numbers>

namespace sqdem {

BroadPhase automaticBroadPhase(const std::vector<double>& radii, double skin) {
  if (radii.empty()) return BroadPhase::CellList;
  double largest = 0.0, volume = 0.0;
  for (const double r : radii) {
    largest = std::max(largest, r);
    volume += r * r * r;
  }
  const double width = 2.0 * largest + skin, meanVolume = 4.0 / 3.0 * std::numbers::pi * volume / static_cast<double>(radii.size());
  return 0.6 * width * width * width / meanVolume > 30.0 ? BroadPhase::AabbTree : BroadPhase::CellList;
}

bool NeighbourList::needsRebuild(const ParticleStore& particles) const {
  if (!covers(particles.size())) return true;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (outOfSkin(i, particles.position[i])) return true;
  }
  return false;
}

void NeighbourList::rebuild(const ParticleStore& particles, const std::vector<double>& reach) {
  reference_.assign(particles.position.begin(), particles.position.begin() + static_cast<std::ptrdiff_t>(particles.size()));
  const ParticleCloud cloud{particles.position, reach, particles.id};
  pairs_ = search_ == BroadPhase::CellList ? cellListPairs(cloud, skin_) : aabbTreePairs(cloud, skin_);
  // Sorted by a, owned slots first: the pairs of a ghost A (computed where A is owned) end it.
  const auto owned = static_cast<std::uint32_t>(particles.size());
  pairs_.erase(std::partition_point(pairs_.begin(), pairs_.end(), [&](const CandidatePair& c) { return c.a < owned; }), pairs_.end());
  ++builds_;
}

}  // namespace sqdem
