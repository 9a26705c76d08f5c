#include "sqdem/distributed/migration.hpp"

#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {

std::size_t migrate(ParticleStore& p, Interactions& contacts, const std::vector<SubDomain>& parts,
                    const Communicator& ranks) {
  const int me = ranks.rank(), count = ranks.size();
  if (count == 1) return 0;
  std::vector<int> to(p.size());
  std::vector<std::uint8_t> leaving(p.size(), 0);
  std::vector<std::vector<std::uint32_t>> particlesTo(count);
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    to[i] = ownerOf(parts, p.position[i]);
    leaving[i] = to[i] != me;
    if (leaving[i]) particlesTo[to[i]].push_back(i);
  }
  const ContactStore gone = contacts.takeLeaving(leaving);
  std::vector<std::vector<std::uint32_t>> contactsTo(count);
  for (std::uint32_t k = 0; k < gone.size(); ++k) contactsTo[to[gone.a[k]]].push_back(k);
  // A message: the particles (every per-particle field), then their contacts (every kept array).
  std::vector<std::string> outbox(count);
  std::size_t left = 0;
  for (int r = 0; r < count; ++r) {
    if (particlesTo[r].empty()) continue;
    CheckpointWriter out;
    out.put(static_cast<std::uint64_t>(particlesTo[r].size()));
    for (const std::uint32_t i : particlesTo[r]) {
      ParticleStore::forEachArray(p, [&](const auto& array) { out.put(array[i]); });
    }
    out.put(static_cast<std::uint64_t>(contactsTo[r].size()));
    for (const std::uint32_t k : contactsTo[r]) gone.write(k, out);
    outbox[r] = out.bytes();
    left += particlesTo[r].size();
  }
  if (left > 0) {  // the staying particles, in their order
    std::vector<std::uint32_t> stay;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      if (!leaving[i]) stay.push_back(i);
    }
    ParticleStore::forEachArray(p, [&](auto& array) {
      for (std::size_t m = 0; m < stay.size(); ++m) array[m] = array[stay[m]];
      array.resize(stay.size());
    });
  }
  const std::vector<std::string> inbox = ranks.exchangeAll(std::move(outbox));
  ContactStore arrived = gone;
  arrived.retain([](std::size_t) { return false; });  // empty, the same optional arrays
  for (int r = 0; r < count; ++r) {
    if (inbox[r].empty()) continue;
    CheckpointReader in(inbox[r]);
    std::uint64_t n = 0;
    in.get(n);
    for (std::uint64_t m = 0; m < n; ++m) {
      ParticleStore::forEachArray(p, [&](auto& array) {
        typename std::remove_reference_t<decltype(array)>::value_type value;
        in.get(value);
        array.push_back(value);
      });
    }
    in.get(n);
    for (std::uint64_t m = 0; m < n; ++m) arrived.read(in);
  }
  contacts.addArrived(arrived);
  return left;
}

}  // namespace sqdem
