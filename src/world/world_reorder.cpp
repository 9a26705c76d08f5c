// Re-ordering the owned particle slots along a Hilbert curve (spatial_order.hpp) so that
// neighbours in space are neighbours in memory, just before a neighbour-list build: the contacts
// find their slots again by key there, so every result stays as it was.

#include "sqdem/math/permutation.hpp"
#include "sqdem/world/spatial_order.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

void World::reorderAlongHilbertCurve() {
  const std::vector<std::uint32_t> order = hilbertOrder(particles_.position);  // new slot k <- old order[k]
  ParticleStore::forEachArray(particles_, [&](auto& array) { permute(array, order); });
}

}  // namespace sqdem
