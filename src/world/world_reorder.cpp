// Re-ordering the particle slots along a Hilbert curve (spatial_order.hpp) so that neighbours
// in space are neighbours in memory. Contacts follow their particles (Interactions::followSlots);
// their keys and so every result stay as they were.

#include "sqdem/math/permutation.hpp"
#include "sqdem/world/spatial_order.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

void World::reorderAlongHilbertCurve() {
  const std::vector<std::uint32_t> order = hilbertOrder(particles_.position);  // new slot k <- old order[k]
  std::vector<std::uint32_t> slotOf(order.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) slotOf[order[k]] = k;

  ParticleStore::forEachArray(particles_, [&](auto& array) { permute(array, order); });
  interactions_.followSlots(slotOf);
  neighbours_.invalidate();
}

}  // namespace sqdem
