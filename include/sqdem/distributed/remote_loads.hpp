#pragma once
// Loads across ranks (docs/architecture.md, "Ghosts"): a contact is computed where its A is
// owned; when its B is a ghost of another rank's particle, B's load goes to that rank every
// step, where B adds it in key order with its own contacts (Interactions::setRemoteContacts), so
// B's sum has the same terms in the same order as in one process.

#include <cstdint>
#include <utility>
#include <vector>

#include "sqdem/distributed/communicator.hpp"
#include "sqdem/distributed/ghosts.hpp"
#include "sqdem/interaction/interactions.hpp"

namespace sqdem {

class RemoteLoads {
 public:
  /// After a candidate build: tells every rank which contacts of its particles this one computes
  /// (B's slot there and the key) and sets the ones the other ranks compute for this rank's
  /// particles into `contacts`. Collective.
  void build(Interactions& contacts, const ParticleStore& p, const Ghosts& ghosts, const Communicator& ranks);
  /// Sends this step's loads on the other ranks' Bs and returns the loads the others computed
  /// for this rank's particles, in setRemoteContacts' order. Between the partners of the build.
  std::vector<LoadOnB> exchange(const Interactions& contacts, const ParticleStore& p, const Communicator& ranks) const;

 private:
  std::vector<std::pair<int, std::vector<std::uint32_t>>> sends_;  ///< per rank, the contacts whose B it owns
  std::vector<int> sources_;  ///< the ranks that send this one loads, in order
};

}  // namespace sqdem
