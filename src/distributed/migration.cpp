#include "sqdem/distributed/migration.hpp"

#include "particle_record.hpp"
#include "sqdem/math/permutation.hpp"

namespace sqdem {

std::size_t migrate(ParticleStore& p, Interactions& contacts, const std::vector<SubDomain>& parts,
                    const Communicator& ranks) {
  const int me = ranks.rank(), count = ranks.size();
  if (count == 1) return 0;
  std::vector<int> to(p.size());
  std::vector<std::uint8_t> leaving(p.size(), 0);
  std::vector<std::vector<std::uint32_t>> particlesTo(count);
  std::vector<std::uint32_t> staying;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    to[i] = ownerOf(parts, p.position[i]);
    leaving[i] = to[i] != me;
    (leaving[i] ? particlesTo[to[i]] : staying).push_back(i);
  }
  const ContactStore& s = contacts.store();
  std::vector<std::vector<std::uint32_t>> contactsTo(count);
  for (std::uint32_t k = 0; k < s.size(); ++k) {
    if (leaving[s.a[k]]) contactsTo[to[s.a[k]]].push_back(k);
  }
  // A message: the particles (every per-particle field), then their contacts (every kept array).
  std::vector<std::string> outbox(count);
  for (int r = 0; r < count; ++r) {
    if (particlesTo[r].empty()) continue;
    CheckpointWriter out;
    out.put(static_cast<std::uint64_t>(particlesTo[r].size()));
    for (const std::uint32_t i : particlesTo[r]) detail::writeParticle(out, p, i);
    out.put(static_cast<std::uint64_t>(contactsTo[r].size()));
    for (const std::uint32_t k : contactsTo[r]) s.write(k, out);
    outbox[r] = out.bytes();
  }
  const std::size_t left = p.size() - staying.size();
  contacts.removeLeaving(leaving);
  if (left > 0) ParticleStore::forEachArray(p, [&](auto& array) { permute(array, staying); });  // in their order
  const std::vector<std::string> inbox = ranks.exchangeAll(std::move(outbox));
  for (int r = 0; r < count; ++r) {
    if (inbox[r].empty()) continue;
    CheckpointReader in(inbox[r]);
    std::uint64_t n = 0;
    in.get(n);
    for (std::uint64_t m = 0; m < n; ++m) detail::appendParticle(in, p);
    in.get(n);
    contacts.readArrived(in, n);
  }
  return left;
}

}  // namespace sqdem
