#include "sqdem/interaction/interactions.hpp"

#include "sqdem/archive/checkpoint_file.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace sqdem {
namespace {

/// Index of contact k's model in InteractionScene::models.
std::uint32_t modelIndex(const InteractionScene& scene, const ContactStore& s, std::size_t k) {
  const std::uint32_t ma = scene.particles.material[s.a[k]];
  const std::uint32_t mb = s.onWall(k) ? scene.walls[s.b[k] & ~wallFlag].material : scene.particles.material[s.b[k]];
  return static_cast<std::uint32_t>(std::min(ma, mb) * scene.materialCount + std::max(ma, mb));
}

PairKind kindOf(const InteractionScene& scene, const ContactStore& s, std::size_t k) {
  const Superquadric& A = scene.shapes[scene.particles.shape[s.a[k]]];
  return s.onWall(k) ? wallPairKind(A, scene.walls[s.b[k] & ~wallFlag]) : pairKind(A, scene.shapes[scene.particles.shape[s.b[k]]]);
}

}  // namespace

ContactStore emptyStore(const InteractionScene& scene) {
  ContactStore s;
  // Round contacts (pair_kind.hpp) compute no curvatures: spheres with planes alone need no cache.
  const bool anyNonRound =
      std::any_of(scene.shapes.begin(), scene.shapes.end(), [](const Superquadric& shape) { return !shape.isSphere(); }) ||
      std::any_of(scene.walls.begin(), scene.walls.end(), [](const Wall& w) { return !w.is<PlaneWall>(); });
  s.withEnergy = scene.energy;
  for (const ContactModel& m : scene.models) {
    s.withRolling = s.withRolling || m.rolling.has_value();
    s.withBonds = s.withBonds || m.bond.has_value();
    s.withCurvatureCache = s.withCurvatureCache || (anyNonRound && m.usesCurvatures() && m.curvatureTolerance > 0.0);
    s.withTrueGap = s.withTrueGap || (anyNonRound && std::holds_alternative<TrueGapLaw>(m.normal));
  }
  return s;
}

std::size_t Interactions::setCandidates(const std::vector<CandidateKey>& candidates, const InteractionScene& scene,
                                        const std::vector<std::uint32_t>& ghostOwner) {
  if (candidates.size() > contactMask) throw std::length_error("Interactions: more than 2^29 candidate contacts");
  const std::vector<std::uint32_t>& id = scene.particles.id;
  ContactStore next = emptyStore(scene);
  next.reserve(candidates.size());
  for (const CandidateKey& c : candidates) {
    const std::uint32_t idB = (c.b & wallFlag) != 0 ? c.b : id[c.b];
    next.add({(std::uint64_t{id[c.a]} << 32) | idB, c.feature}, c.a, c.b, c.wallImage);
  }
  std::vector<std::uint32_t> previousOrder = std::move(keyOrder_);
  const ContactStore previous = std::exchange(store_, std::move(next));
  storeChanged();
  // Carry the state of pairs that persist: both stores walked in key order.
  auto old = previousOrder.begin();
  for (const std::uint32_t k : keyOrder_) {
    while (old != previousOrder.end() && previous.key(*old) < store_.key(k)) ++old;
    if (old != previousOrder.end() && previous.key(*old) == store_.key(k)) store_.carryOver(k, previous, *old);
  }
  remote_.clear();
  regroup(scene);
  indexInvolvement(scene.particles.size(), ghostOwner);
  return previous.intactBonds() - store_.intactBonds();
}

void Interactions::removeLeaving(const std::vector<std::uint8_t>& leaving) {
  std::vector<std::uint32_t> staying;
  for (std::uint32_t k = 0; k < store_.size(); ++k) {
    if (leaving[store_.a[k]] == 0) staying.push_back(k);
  }
  store_.permute(staying);
  storeChanged();
}

void Interactions::readArrived(CheckpointReader& in, std::uint64_t count) {
  for (std::uint64_t m = 0; m < count; ++m) store_.read(in);
  storeChanged();
}

void Interactions::setRemoteContacts(const std::vector<RemoteContact>& contacts, std::size_t owned,
                                     const std::vector<std::uint32_t>& ghostOwner) {
  if (contacts.size() > contactMask) throw std::length_error("Interactions: more than 2^29 remote contacts");
  remote_ = contacts;
  indexInvolvement(owned, ghostOwner);
}

void Interactions::storeChanged() {
  warmSkips_.clear();  // made afresh by the next computation that keeps records
  interactingListed_ = false;
  keyOrder_.resize(store_.size());
  std::iota(keyOrder_.begin(), keyOrder_.end(), 0u);
  std::sort(keyOrder_.begin(), keyOrder_.end(), [&](std::uint32_t x, std::uint32_t y) { return store_.key(x) < store_.key(y); });
}

const std::vector<std::uint32_t>& Interactions::listActing() const {
  if (!interactingListed_) {
    interacting_.clear();
    for (const std::uint32_t k : keyOrder_) {
      if (store_.acting[k]) interacting_.push_back(k);
    }
    interactingListed_ = true;
  }
  return interacting_;
}

void Interactions::fitStore(const InteractionScene& scene) {
  const ContactStore wanted = emptyStore(scene);
  for (TrueGapRungs& rungs : store_.trueGap) rungs = {};  // solved for the models that were (E*, cells)
  if (wanted.sameOptionalArrays(store_)) return;
  ContactStore fitted = wanted;
  for (std::size_t k = 0; k < store_.size(); ++k) {
    fitted.add(store_.key(k), store_.a[k], store_.b[k], store_.wallImage[k]);
    fitted.carryOver(k, store_, k);
  }
  store_ = std::move(fitted);
  interactingListed_ = false;
}

void Interactions::regroup(const InteractionScene& scene) {
  std::map<std::pair<PairKind, std::uint32_t>, std::vector<std::uint32_t>> members;
  for (std::uint32_t k = 0; k < store_.size(); ++k) members[{kindOf(scene, store_, k), modelIndex(scene, store_, k)}].push_back(k);
  groups_.clear();
  for (auto& [type, list] : members) groups_.push_back({type.first, type.second, std::move(list)});
  bySlot_ = std::ranges::is_sorted(store_.a);
}

std::span<const std::uint32_t> Interactions::memberShare(const Group& group, std::ptrdiff_t owned, const TeamSplit* split) const {
  const std::span<const std::uint32_t> all(group.members);
  if (!bySlot_) {
    const Share even = threadShare(static_cast<std::ptrdiff_t>(all.size()));
    return all.subspan(even.begin, even.end - even.begin);
  }
  const Share particles = split != nullptr ? split->share(owned) : threadShare(owned);
  const auto from = [&](std::ptrdiff_t slot) {  // the first member whose A is at slot or after
    return std::partition_point(all.begin(), all.end(), [&](std::uint32_t k) { return store_.a[k] < slot; }) - all.begin();
  };
  const std::ptrdiff_t begin = from(particles.begin), end = from(particles.end);
  return all.subspan(begin, end - begin);
}

void Interactions::indexInvolvement(std::size_t owned, const std::vector<std::uint32_t>& ghostOwner) {
  // B's owned slot here (remoteGhost: the contact's B is owned on another rank, which sums it).
  const auto ownerOfB = [&](std::size_t k) {
    return store_.onWall(k) ? remoteGhost : store_.b[k] < owned ? store_.b[k] : ghostOwner[store_.b[k] - owned];
  };
  // Counting sort of the contacts by particle, in key order within each particle: the store's
  // and the remote ones merged by key.
  involvementStart_.assign(owned + 1, 0);
  for (std::size_t k = 0; k < store_.size(); ++k) {
    ++involvementStart_[store_.a[k] + 1];
    if (ownerOfB(k) != remoteGhost) ++involvementStart_[ownerOfB(k) + 1];
  }
  for (const RemoteContact& r : remote_) ++involvementStart_[r.slot + 1];
  std::vector<std::uint32_t> remoteOrder(remote_.size());
  std::iota(remoteOrder.begin(), remoteOrder.end(), 0u);
  std::sort(remoteOrder.begin(), remoteOrder.end(), [&](std::uint32_t x, std::uint32_t y) { return remote_[x].key < remote_[y].key; });
  std::partial_sum(involvementStart_.begin(), involvementStart_.end(), involvementStart_.begin());
  involvement_.resize(involvementStart_.back());
  std::vector<std::uint32_t> fill(involvementStart_.begin(), involvementStart_.end() - 1);
  auto next = remoteOrder.begin();
  const auto remoteUpTo = [&](const ContactKey& key) {
    for (; next != remoteOrder.end() && remote_[*next].key < key; ++next) involvement_[fill[remote_[*next].slot]++] = remoteFlag | *next;
  };
  for (const std::uint32_t k : keyOrder_) {
    remoteUpTo(store_.key(k));
    involvement_[fill[store_.a[k]]++] = k;
    if (ownerOfB(k) != remoteGhost) involvement_[fill[ownerOfB(k)]++] = k | bodyBFlag | (store_.b[k] >= owned ? imageFlag : 0u);
  }
  remoteUpTo(ContactKey{~std::uint64_t{0}, ~std::uint32_t{0}});
}

std::array<ExactSum, 6> Interactions::energy() const {
  std::array<ExactSum, 6> sum;
  for (const ContactEnergy& e : store_.energy) {
    sum[0].add(e.stored);
    sum[1].add(e.normal);
    sum[2].add(e.damping);
    sum[3].add(e.tangential);
    sum[4].add(e.bondStored);
    sum[5].add(e.bond);
  }
  return sum;
}

std::size_t Interactions::bytes() const {
  std::size_t total = 0;
  ContactStore::forEachArray(store_, [&](const auto& array) { total += array.capacity() * sizeof(array[0]); });
  for (const Group& g : groups_) total += g.members.capacity() * sizeof(std::uint32_t);
  total += warmSkips_.capacity() * sizeof(detail::WarmSkip);
  total += (keyOrder_.capacity() + involvementStart_.capacity() + involvement_.capacity() + interacting_.capacity()) *
           sizeof(std::uint32_t);
  return total;
}

}  // namespace sqdem
