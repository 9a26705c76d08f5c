#pragma once
// Broad phase with a Verlet skin (DESIGN.md §3). Candidate pairs are particles whose bounding
// spheres come closer than the skin; the list stays valid until some particle has moved more
// than half the skin since the build. The pairs are found by one of two searches, chosen per
// scene (`broad_phase`):
//   CellList  uniform cells at least the largest bounding diameter + skin wide (polydisperse
//             beds stay correct: small particles just share cells), cell_list_pairs.cpp
//   AabbTree  FCL's dynamic AABB tree of the skin-inflated bounding spheres, aabb_tree_pairs.cpp
//             (own CMake target: FCL's headers stay out of the engine)
// Both return the same sorted list; periodic images in any of x, y, z (the nearest image of a
// pair when the box is narrower than three reaches).

#include <cstdint>
#include <vector>

#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/world/domain.hpp"

namespace sqdem {

/// A candidate pair: particle b is seen at position[b] + shift (its periodic image) from a; a < b.
struct CandidatePair {
  std::uint32_t a, b;
  Vec3 shift;
};

enum class BroadPhase { CellList, AabbTree };

/// The pairs (a < b, sorted by (a, b)) whose bounding spheres, radius[i], come closer than skin
/// (m) at the given positions (wrapped into the periodic directions).
std::vector<CandidatePair> cellListPairs(const Domain& domain, const std::vector<Vec3>& position,
                                         const std::vector<double>& radius, double skin);
std::vector<CandidatePair> aabbTreePairs(const Domain& domain, const std::vector<Vec3>& position,
                                         const std::vector<double>& radius, double skin);

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
