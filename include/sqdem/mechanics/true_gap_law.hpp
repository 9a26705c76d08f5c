#pragma once
// normal: true_gap (docs/contact_laws.md, "The true-gap law"): the normal force of two
// superquadrics from the half-space contact of their true gap, which holds for any gap,
// Hertzian or not (a face pressed on an edge). This file is the law's arithmetic on a contact's
// ladder of solved rungs; truegap/true_gap_rungs.hpp solves the rungs from the pair's gap, and
// the engine keeps them per contact while its curvature cache holds (curvature_cache.hpp) and
// the bodies' tilt since leaves the gap across the contact within the law's gap_tolerance of the
// overlap (holdAfterTurning).
//
// The ladder: delta_k = 2^k R_ref (k = -20 ... -1, R_ref = sqrt(R_vol,A R_vol,B)), at each rung
// the force and area of the pair's half-space contact at that approach (16 x 16 cells). Between
// two rungs the force is the power law through them,
//   F(delta) = F_k (delta / delta_k)^m_k,   m_k = log2(F_k+1 / F_k),
// below the lowest rung its segment's law continued to 0, above the highest (delta >= R_ref / 2,
// far beyond half-space theory) the highest segment's continued; the area likewise. The stiffness is
// dF/d(delta) = m_k F / delta, the stored energy the integral of F from 0, in closed form on each
// segment, F_k delta_k / (m_k + 1) [s^(m_k + 1) - 1] with s = delta / delta_k: the force is the
// energy's derivative at every overlap, and a loading-unloading cycle at a pose does no net work.
//
// Near ellipsoids the gap is Hertz's quadratic form: the law blends elliptic Hertz
// (hertz_law.hpp, 004 Eqs. 1-2) into the rungs' force by the weight
// w = min(1, max |n - 2| / 0.5) over both bodies' exponents; w = 0 (two ellipsoids) is elliptic
// Hertz exactly and needs no rung.

#include <array>
#include <cstdint>

#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/mechanics/normal_law.hpp"

namespace sqdem {

/// One rung of a ladder: the half-space contact at delta_k.
struct TrueGapRung {
  double force = 0.0;  ///< (N)
  double area = 0.0;   ///< (m^2)
  float reach1 = 0.0f;  ///< (m) how far the contact reaches along the plane's t1 (truegap/pair_gap.hpp): a bound's length
  float reach2 = 0.0f;  ///< (m) along t2
};

/// A contact's ladder (above): the rungs solved so far. A contact-step reads the head and one
/// segment's two rungs, each rung's numbers side by side: 72 bytes on two to four cache lines,
/// where an array per quantity spread them over five or more (docs/performance.md, "Cheaper
/// rungs").
struct TrueGapRungs {
  static constexpr int lowest = -20, count = 20;  // delta_k = 2^k R_ref, k = -20 ... -1

  std::uint32_t solved = 0;    ///< bit k - lowest: rung k solved
  std::uint32_t failures = 0;  ///< bit k - lowest: rung k's contact failed on this pose
  double length = 0.0;         ///< R_ref (m)
  double weight = 0.0;         ///< w of the blend (above)
  std::array<TrueGapRung, count> rung{};  ///< rung k: rung[k - lowest]

  double overlap(int k) const;  ///< delta_k (m)
  /// The lower rung of the segment holding the overlap > 0 (the lowest or highest segment's
  /// beyond the ladder).
  int segment(double overlap) const;
  bool has(int k) const { return (solved >> (k - lowest)) & 1u; }
  bool failed(int k) const { return (failures >> (k - lowest)) & 1u; }
  /// Whether both rungs of segment k are solved.
  bool hasSegment(int k) const { return has(k) && has(k + 1); }
  /// Whether the law at `overlap` has every rung it needs: none (w = 0, or no overlap), or both
  /// of the overlap's segment.
  bool holds(double overlap) const;
  /// Whether the rungs still hold after B turned against A since they were solved by a rotation
  /// vector with components tilt1, tilt2 (rad) along the plane's axes t1, t2 (its twist about n
  /// left out: it moves no point of two flat faces off their plane): the tilt changes the gap at
  /// a point (x, y) of the contact by y tilt1 - x tilt2, at most |tilt1| r2 + |tilt2| r1 with the
  /// reaches r1, r2 at the overlap segment's upper rung (its lower where only that is solved),
  /// which must stay within tolerance x overlap. True at w = 0, without overlap or without either
  /// rung.
  bool holdAfterTurning(double overlap, double tilt1, double tilt2, double tolerance) const;
  /// Rung k solved: force (N), area (m^2) > 0 and reaches (m) >= 0.
  void set(int k, double rungForce, double rungArea, double rungReach1, double rungReach2);
  void fail(int k) { failures |= 1u << (k - lowest); }
  /// Every rung unsolved (a new pose), the ladder kept.
  void forget() { solved = failures = 0; }
};

/// The weight w of the blend for the bodies' exponents n1, n2 of A and of B.
double trueGapWeight(double n1A, double n2A, double n1B, double n2B);

struct TrueGapLaw {
  static constexpr std::array<std::string_view, 2> keys{"cells", "gap_tolerance"};
  static constexpr int fewestCells = 8, mostCells = 64;
  int cells = 16;  ///< of the coarse grid, per side (fewestCells ... mostCells)
  /// The rungs are solved again once a turn of the bodies has changed the gap across the
  /// contact by this fraction of the overlap (TrueGapRungs::holdAfterTurning), [0, 1].
  double gapTolerance = 0.05;

  struct History {};
  static TrueGapLaw read(const LawInput& in, const PairElasticity& pair);

  /// c.trueGap holds the rungs around the overlap (unless w = 0); c's radii, factors and E* are
  /// elliptic Hertz's. Without them (none handed on, or not solved) elliptic Hertz.
  NormalResponse force(const NormalContact& c, double overlap, History&) const;
  /// The integral of the force from 0 (J): needs every rung up to the overlap's segment, elliptic
  /// Hertz's 2/5 F delta without them.
  double energy(const NormalContact& c, double overlap) const;
  double range(const History&) const { return 0.0; }
  double reach(double, double) const { return 0.0; }
};

}  // namespace sqdem
