#pragma once
// Ghosts (docs/architecture.md, "Ghosts"): copies of particles that this process's particles must
// see but that it does not own, kept in the slots after the owned ones (ParticleStore). A ghost
// is an image x + o of a particle (o = 0, or each component +-L along a periodic direction) that
// lies within the interaction cut-off of a rank's sub-domain, other than the particle itself in
// its own rank: the particles of the neighbouring ranks near this one's faces, and the periodic
// images, of this rank's particles or of others'. So a particle near a periodic face or a rank
// face meets the particles across it as ghosts, the broad phase searches an open box, and no
// contact carries a shift of its own.
//
// Ghosts are chosen when the neighbour list is built, from the positions of that build, and
// refreshed at every force computation: a ghost's position is its owner's plus the image offset,
// added by the owner's process, so every contact with a ghost sees the same bits in whatever
// process computes it.

#include <cstdint>
#include <span>
#include <vector>

#include "sqdem/distributed/communicator.hpp"
#include "sqdem/distributed/decomposition.hpp"
#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/geometry/domain.hpp"
#include "sqdem/interaction/interactions.hpp"

namespace sqdem {

class Ghosts {
 public:
  /// localOwners' entry for a ghost whose particle another rank owns (what Interactions reads).
  static constexpr std::uint32_t remote = Interactions::remoteGhost;

  /// Replaces the ghosts: every image x + o of an owned particle at `at` (one per owned slot,
  /// wrapped into the box; may be p.position) that rank r's sub-domain parts[r], widened by
  /// `cutoff` (m), holds becomes a ghost on rank r, except o = 0 on the particle's own rank. In
  /// order of the sending rank, then of the sender's slots, then of the offsets. cutoff must cover
  /// the largest pair reach (r_a + r_b + skin + law range). Collective across the ranks.
  void build(ParticleStore& p, std::span<const Vec3> at, const Domain& domain, double cutoff,
             const std::vector<SubDomain>& parts, const Communicator& ranks);
  /// Removes the ghosts from the store.
  void drop(ParticleStore& p);
  /// Copies the owners' moving state (position + offset, orientation, velocities) to their
  /// ghosts, here and on the other ranks. Collective. (A ghost's other fields are those of the
  /// build: the contacts do not read its momenta.)
  void refresh(ParticleStore& p, const Communicator& ranks) const;
  /// Per ghost (slot p.size() + g), the owned slot it stands for, or `remote`.
  const std::vector<std::uint32_t>& localOwners() const { return localOwner_; }
  /// Where a ghost's particle is owned: its rank and its slot there.
  struct Origin {
    int rank;
    std::uint32_t slot;
  };
  const std::vector<Origin>& origins() const { return origin_; }
  /// Adds every ghost's entry of a per-slot array (slots() entries) to its owner's and drops the
  /// ghosts' entries (counts per particle, say). Only ghosts of this rank's particles: the
  /// others' entries stay with the contacts' loads sent to their owners (remote_loads.hpp).
  template <typename T>
  void fold(const ParticleStore& p, std::vector<T>& perSlot) const {
    const std::size_t owned = p.size();
    for (std::size_t g = 0; g < localOwner_.size(); ++g) {
      if (localOwner_[g] != remote) perSlot[localOwner_[g]] += perSlot[owned + g];
    }
    perSlot.resize(owned);
  }

 private:
  /// A copy this rank sends at every refresh: its slot and the image offset.
  struct Copy {
    std::uint32_t slot;
    Vec3 offset;
  };
  std::vector<std::uint32_t> localOwner_;  ///< per ghost, its owner's slot here, or remote
  std::vector<Origin> origin_;             ///< per ghost, its owner's rank and slot
  std::vector<Copy> images_;               ///< this rank's ghosts of its own particles, in ghost order
  std::uint32_t firstImage_ = 0;           ///< ... the first of them (offset from p.size())
  std::vector<std::pair<int, std::vector<Copy>>> sends_;  ///< per other rank, the copies it gets
  std::vector<int> sources_;               ///< the other ranks that send this one ghosts
  std::vector<std::uint32_t> firstOf_;     ///< ... and the first ghost of each (offset from p.size())
};

}  // namespace sqdem
