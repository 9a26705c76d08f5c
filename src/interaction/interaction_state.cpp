// A contact store restored from a checkpoint (world_state.cpp: its slots already placed in this
// process): the indices Interactions derives from it made again.

#include "sqdem/interaction/interactions.hpp"
#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {

Interactions Interactions::restore(ContactStore store, const InteractionScene& scene,
                                   const std::vector<std::uint32_t>& ghostOwner) {
  Interactions out;
  const ContactStore expected = emptyStore(scene);
  requireIntact(store.sameOptionalArrays(expected), "optional contact arrays");
  const std::size_t n = scene.particles.size(), slots = scene.particles.slots(), walls = scene.walls.size();
  const std::vector<std::uint32_t>& id = scene.particles.id;
  for (std::size_t k = 0; k < store.size(); ++k) {
    requireIntact(store.a[k] < n && store.idA[k] == id[store.a[k]], "contact body A");
    requireIntact(store.onWall(k) ? (store.b[k] & ~wallFlag) < walls && store.idB[k] == store.b[k]
                                  : store.b[k] < slots && store.idB[k] == id[store.b[k]] && store.idA[k] < store.idB[k],
                  "contact body B");
  }
  out.store_ = std::move(store);
  out.storeChanged();  // the acting flags are as the last computation left them
  out.regroup(scene);
  out.indexInvolvement(n, ghostOwner);
  return out;
}

}  // namespace sqdem
