#pragma once
// A decomposed run's state as one process holding every particle would keep it
// (docs/architecture.md, "Checkpoints"): what a checkpoint holds, so that a run written at R ranks
// resumes at any R'. Particles in id order (slot = id), their positions at the last
// neighbour-list build, and the candidate contacts in key order with their histories, slot a =
// idA, slot b = idB (a wall's flag as it is), and B's image where the contact saw it: a ghost's
// position is its owner's plus an image offset, so a contact's B is found again, at any rank
// count, as the copy of idB at that position.

#include <span>
#include <vector>

#include "sqdem/distributed/communicator.hpp"
#include "sqdem/distributed/decomposition.hpp"
#include "sqdem/distributed/ghosts.hpp"
#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/interaction/contact_store.hpp"

namespace sqdem {

struct WholeState {
  ParticleStore particles;     ///< every particle, in id order, no ghosts
  std::vector<Vec3> reference;  ///< per particle, its position at the last build (empty: none yet)
  ContactStore contacts;        ///< every candidate contact, in key order (slots as above)
  std::vector<Vec3> imageOfB;   ///< per contact, the position of B's copy it saw (walls: zero)
};

/// Gathers every rank's owned particles (with their `reference` positions, one per owned slot,
/// or none) and contacts on rank 0, in id and key order; `layout` is an empty store with the
/// contacts' optional arrays. Collective; the other ranks get an empty state.
WholeState gatherWhole(const ParticleStore& p, std::span<const Vec3> reference, const ContactStore& contacts,
                       const ContactStore& layout, const Communicator& ranks);

/// Where each particle of `whole` stood at the last build (its reference), or before the first
/// build its position wrapped into `box`: what decides its owner.
std::vector<Vec3> buildPositions(const WholeState& whole, const Domain& box);

/// The particles of `whole` that `parts[rank]` owns at their build positions `at`, in id
/// order, with their references.
void keepOwned(WholeState& whole, const std::vector<SubDomain>& parts, int rank, std::span<const Vec3> at);

/// The contacts of `whole` (taken from it) whose A is owned in p (after keepOwned and with its
/// ghosts made), their slots found: A's by id, B's the copy of idB (owned, or a ghost) at the
/// position the contact saw, in the order a candidate build finds them (by the slots of A, then
/// B). Throws CheckpointError when a B has no copy there.
ContactStore placeContacts(WholeState& whole, const ParticleStore& p);

}  // namespace sqdem
