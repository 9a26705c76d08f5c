// Checkpoints of the contact store: every array raw (plain data), then on reading every count,
// index, id, status and key checked before the store is replaced.

#include <string>

#include "sqdem/interaction/interactions.hpp"
#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {

void Interactions::writeState(CheckpointWriter& out) const {
  out.put(static_cast<std::uint8_t>(store_.withRolling));
  out.put(static_cast<std::uint8_t>(store_.withCurvatureCache));
  out.put(static_cast<std::uint8_t>(store_.withEnergy));
  ContactStore::forEachArray(store_, [&](const auto& array) { out.putVector(array); });
  out.putVector(interacting_);
}

Interactions Interactions::readState(CheckpointReader& in, const InteractionScene& scene,
                                     const std::vector<std::uint32_t>& ghostOwner) {
  Interactions out;
  ContactStore& s = out.store_;
  const ContactStore expected = emptyStore(scene);
  std::uint8_t rolling = 0, cache = 0, energy = 0;
  in.get(rolling);
  in.get(cache);
  in.get(energy);
  requireIntact(rolling == expected.withRolling && cache == expected.withCurvatureCache && energy == expected.withEnergy,
                "optional contact arrays");
  s.withRolling = expected.withRolling;
  s.withCurvatureCache = expected.withCurvatureCache;
  s.withEnergy = expected.withEnergy;
  const std::uint64_t anyLength = ~std::uint64_t{0};  // bounded by the bytes left
  std::uint64_t count = 0;
  bool first = true;
  ContactStore::forEachArray(s, [&](auto& array) {
    if (!s.keeps(&array)) {
      in.getVector(array, 0);
      return;
    }
    in.getVector(array, first ? anyLength : count);
    if (first) count = array.size(), first = false;
    requireIntact(array.size() == count, "contact array length");
  });
  std::vector<std::uint32_t> interacting;
  in.getVector(interacting, count);

  const std::size_t n = scene.particles.size(), slots = scene.particles.slots(), walls = scene.walls.size();
  const std::vector<std::uint32_t>& id = scene.particles.id;
  for (std::size_t k = 0; k < count; ++k) {
    requireIntact(s.a[k] < n && s.idA[k] == id[s.a[k]], "contact body A");
    requireIntact(s.onWall(k) ? (s.b[k] & ~wallFlag) < walls && s.idB[k] == s.b[k]
                              : s.b[k] < slots && s.idB[k] == id[s.b[k]] && s.idA[k] < s.idB[k],
                  "contact body B");
    requireIntact(static_cast<unsigned>(s.status[k]) <= static_cast<unsigned>(ContactStatus::Degenerate), "contact status");
    const Wall* wall = s.onWall(k) ? &scene.walls[s.b[k] & ~wallFlag] : nullptr;
    const bool onMesh = wall != nullptr && wall->shape == WallShape::Mesh;
    requireIntact(onMesh ? wall->mesh < scene.meshes.size() && s.feature[k] < scene.meshes[wall->mesh].featureCount()
                         : s.feature[k] == 0,
                  "mesh feature");
  }
  out.sortKeys();
  for (std::size_t m = 1; m < count; ++m) requireIntact(s.key(out.keyOrder_[m - 1]) < s.key(out.keyOrder_[m]), "contact keys");
  for (std::size_t k = 0; k < interacting.size(); ++k) {
    requireIntact(interacting[k] < count && s.acting[interacting[k]] &&
                      (k == 0 || s.key(interacting[k - 1]) < s.key(interacting[k])),
                  "interacting contacts");
  }
  out.interacting_ = std::move(interacting);
  out.regroup(scene);
  out.indexInvolvement(n, ghostOwner);
  return out;
}

}  // namespace sqdem
