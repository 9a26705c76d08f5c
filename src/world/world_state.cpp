// World checkpoints (docs/architecture.md, "Checkpoints"): the dynamic state as one process holding
// every particle would keep it (distributed/whole_state.hpp), gathered from the ranks and written
// by rank 0, read by every rank, which keeps its share, so that a run written at R ranks resumes
// at any R'. Raw little-endian records (Wall and vectors of Eigen fixed-size types are plain
// data). The file around it (checkpoint_file.hpp) carries the magic, the build and scene
// fingerprints and a checksum; here every count and index is checked again while reading, so
// even a payload that passed the checksum cannot index out of range.

#include <algorithm>
#include <cmath>

#include "sqdem/archive/checkpoint_file.hpp"
#include "sqdem/distributed/whole_state.hpp"
#include "sqdem/math/permutation.hpp"
#include "sqdem/world/spatial_order.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

/// The payload's version: raised whenever writeState (or the run checkpoint around it) writes other
/// records or in another order.
constexpr std::uint64_t stateVersion = 21;

/// Checks what the engine will follow in a whole state of n particles and `walls` walls (every
/// rank reads the same, so every rank throws alike).
void requireWholeIntact(const WholeState& whole, std::size_t walls, const std::vector<MeshFeatures>& meshes,
                        const std::vector<Wall>& wallRecords) {
  const ParticleStore& p = whole.particles;
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) requireIntact(p.id[i] == i, "particle ids");
  requireIntact(whole.reference.empty() || whole.reference.size() == n, "array lengths");
  const ContactStore& s = whole.contacts;
  requireIntact(whole.imageOfB.size() == s.size(), "array lengths");
  for (std::size_t k = 0; k < s.size(); ++k) {
    requireIntact(s.idA[k] < n && s.a[k] == s.idA[k], "contact body A");
    requireIntact(s.onWall(k) ? (s.idB[k] & ~wallFlag) < walls && s.b[k] == s.idB[k]
                              : s.idB[k] < n && s.b[k] == s.idB[k] && s.idA[k] < s.idB[k],
                  "contact body B");
    requireIntact(static_cast<unsigned>(s.status[k]) <= static_cast<unsigned>(ContactStatus::Degenerate), "contact status");
    const Wall* wall = s.onWall(k) ? &wallRecords[s.idB[k] & ~wallFlag] : nullptr;
    const MeshWall* mesh = wall != nullptr ? wall->as<MeshWall>() : nullptr;
    requireIntact(mesh != nullptr ? s.feature[k] < meshes[mesh->mesh].featureCount() : s.feature[k] == 0, "mesh feature");
    requireIntact(k == 0 || s.key(k - 1) < s.key(k), "contact keys");
    if (s.withBonds) {
      const BondRecord& b = s.bond[k];
      requireIntact(b.state <= BondRecord::State::Broken && (!b.intact() || (b.radius > 0.0 && std::isfinite(b.radius))), "bond");
    }
  }
}

}  // namespace

std::uint64_t World::stateFingerprint() {
  Fingerprint f;
  for (const std::size_t size : {sizeof(Wall), sizeof(ContactStatistics), sizeof(Vec3), sizeof(Quat), sizeof(Vec4),
                                 sizeof(ContactStatus), sizeof(NormalHistory), sizeof(NormalLoad), sizeof(ContactEnergy), sizeof(TrueGapRungs),
                                 sizeof(EnergyLedger)}) {
    f(static_cast<std::uint64_t>(size));
  }
  return f(stateVersion).value();
}

ContactStatistics World::totalStatistics() const {
  std::vector<long long> counts;
  ContactStatistics::forEachCount(statistics_, [&](long long count) { counts.push_back(count); });
  communicator_->sum(counts);
  ContactStatistics total;
  auto next = counts.begin();
  ContactStatistics::forEachCount(total, [&](long long& count) { count = *next++; });
  return total;
}

void World::writeState(CheckpointWriter& out) const {
  const WholeState whole = gatherWhole(particles_, neighbours_.referencePositions(), interactions_.store(),
                                       emptyStore(interactionScene()), *communicator_);
  const ContactStatistics statistics = totalStatistics();
  if (communicator_->rank() != 0) return;
  out.put(static_cast<std::uint64_t>(whole.particles.size()));
  out.put(static_cast<std::uint64_t>(walls_.size()));
  ParticleStore::forEachArray(whole.particles, [&](const auto& array) { out.putVector(array); });
  out.putVector(whole.reference);
  whole.contacts.writeArrays(out);
  out.putVector(whole.imageOfB);
  out.putVector(walls_);
  out.putVector(wallReference_);
  out.put(neighbours_.builds());
  out.put(statistics);
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
  const auto scene = static_cast<std::uint64_t>(communicator_->sum(static_cast<long long>(particles_.size())));
  if (n != scene || walls != walls_.size()) {
    throw CheckpointError("checkpoint has " + std::to_string(n) + " particles and " + std::to_string(walls) +
                          " walls; the scene builds " + std::to_string(scene) + " and " + std::to_string(walls_.size()));
  }
  WholeState whole;
  ParticleStore::forEachArray(whole.particles, [&](auto& array) {
    in.getVector(array, n);
    requireIntact(array.size() == n, "per-particle array length");
  });
  in.getVector(whole.reference, n);
  whole.contacts = ContactStore::readArrays(in, emptyStore(interactionScene()));
  in.getVector(whole.imageOfB, whole.contacts.size());
  std::vector<Wall> wallRecords;
  std::vector<Vec3> wallReference;
  int builds = 0;
  in.getVector(wallRecords, walls);
  in.getVector(wallReference, walls);
  requireIntact(wallRecords.size() == walls, "array lengths");
  ContactStatistics statistics;
  Vec3 gravity;
  double viscousDamping = 0.0, dt = 0.0, time = 0.0;
  int reorderInterval = 0;
  bool forcesCurrent = false;
  in.get(builds);
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
  const ParticleStore& all = whole.particles;
  for (std::size_t i = 0; i < n; ++i) {
    requireIntact(all.shape[i] < shapes_.size() && all.material[i] < materials_.size(), "shape or material index");
    requireIntact(all.boundingRadius[i] == shapes_[all.shape[i]].boundingRadius(), "bounding radius");
  }
  for (const Wall& w : wallRecords) {
    requireIntact(w.material < materials_.size(), "wall material index");
    requireIntact(w.surface.index() < std::variant_size_v<WallSurface>, "wall shape");  // before any visit
    if (const MeshWall* mesh = w.as<MeshWall>()) {
      requireIntact(mesh->mesh < meshes_.size(), "wall mesh index");
      requireIntact(std::abs(mesh->orientation.squaredNorm() - 1.0) < 1e-9, "wall orientation");
    }
  }
  requireWholeIntact(whole, walls, meshes_, wallRecords);
  requireIntact(wallReference.empty() || wallReference.size() == walls, "wall reference points");
  requireIntact(builds >= 0 && std::isfinite(dt) && dt > 0.0 && std::isfinite(time), "counters");

  // This rank's share: the sub-domains cut afresh by counts (the result does not depend on
  // them), the particles of its own, their ghosts as the last build made them (from its
  // positions), the contacts of its A with their B's copies found again.
  const std::vector<Vec3> at = buildPositions(whole, domain_);
  for (const Vec3& x : at) requireIntact(wholeBox(domain_).owns(x), "positions at the last build");
  std::vector<SubDomain> parts{wholeBox(domain_)};
  if (communicator_->size() > 1) {
    parts = bisect(domain_, at, std::vector<double>(n, 1.0), communicator_->size(), SerialCommunicator());
  }
  keepOwned(whole, parts, communicator_->rank(), at);
  // The slots along a Hilbert curve of the build's positions, as a re-ordering run keeps them
  // (memory traffic only: slots change no result).
  if (reorderInterval > 0 && !whole.reference.empty()) {
    const std::vector<std::uint32_t> order = hilbertOrder(whole.reference);
    ParticleStore::forEachArray(whole.particles, [&](auto& array) { permute(array, order); });
    permute(whole.reference, order);
  }
  Ghosts ghosts;
  if (!whole.reference.empty()) {
    ghosts.build(whole.particles, whole.reference, domain_, ghostCutoff(whole.particles), parts, *communicator_);
  }
  std::optional<Interactions> interactions;
  std::string trouble;
  try {
    interactions = Interactions::restore(
        placeContacts(whole, whole.particles),
        {whole.particles, shapes_, wallRecords, meshes_, models_, materials_.size(), neighbours_.skin(), dt_, detector_,
         ledger_.has_value()},
        ghosts.localOwners());
  } catch (const CheckpointError& e) {
    trouble = e.what();
  }
  if (communicator_->any(!trouble.empty())) {  // every rank stops alike
    throw CheckpointError(trouble.empty() ? "checkpoint is corrupt (a contact does not fit another rank's particles)" : trouble);
  }

  particles_ = std::move(whole.particles);
  ghosts_ = std::move(ghosts);
  parts_ = std::move(parts);
  walls_ = std::move(wallRecords);
  wallReference_ = std::move(wallReference);
  interactions_ = std::move(*interactions);
  if (communicator_->size() > 1) {  // and the loads of the checkpointed step on the others' particles
    remoteLoads_.build(interactions_, particles_, ghosts_, *communicator_);
    remoteLoadsNow_ = remoteLoads_.exchange(interactions_, particles_, *communicator_);
  }
  neighbours_.restore(std::move(whole.reference), builds);
  statistics_ = communicator_->rank() == 0 ? statistics : ContactStatistics{};  // the run's totals, counted once
  gravity_ = gravity;
  viscousDamping_ = viscousDamping;
  reorderInterval_ = reorderInterval;
  dt_ = dt;
  time_ = time;
  forcesCurrent_ = forcesCurrent;
  if (hasLedger) ledger_ = ledger;
}

}  // namespace sqdem
