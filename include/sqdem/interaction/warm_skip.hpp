#pragma once
// Warm solves confirmed without evaluating a surface (docs/performance.md, "Confirmed warm
// answers"). A pair's warm solve starts from its last surface points; in a settled bed
// its first residual mostly passes the tolerance, and it returns those points at the new poses.
// That residual needs both surfaces' normals at the points, the gradients that cost most of a warm
// solve (powers and roots for blocky shapes). A's point and normal are fixed in A's body frame and
// B's in B's, so with both normals kept from the last evaluation confirmContact (detector.hpp)
// computes the residual from the new relative pose alone and, where it is within the tolerance,
// returns the warm solve's answer to the same bits. This is each contact's record of the normals,
// kept for quiet pairs only (their last solve took no Newton step and left the residual within half
// the tolerance: a pair that moves by about the tolerance a step would fail the confirmation and
// pay it on top of its solve).

#include <cstdint>

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/math/types.hpp"

namespace sqdem::detail {

struct WarmSkip {
  /// Confirmations in a row before the next evaluation: each re-expresses B's point in the new
  /// relative frame (the warm solve's round trip, ~1e-16 of its size a step) while the kept B
  /// normal stays that of the evaluated point; evaluating every so often keeps the two within
  /// confirmContact's margin (16 round trips of a 1e-3 m body: ~1e-17 m).
  static constexpr std::uint32_t mostInARow = 16;

  /// Whether an evaluated answer is kept: its warm start solved it without a Newton step, with
  /// the residual within half the tolerance (m), so the next step's confirmation will likely pass.
  static bool quiet(const ContactGeometry& g, double tolerance) {
    return g.converged() && g.iterations == 0 && g.residual <= 0.5 * tolerance;
  }

  Vec3 normalA = Vec3::Zero();  ///< A's outward normal at the pair's point, A's body frame
  Vec3 normalB = Vec3::Zero();  ///< B's, B's body frame
  std::uint32_t left = 0;       ///< confirmations allowed before an evaluation; 0: none kept

  /// After an evaluated answer of a quiet pair.
  void restart(const Vec3& localNormalA, const Vec3& localNormalB) { *this = {localNormalA, localNormalB, mostInARow}; }
  void unset() { left = 0; }
};

}  // namespace sqdem::detail
