// World checkpoints: raw little-endian binary of the dynamic state, preceded by a header that
// identifies the format and the world's size. Plain-data records (Contact, Wall, vectors of
// Eigen fixed-size types) are written as bytes, so a checkpoint is for the same build and
// machine architecture; it is a restart file, not an archive format.

#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <type_traits>

#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

constexpr char magic[8] = {'s', 'q', 'd', 'e', 'm', 'c', 'k', '4'};

template <typename T>
void put(std::ostream& out, const T& value) {
  static_assert(std::is_trivially_destructible_v<T>);
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
void putVector(std::ostream& out, const std::vector<T>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

template <typename T>
void get(std::istream& in, T& value) {
  in.read(reinterpret_cast<char*>(&value), sizeof(T));
  if (!in) throw std::runtime_error("checkpoint is truncated");
}

template <typename T>
void getVector(std::istream& in, std::vector<T>& v, std::uint64_t limit) {
  std::uint64_t n = 0;
  get(in, n);
  if (n > limit) throw std::runtime_error("checkpoint is corrupt (implausible array size)");
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
  if (!in) throw std::runtime_error("checkpoint is truncated");
}

}  // namespace

void World::writeState(std::ostream& out) const {
  out.write(magic, sizeof magic);
  put(out, static_cast<std::uint64_t>(particles_.size()));
  put(out, static_cast<std::uint64_t>(walls_.size()));
  ParticleStore::forEachArray(particles_, [&](const auto& array) { putVector(out, array); });
  putVector(out, boundingRadius_);
  putVector(out, walls_);
  putVector(out, wallReference_);
  putVector(out, pairs_);
  putVector(out, interacting_);
  putVector(out, neighbours_.referencePositions());
  putVector(out, neighbours_.pairs());
  put(out, neighbours_.builds());
  put(out, statistics_);
  put(out, gravity_);
  put(out, viscousDamping_);
  put(out, reorderInterval_);
  put(out, dt_);
  put(out, time_);
  put(out, forcesCurrent_);
  if (!out) throw std::runtime_error("cannot write the checkpoint");
}

void World::readState(std::istream& in) {
  char header[sizeof magic];
  in.read(header, sizeof header);
  if (!in || std::memcmp(header, magic, sizeof magic) != 0) throw std::runtime_error("not an sqdem checkpoint");
  std::uint64_t n = 0, walls = 0;
  get(in, n);
  get(in, walls);
  if (n != particles_.size() || walls != walls_.size()) {
    throw std::runtime_error("checkpoint has " + std::to_string(n) + " particles and " + std::to_string(walls) +
                             " walls; the scene builds " + std::to_string(particles_.size()) + " and " +
                             std::to_string(walls_.size()));
  }
  const std::uint64_t limit = 1ull << 34;
  ParticleStore::forEachArray(particles_, [&](auto& array) { getVector(in, array, n); });
  getVector(in, boundingRadius_, n);
  getVector(in, walls_, walls);
  getVector(in, wallReference_, walls);
  getVector(in, pairs_, limit);
  getVector(in, interacting_, limit);
  std::vector<Vec3> reference;
  std::vector<CandidatePair> candidates;
  int builds = 0;
  getVector(in, reference, n);
  getVector(in, candidates, limit);
  get(in, builds);
  neighbours_.restore(std::move(reference), std::move(candidates), builds);
  get(in, statistics_);
  get(in, gravity_);
  get(in, viscousDamping_);
  get(in, reorderInterval_);
  get(in, dt_);
  get(in, time_);
  get(in, forcesCurrent_);
  for (const Contact& c : pairs_) {
    if (c.a >= n || (c.onWall() ? (c.b & ~wallFlag) >= walls : c.b >= n)) throw std::runtime_error("checkpoint is corrupt (contact index)");
  }
  indexInvolvement();
}

}  // namespace sqdem
