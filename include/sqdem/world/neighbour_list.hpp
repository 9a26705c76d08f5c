#pragma once
// Broad phase with a Verlet skin (docs/architecture.md, "A step", "Identity", "Ghosts").
// Candidate pairs are particles whose bounding spheres come closer than the skin; the list stays
// valid until some particle has moved more than half the skin since the build. The search runs
// in open space over the owned particles and their ghosts (periodic images are ghosts,
// distributed/ghosts.hpp), by one of two methods, chosen per scene (`broad_phase`):
//   CellList  uniform cells at least the largest bounding diameter + skin wide (polydisperse
//             beds stay correct: small particles just share cells), cell_list_pairs.cpp
//   AabbTree  FCL's dynamic AABB tree of the skin-inflated bounding spheres, aabb_tree_pairs.cpp
//             (own CMake target: FCL's headers stay out of the engine)
// Both return the same sorted list. Both test a pair by a distance that is the same seen from
// either particle (candidateDistanceSquared) and orient it by id (oriented), so that whether a
// pair is a candidate depends neither on the slots nor on which process finds it.

#include <cstdint>
#include <vector>

#include "sqdem/dynamics/particle_store.hpp"

namespace sqdem {

/// A candidate pair of slots, id[a] < id[b].
struct CandidatePair {
  std::uint32_t a, b;
};

/// What the searches read: positions, bounding radii (m) and ids, per slot.
struct ParticleCloud {
  const std::vector<Vec3>& position;
  const std::vector<double>& radius;
  const std::vector<std::uint32_t>& id;
};

/// Slots i and j as a pair oriented by id.
inline CandidatePair oriented(const ParticleCloud& cloud, std::uint32_t i, std::uint32_t j) {
  return cloud.id[i] < cloud.id[j] ? CandidatePair{i, j} : CandidatePair{j, i};
}
/// The squared centre distance (m^2) of slots i and j: the same bits seen from j (x_i - x_j is
/// exactly -(x_j - x_i)), so the test needs no orientation and gives every process the same
/// answer.
inline double candidateDistanceSquared(const ParticleCloud& cloud, std::uint32_t i, std::uint32_t j) {
  return (cloud.position[j] - cloud.position[i]).squaredNorm();
}
/// Whether the bounding spheres of slots i and j at that distance come closer than the skin.
inline bool withinSkin(const ParticleCloud& cloud, std::uint32_t i, std::uint32_t j, double distanceSquared, double skin) {
  const double reach = cloud.radius[i] + cloud.radius[j] + skin;
  return distanceSquared < reach * reach;
}

enum class BroadPhase { CellList, AabbTree };

/// The broad phase for particles of bounding radii `radii` and a skin (m): the cell list unless
/// its cells (2 r_max + skin wide) would hold more than 30 particles at a dense packing (bounding
/// spheres at 0.6 of the volume), then the AABB tree. Measured (bench_broad_phase, 10^5
/// particles): the cell list is 2.7-4.4x faster where cells hold a few particles (monodisperse,
/// radii 1:10 uniform: 1.3 and 4 at 0.6), the tree 5x faster for 1 % large among small at 1:20
/// (115) and 6-70x for an electrode's NMC among carbon-binder particles 1:10-1:50 (200 and more).
BroadPhase automaticBroadPhase(const std::vector<double>& radii, double skin);

/// The pairs (oriented by id, sorted by (a, b)) whose bounding spheres come closer than skin (m).
std::vector<CandidatePair> cellListPairs(const ParticleCloud& cloud, double skin);
std::vector<CandidatePair> aabbTreePairs(const ParticleCloud& cloud, double skin);

class NeighbourList {
 public:
  /// skin (m): extra distance kept in the list.
  explicit NeighbourList(double skin, BroadPhase search = BroadPhase::CellList)
      : skin_(skin), limit_(0.25 * skin * skin), search_(search) {}

  /// True when an owned particle has moved more than skin/2 since the last build (or never built).
  bool needsRebuild(const ParticleStore& particles) const;
  /// Whether owned slot i, now at x, has moved more than skin/2 since the last build (the step's
  /// drift asks for each of its particles); the build must cover the slots (covers).
  bool outOfSkin(std::size_t i, const Vec3& x) const { return i >= reference_.size() || (x - reference_[i]).squaredNorm() > limit_; }
  /// Whether the last build was of `owned` particles.
  bool covers(std::size_t owned) const { return reference_.size() == owned; }
  /// Rebuilds the candidate list from where the owned particles and their ghosts are now: the
  /// pairs whose A (the lower id) is owned. reach[s] is slot s's bounding-sphere radius (m).
  void rebuild(const ParticleStore& particles, const std::vector<double>& reach);

  const std::vector<CandidatePair>& pairs() const { return pairs_; }
  /// The build state, for checkpoints: owned positions at the last build (the candidate list
  /// is used once, by the build that makes it, and not kept across a restore).
  const std::vector<Vec3>& referencePositions() const { return reference_; }
  void restore(std::vector<Vec3> reference, int builds) {
    reference_ = std::move(reference);
    pairs_.clear();
    builds_ = builds;
  }
  int builds() const { return builds_; }
  double skin() const { return skin_; }
  BroadPhase search() const { return search_; }

 private:
  double skin_;
  double limit_;  ///< (skin/2)^2 (m^2)
  BroadPhase search_;
  std::vector<Vec3> reference_;  ///< owned positions at the last build
  std::vector<CandidatePair> pairs_;
  int builds_ = 0;
};

}  // namespace sqdem
