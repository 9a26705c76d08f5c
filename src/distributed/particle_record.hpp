#pragma once
// A particle's record between ranks (ghosts, migration): every per-particle field of the store,
// in ParticleStore::forEachArray's order.

#include <type_traits>

#include "sqdem/archive/checkpoint_file.hpp"
#include "sqdem/dynamics/particle_store.hpp"

namespace sqdem::detail {

inline void writeParticle(CheckpointWriter& out, const ParticleStore& p, std::size_t i) {
  ParticleStore::forEachArray(p, [&](const auto& array) { out.put(array[i]); });
}

/// Appends the particle of a record written by writeParticle.
inline void appendParticle(CheckpointReader& in, ParticleStore& p) {
  ParticleStore::forEachArray(p, [&](auto& array) {
    typename std::remove_reference_t<decltype(array)>::value_type value;
    in.get(value);
    array.push_back(value);
  });
}

}  // namespace sqdem::detail
