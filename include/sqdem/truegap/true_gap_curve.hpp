#pragma once
// The true-gap law (mechanics/true_gap_law.hpp; docs/contact_laws.md, "The true-gap law") at one
// fixed pose of two posed superquadrics: the single-contact driver's curve, the Table 1 curves,
// the tests. The rungs are solved from the pair's true gap (true_gap_rungs.hpp) as the
// overlaps asked for reach them, and kept.

#include "sqdem/mechanics/true_gap_law.hpp"
#include "sqdem/truegap/pair_gap.hpp"

namespace sqdem {

class TrueGapCurve {
 public:
  /// The pair at its pose and the detector's contact there; the contact's relative radii
  /// (elliptic Hertz's, with the exact e^2, blended in near ellipsoids), E* (Pa) and the coarse
  /// grid's cells per side.
  TrueGapCurve(const PairBody& A, const PairBody& B, const ContactGeometry& contact, const RelativeRadii& radii,
               double effectiveModulus, int cells);

  /// Force (N), stiffness (N/m) and area (m^2) at the overlap (m); not acting at overlap <= 0.
  /// Throws std::runtime_error when a rung's contact fails (pair_contact.hpp).
  NormalResponse at(double overlap);
  /// The stored energy (J): the integral of the force from 0 (solves every rung below).
  double energy(double overlap);

  double weight() const { return rungs_.weight; }
  /// Rungs solved so far (each a coarse half-space contact).
  int solvedRungs() const;

 private:
  /// The law's view, its rungs solved through the overlap's segment (from the lowest rung, or
  /// that segment's only).
  NormalContact solvedTo(double overlap, bool fromLowest);

  PairGap gap_;
  NormalContact hertz_;
  TrueGapLaw law_;
  TrueGapRungs rungs_;
};

}  // namespace sqdem
