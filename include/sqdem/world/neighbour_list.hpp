#pragma once
// Broad phase with a Verlet skin (docs/architecture.md, "A step", "Identity"). Candidate pairs are particles whose bounding
// spheres come closer than the skin; the list stays valid until some particle has moved more
// than half the skin since the build. The pairs are found by one of two searches, chosen per
// scene (`broad_phase`):
//   CellList  uniform cells at least the largest bounding diameter + skin wide (polydisperse
//             beds stay correct: small particles just share cells), cell_list_pairs.cpp
//   AabbTree  FCL's dynamic AABB tree of the skin-inflated bounding spheres, aabb_tree_pairs.cpp
//             (own CMake target: FCL's headers stay out of the engine)
// Both return the same sorted list; periodic images in any of x, y, z (the nearest image of a
// pair when the box is narrower than three reaches). Both test a pair by a distance that is the
// same seen from either particle (candidateDistanceSquared) and orient it by id (oriented), so
// that whether a pair is a candidate, and which image it takes, depends neither on the slots
// nor on which process finds it.

#include <cstdint>
#include <vector>

#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/world/domain.hpp"

namespace sqdem {

/// A candidate pair of slots: particle b is seen at position[b] + shift (its periodic image)
/// from a; id[a] < id[b].
struct CandidatePair {
  std::uint32_t a, b;
  Vec3 shift;
};

/// What the searches read: positions (wrapped into the periodic directions), bounding radii
/// (m) and ids, per slot.
struct ParticleCloud {
  const std::vector<Vec3>& position;
  const std::vector<double>& radius;
  const std::vector<std::uint32_t>& id;
};

/// Slots i and j, j seen at position[j] + shift from i, as a pair oriented by id.
inline CandidatePair oriented(const ParticleCloud& cloud, std::uint32_t i, std::uint32_t j, const Vec3& shift) {
  return cloud.id[i] < cloud.id[j] ? CandidatePair{i, j, shift} : CandidatePair{j, i, Vec3(-shift)};
}
/// The squared centre distance (m^2) of slots i and j, j seen at position[j] + shift from i:
/// the same bits seen from j (x_i - x_j - s is exactly -(x_j - x_i + s)), so the test needs no
/// orientation and gives every process the same answer.
inline double candidateDistanceSquared(const ParticleCloud& cloud, std::uint32_t i, std::uint32_t j, const Vec3& shift) {
  return ((cloud.position[j] - cloud.position[i]) + shift).squaredNorm();
}
/// Whether the bounding spheres of slots i and j at that distance come closer than the skin.
inline bool withinSkin(const ParticleCloud& cloud, std::uint32_t i, std::uint32_t j, double distanceSquared, double skin) {
  const double reach = cloud.radius[i] + cloud.radius[j] + skin;
  return distanceSquared < reach * reach;
}

enum class BroadPhase { CellList, AabbTree };

/// The pairs (oriented by id, sorted by (a, b)) whose bounding spheres come closer than skin (m).
std::vector<CandidatePair> cellListPairs(const Domain& domain, const ParticleCloud& cloud, double skin);
std::vector<CandidatePair> aabbTreePairs(const Domain& domain, const ParticleCloud& cloud, double skin);

class NeighbourList {
 public:
  /// skin (m): extra distance kept in the list.
  NeighbourList(const Domain& domain, double skin, BroadPhase search = BroadPhase::CellList)
      : domain_(domain), skin_(skin), search_(search) {}

  /// True when a particle has moved more than skin/2 since the last build (or never built).
  bool needsRebuild(const ParticleStore& particles) const;
  /// Wraps periodic positions into the box, then rebuilds the candidate list.
  /// boundingRadius[i] is particle i's bounding-sphere radius (m).
  void rebuild(ParticleStore& particles, const std::vector<double>& boundingRadius);

  const std::vector<CandidatePair>& pairs() const { return pairs_; }
  /// Forces a rebuild at the next check (after the particles were re-ordered).
  void invalidate() { reference_.clear(); }
  /// The build state, for checkpoints: positions at the last build and the candidate list.
  const std::vector<Vec3>& referencePositions() const { return reference_; }
  void restore(std::vector<Vec3> reference, std::vector<CandidatePair> pairs, int builds) {
    reference_ = std::move(reference);
    pairs_ = std::move(pairs);
    builds_ = builds;
  }
  int builds() const { return builds_; }
  double skin() const { return skin_; }
  BroadPhase search() const { return search_; }

 private:
  Domain domain_;
  double skin_;
  BroadPhase search_;
  std::vector<Vec3> reference_;  ///< positions at the last build
  std::vector<CandidatePair> pairs_;
  int builds_ = 0;
};

}  // namespace sqdem
