#include "sqdem/distributed/whole_state.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "particle_record.hpp"
#include "sqdem/math/permutation.hpp"

namespace sqdem {

WholeState gatherWhole(const ParticleStore& p, std::span<const Vec3> reference, const ContactStore& contacts,
                       const ContactStore& layout, const Communicator& ranks) {
  // A rank's message: its particles (each with its reference), then its contacts (each with the
  // position of the copy of B it saw).
  CheckpointWriter out;
  const bool withReference = ranks.any(!reference.empty());  // a rank without particles has none
  if (withReference && reference.size() != p.size()) throw std::logic_error("gatherWhole: a reference per particle");
  out.put(static_cast<std::uint64_t>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) {
    detail::writeParticle(out, p, i);
    if (withReference) out.put(reference[i]);
  }
  out.put(static_cast<std::uint64_t>(contacts.size()));
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    contacts.write(k, out);
    out.put(contacts.onWall(k) ? Vec3(Vec3::Zero()) : p.position[contacts.b[k]]);
  }
  WholeState whole{{}, {}, layout, {}};
  for (std::string& message : ranks.gather(out.bytes())) {
    CheckpointReader in(message);
    std::uint64_t n = 0;
    in.get(n);
    for (std::uint64_t m = 0; m < n; ++m) {
      detail::appendParticle(in, whole.particles);
      if (withReference) in.get(whole.reference.emplace_back());
    }
    in.get(n);
    for (std::uint64_t m = 0; m < n; ++m) {
      whole.contacts.read(in);
      in.get(whole.imageOfB.emplace_back());
    }
    std::string().swap(message);  // read: rank 0 holds the whole state once
  }
  ParticleStore& all = whole.particles;
  std::vector<std::uint32_t> byId(all.size());
  for (std::uint32_t i = 0; i < all.size(); ++i) byId[all.id[i]] = i;
  ParticleStore::forEachArray(all, [&](auto& array) { permute(array, byId); });
  if (withReference) permute(whole.reference, byId);

  ContactStore& s = whole.contacts;
  std::vector<std::uint32_t> byKey(s.size());
  std::iota(byKey.begin(), byKey.end(), 0u);
  std::sort(byKey.begin(), byKey.end(), [&](std::uint32_t x, std::uint32_t y) { return s.key(x) < s.key(y); });
  s.permute(byKey);
  permute(whole.imageOfB, byKey);
  s.a = s.idA;
  s.b = s.idB;
  return whole;
}

std::vector<Vec3> buildPositions(const WholeState& whole, const Domain& box) {
  if (!whole.reference.empty()) return whole.reference;
  std::vector<Vec3> at;
  for (const Vec3& x : whole.particles.position) at.push_back(box.wrap(x));
  return at;
}

void keepOwned(WholeState& whole, const std::vector<SubDomain>& parts, int rank, std::span<const Vec3> at) {
  std::vector<std::uint32_t> mine;
  for (std::uint32_t i = 0; i < at.size(); ++i) {
    if (ownerOf(parts, at[i]) == rank) mine.push_back(i);
  }
  ParticleStore::forEachArray(whole.particles, [&](auto& array) { permute(array, mine); });
  if (!whole.reference.empty()) permute(whole.reference, mine);
}

ContactStore placeContacts(WholeState& whole, const ParticleStore& p) {
  // Every slot of this process (owned and ghosts) by id.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> copies(p.slots());
  for (std::uint32_t i = 0; i < p.slots(); ++i) copies[i] = {p.id[i], i};
  std::sort(copies.begin(), copies.end());
  const auto copiesOf = [&](std::uint32_t id) {
    return std::equal_range(copies.begin(), copies.end(), std::pair{id, 0u},
                            [](const auto& x, const auto& y) { return x.first < y.first; });
  };
  ContactStore& placed = whole.contacts;
  std::vector<std::uint32_t> here;
  for (std::uint32_t k = 0; k < placed.size(); ++k) {
    const auto [first, last] = copiesOf(placed.idA[k]);
    if (first != last && first->second < p.size()) here.push_back(k);  // A owned here
  }
  placed.permute(here);
  permute(whole.imageOfB, here);
  for (std::size_t m = 0; m < placed.size(); ++m) {
    placed.a[m] = copiesOf(placed.idA[m]).first->second;
    if (placed.onWall(m)) continue;
    // The copy at the very position the contact saw: its owner's plus the same offset, the same
    // rounded addition in any process.
    const auto [first, last] = copiesOf(placed.idB[m]);
    const auto copy = std::find_if(first, last, [&](const auto& c) { return p.position[c.second] == whole.imageOfB[m]; });
    requireIntact(copy != last, "a contact's B has no copy where the contact saw it");
    placed.b[m] = copy->second;
  }
  // In the order a candidate build finds them (by A's slot, then B's, walls after particles),
  // which keeps a particle's contacts near it in memory.
  std::vector<std::uint32_t> bySlots(placed.size());
  std::iota(bySlots.begin(), bySlots.end(), 0u);
  std::sort(bySlots.begin(), bySlots.end(), [&](std::uint32_t x, std::uint32_t y) {
    return std::tie(placed.a[x], placed.b[x], placed.feature[x]) < std::tie(placed.a[y], placed.b[y], placed.feature[y]);
  });
  placed.permute(bySlots);
  return std::move(placed);
}

}  // namespace sqdem
