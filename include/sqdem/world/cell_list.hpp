#pragma once
// Broad phase: a cell list with a Verlet skin (DESIGN.md §3). Candidate pairs are particles whose
// bounding spheres come closer than the skin; the list stays valid until some particle has moved
// more than half the skin since the build. Cells are at least the largest bounding diameter plus
// the skin wide, so polydisperse beds stay correct (small particles just share cells).
// Periodic directions need at least three cells (checked at start-up by the scene loader).

#include <cstdint>
#include <vector>

#include "sqdem/dynamics/particle_store.hpp"
#include "sqdem/world/domain.hpp"

namespace sqdem {

/// A candidate pair: particle b is seen at position[b] + shift (its periodic image) from a.
struct CandidatePair {
  std::uint32_t a, b;
  Vec3 shift;
};

class CellList {
 public:
  /// skin (m): extra distance kept in the list.
  CellList(const Domain& domain, double skin) : domain_(domain), skin_(skin) {}

  /// True when a particle has moved more than skin/2 since the last build (or never built).
  bool needsRebuild(const ParticleStore& particles) const;
  /// Wraps periodic positions into the box, then rebuilds the sorted candidate list.
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

 private:
  Domain domain_;
  double skin_;
  std::vector<Vec3> reference_;  ///< positions at the last build
  std::vector<CandidatePair> pairs_;
  int builds_ = 0;
};

/// The smallest number of cells per direction the cell list needs for periodic directions.
inline constexpr int minimumPeriodicCells = 3;

}  // namespace sqdem
