#include "sqdem/distributed/ghosts.hpp"

#include <array>

#include "particle_record.hpp"

namespace sqdem {
namespace {

/// Whether the sub-domain widened by cutoff holds y.
bool withinReach(const SubDomain& part, const Vec3& y, double cutoff) {
  return (y.array() > part.lo.array() - cutoff).all() && (y.array() < part.hi.array() + cutoff).all();
}

/// Whether x lies deeper than cutoff inside the sub-domain: then neither x nor any periodic
/// image of it is within reach of another sub-domain (they are disjoint and lie in the box along
/// the periodic directions), nor an image within reach of this one.
bool deepInside(const SubDomain& part, const Vec3& x, double cutoff) {
  return (x.array() - part.lo.array() > cutoff).all() && (part.hi.array() - x.array() > cutoff).all();
}

/// The arrays a refresh carries besides the position: what the contacts read of a ghost
/// (orientation, velocities; not the momenta, which only the owner integrates).
template <typename F>
void forEachMovingArray(ParticleStore& p, F&& f) {
  f(p.orientation);
  f(p.velocity);
  f(p.angularVelocity);
}

}  // namespace

void Ghosts::drop(ParticleStore& p) {
  const std::size_t owned = p.size();
  ParticleStore::forEachArray(p, [&](auto& array) { array.resize(owned); });
  p.ghostCount = 0;
  localOwner_.clear();
  origin_.clear();
  images_.clear();
  firstImage_ = 0;
  sends_.clear();
  sources_.clear();
  firstOf_.clear();
}

void Ghosts::build(ParticleStore& p, std::span<const Vec3> at, const Domain& domain, double cutoff,
                   const std::vector<SubDomain>& parts, const Communicator& ranks) {
  drop(p);
  const int me = ranks.rank(), count = ranks.size();
  // The image offsets along each direction: 0, and -L, +L along a periodic one.
  const Vec3 L = domain.length();
  std::array<std::array<double, 3>, 3> offsets{};
  std::array<int, 3> n{};
  for (int d = 0; d < 3; ++d) {
    offsets[d][n[d]++] = 0.0;
    if (domain.periodic[d]) offsets[d][n[d]++] = -L(d), offsets[d][n[d]++] = L(d);
  }
  // The copies for every rank first (`at` may be the store's own positions), then the ghosts.
  std::vector<std::vector<Copy>> copies(count);
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    if (deepInside(parts[me], at[i], cutoff)) continue;
    for (int z = 0; z < n[2]; ++z) {
      for (int y = 0; y < n[1]; ++y) {
        for (int x = 0; x < n[0]; ++x) {
          const Vec3 o(offsets[0][x], offsets[1][y], offsets[2][z]);
          const Vec3 image = at[i] + o;
          for (int r = 0; r < count; ++r) {
            if ((r != me || x + y + z > 0) && withinReach(parts[r], image, cutoff)) copies[r].push_back({i, o});
          }
        }
      }
    }
  }
  // A ghost record: every per-particle field of the owner, then its slot there and the image's
  // position (the owner's position + offset, added here).
  std::vector<std::string> outbox(count);
  for (int r = 0; r < count; ++r) {
    if (r == me || copies[r].empty()) continue;
    CheckpointWriter out;
    for (const Copy& c : copies[r]) {
      detail::writeParticle(out, p, c.slot);
      out.put(c.slot);
      out.put(Vec3(p.position[c.slot] + c.offset));
    }
    outbox[r] = out.bytes();
    sends_.emplace_back(r, std::move(copies[r]));
  }
  const std::vector<std::string> inbox = ranks.exchangeAll(std::move(outbox));
  for (int r = 0; r < count; ++r) {
    const auto first = static_cast<std::uint32_t>(localOwner_.size());
    if (r == me) {
      firstImage_ = first;
      for (const Copy& c : copies[me]) {
        ParticleStore::forEachArray(p, [&](auto& array) {
          const auto value = array[c.slot];  // a copy: push_back may move the array
          array.push_back(value);
        });
        p.position.back() = p.position[c.slot] + c.offset;
        images_.push_back(c);
        localOwner_.push_back(c.slot);
        origin_.push_back({me, c.slot});
      }
      continue;
    }
    if (inbox[r].empty()) continue;
    CheckpointReader in(inbox[r]);
    while (in.left() > 0) {
      detail::appendParticle(in, p);
      Origin origin{r, 0};
      in.get(origin.slot);
      in.get(p.position.back());
      localOwner_.push_back(remote);
      origin_.push_back(origin);
    }
    sources_.push_back(r);
    firstOf_.push_back(first);
  }
  p.ghostCount = localOwner_.size();
}

void Ghosts::refresh(ParticleStore& p, const Communicator& ranks) const {
  const std::size_t owned = p.size();
  for (std::size_t k = 0; k < images_.size(); ++k) {
    const std::uint32_t i = images_[k].slot;
    const std::size_t s = owned + firstImage_ + k;
    p.position[s] = p.position[i] + images_[k].offset;
    forEachMovingArray(p, [&](auto& array) { array[s] = array[i]; });
  }
  if (sends_.empty() && sources_.empty()) return;
  std::vector<std::pair<int, std::string>> outbox;
  for (const auto& [r, copies] : sends_) {
    CheckpointWriter out;
    for (const Copy& c : copies) {
      out.put(Vec3(p.position[c.slot] + c.offset));
      forEachMovingArray(p, [&](const auto& array) { out.put(array[c.slot]); });
    }
    outbox.emplace_back(r, out.bytes());
  }
  const std::vector<std::string> inbox = ranks.exchange(outbox, sources_);
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    CheckpointReader in(inbox[k]);
    for (std::size_t s = owned + firstOf_[k]; in.left() > 0; ++s) {
      in.get(p.position[s]);
      forEachMovingArray(p, [&](auto& array) { in.get(array[s]); });
    }
  }
}

}  // namespace sqdem
