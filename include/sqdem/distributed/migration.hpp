#pragma once
// Migration (docs/architecture.md, "Ghosts"): at a neighbour-list build every particle whose
// centre has left this rank's sub-domain moves to the rank that owns it now, with the contacts
// it is A of (their histories: a contact lives where its A is owned).

#include <vector>

#include "sqdem/distributed/communicator.hpp"
#include "sqdem/distributed/decomposition.hpp"
#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/interaction/interactions.hpp"

namespace sqdem {

/// Sends every owned particle (centres wrapped into the box; no ghosts in the store) that another
/// rank's sub-domain owns there, with its contacts, and appends the particles the other ranks
/// send this one, in rank order, their contacts added to `contacts` for the carry-over by key.
/// Returns how many particles left this rank. Collective.
std::size_t migrate(ParticleStore& p, Interactions& contacts, const std::vector<SubDomain>& parts,
                    const Communicator& ranks);

}  // namespace sqdem
