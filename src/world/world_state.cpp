// World checkpoints: the dynamic state as raw little-endian records (Wall, vectors of Eigen
// fixed-size types are plain data; the contact store writes its own arrays). The file around it (checkpoint_file.hpp) carries the
// magic, the build and scene fingerprints and a checksum; here every count and index is checked
// again while reading, so even a payload that passed the checksum cannot index out of range.

#include <algorithm>
#include <cmath>

#include "sqdem/archive/checkpoint_file.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

/// The payload's version: raised whenever writeState writes other records or in another order.
constexpr std::uint64_t stateVersion = 12;

}  // namespace

std::uint64_t World::stateFingerprint() {
  Fingerprint f;
  for (const std::size_t size : {sizeof(Wall), sizeof(ContactStatistics), sizeof(CandidatePair), sizeof(Vec3),
                                 sizeof(Quat), sizeof(Vec4), sizeof(ContactStatus), sizeof(NormalHistory),
                                 sizeof(NormalLoad), sizeof(ContactEnergy), sizeof(EnergyLedger)}) {
    f(static_cast<std::uint64_t>(size));
  }
  return f(stateVersion).value();
}

void World::writeState(CheckpointWriter& out) const {
  out.put(static_cast<std::uint64_t>(particles_.size()));
  out.put(static_cast<std::uint64_t>(walls_.size()));
  // The owned particles; the ghosts are made again from the positions of the last build.
  ParticleStore::forEachArray(particles_, [&](const auto& array) { out.putPrefix(array, particles_.size()); });
  out.putVector(walls_);
  out.putVector(wallReference_);
  out.putVector(neighbours_.referencePositions());
  interactions_.writeState(out);
  out.putVector(neighbours_.pairs());
  out.put(neighbours_.builds());
  out.put(statistics_);
  out.put(gravity_);
  out.put(viscousDamping_);
  out.put(reorderInterval_);
  out.put(dt_);
  out.put(time_);
  out.put(forcesCurrent_);
  out.put(ledger_.has_value());
  if (ledger_) out.put(*ledger_);
}

void World::readState(CheckpointReader& in) {
  std::uint64_t n = 0, walls = 0;
  in.get(n);
  in.get(walls);
  if (n != particles_.size() || walls != walls_.size()) {
    throw CheckpointError("checkpoint has " + std::to_string(n) + " particles and " + std::to_string(walls) +
                          " walls; the scene builds " + std::to_string(particles_.size()) + " and " +
                          std::to_string(walls_.size()));
  }
  const std::uint64_t anyLength = ~std::uint64_t{0};  // bounded by the bytes left
  ParticleStore restored;
  ParticleStore::forEachArray(restored, [&](auto& array) {
    in.getVector(array, n);
    requireIntact(array.size() == n, "per-particle array length");
  });
  std::vector<Wall> wallRecords;
  std::vector<Vec3> wallReference, reference;
  std::vector<CandidatePair> candidates;
  int builds = 0;
  in.getVector(wallRecords, walls);
  in.getVector(wallReference, walls);
  requireIntact(wallRecords.size() == walls, "array lengths");
  for (std::size_t i = 0; i < n; ++i) {
    requireIntact(restored.shape[i] < shapes_.size() && restored.material[i] < materials_.size(), "shape or material index");
    requireIntact(restored.boundingRadius[i] == shapes_[restored.shape[i]].boundingRadius(), "bounding radius");
  }
  for (const Wall& w : wallRecords) {
    requireIntact(w.material < materials_.size(), "wall material index");
    requireIntact(w.shape == WallShape::Plane || w.shape == WallShape::Cylinder || w.shape == WallShape::Mesh, "wall shape");
    requireIntact(w.shape != WallShape::Mesh || w.mesh < meshes_.size(), "wall mesh index");
    requireIntact(std::abs(w.orientation.squaredNorm() - 1.0) < 1e-9, "wall orientation");
  }
  in.getVector(reference, n);
  requireIntact(reference.empty() || reference.size() == n, "array lengths");
  // The ghosts of the last build, as it made them (the cut-off from the scene's particles).
  Ghosts ghosts;
  if (!reference.empty()) ghosts.build(restored, reference, domain_, ghostCutoff(restored), parts_, *communicator_);
  Interactions interactions = Interactions::readState(
      in, {restored, shapes_, wallRecords, meshes_, models_, materials_.size(), neighbours_.skin(), dt_, detector_,
           ledger_.has_value()}, ghosts.localOwners());
  in.getVector(candidates, anyLength);
  in.get(builds);
  ContactStatistics statistics;
  Vec3 gravity;
  double viscousDamping = 0.0, dt = 0.0, time = 0.0;
  int reorderInterval = 0;
  bool forcesCurrent = false;
  in.get(statistics);
  in.get(gravity);
  in.get(viscousDamping);
  in.get(reorderInterval);
  in.get(dt);
  in.get(time);
  in.get(forcesCurrent);
  bool hasLedger = false;
  EnergyLedger ledger;
  in.get(hasLedger);
  requireIntact(hasLedger == ledger_.has_value(), "energy ledger");
  if (hasLedger) in.get(ledger);
  requireIntact(in.left() == 0, "trailing bytes");

  // Every index the engine will follow.
  std::vector<std::uint8_t> seen(n, 0);
  for (std::size_t i = 0; i < n; ++i) requireIntact(restored.id[i] < n && !seen[restored.id[i]]++, "particle ids");
  requireIntact(wallReference.empty() || wallReference.size() == walls, "wall reference points");
  for (const CandidatePair& c : candidates) {
    requireIntact(c.a < n && c.b < restored.slots() && restored.id[c.a] < restored.id[c.b], "candidate pair index");
  }
  requireIntact(builds >= 0 && std::isfinite(dt) && dt > 0.0 && std::isfinite(time), "counters");

  particles_ = std::move(restored);
  ghosts_ = std::move(ghosts);
  walls_ = std::move(wallRecords);
  wallReference_ = std::move(wallReference);
  interactions_ = std::move(interactions);
  neighbours_.restore(std::move(reference), std::move(candidates), builds);
  statistics_ = statistics;
  gravity_ = gravity;
  viscousDamping_ = viscousDamping;
  reorderInterval_ = reorderInterval;
  dt_ = dt;
  time_ = time;
  forcesCurrent_ = forcesCurrent;
  if (hasLedger) ledger_ = ledger;
}

}  // namespace sqdem
