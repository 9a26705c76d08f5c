#include "sqdem/distributed/remote_loads.hpp"

#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {

void RemoteLoads::build(Interactions& contacts, const ParticleStore& p, const Ghosts& ghosts, const Communicator& ranks) {
  sends_.clear();
  sources_.clear();
  const int count = ranks.size();
  const ContactStore& s = contacts.store();
  const std::size_t owned = p.size();
  std::vector<std::vector<std::uint32_t>> to(count);
  std::vector<CheckpointWriter> out(count);
  for (std::uint32_t k = 0; k < s.size(); ++k) {
    if (s.onWall(k) || s.b[k] < owned || ghosts.localOwners()[s.b[k] - owned] != Ghosts::remote) continue;
    const Ghosts::Origin& origin = ghosts.origins()[s.b[k] - owned];
    to[origin.rank].push_back(k);
    out[origin.rank].put(RemoteContact{origin.slot, s.key(k)});
  }
  std::vector<std::string> outbox(count);
  for (int r = 0; r < count; ++r) {
    if (to[r].empty()) continue;
    outbox[r] = out[r].bytes();
    sends_.emplace_back(r, std::move(to[r]));
  }
  const std::vector<std::string> inbox = ranks.exchangeAll(std::move(outbox));
  std::vector<RemoteContact> remote;
  for (int r = 0; r < count; ++r) {
    if (inbox[r].empty()) continue;
    CheckpointReader in(inbox[r]);
    while (in.left() > 0) {
      RemoteContact c{};
      in.get(c);
      remote.push_back(c);
    }
    sources_.push_back(r);
  }
  contacts.setRemoteContacts(remote, owned, ghosts.localOwners());
}

std::vector<LoadOnB> RemoteLoads::exchange(const Interactions& contacts, const ParticleStore& p,
                                           const Communicator& ranks) const {
  std::vector<std::pair<int, std::string>> outbox;
  for (const auto& [r, list] : sends_) {
    CheckpointWriter out;
    for (const std::uint32_t k : list) out.put(contacts.loadOnB(k, p));
    outbox.emplace_back(r, out.bytes());
  }
  std::vector<LoadOnB> loads;
  for (const std::string& m : ranks.exchange(outbox, sources_)) {
    CheckpointReader in(m);
    while (in.left() > 0) {
      LoadOnB l;
      in.get(l);
      loads.push_back(l);
    }
  }
  return loads;
}

}  // namespace sqdem
