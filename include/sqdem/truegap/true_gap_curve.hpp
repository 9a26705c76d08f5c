#pragma once
// The true-gap law at a fixed pose (docs/contact_laws.md, "The true-gap law"): the normal force
// of two superquadrics against their overlap delta from the half-space contact of their true gap
// (pair_contact.hpp), which holds for any gap, Hertzian or not (a face pressed on an edge).
//
// The contact is solved on a coarse grid (16 x 16 cells over the region where the gap is below
// delta: 0.7 % from the 128-cell reference at the largest) at the rungs of a ladder
// delta_k = 2^k R_ref (k = -20 ... -1, R_ref = sqrt(R_vol,A R_vol,B)), each when first needed
// and then kept. Between two rungs the force is the power law through them,
//   F(delta) = F_k (delta / delta_k)^m_k,   m_k = log2(F_k+1 / F_k),
// and below the lowest rung its segment's law continued to 0; the area likewise. The stiffness is
// dF/d(delta) = m_k F / delta and the stored energy the integral of F from 0, so the force is the
// energy's derivative at every overlap: loading and unloading at a fixed pose do no net work.
//
// Near ellipsoids the gap is Hertz's quadratic form, and the law is elliptic Hertz
// (mechanics/hertz_law.hpp, 004 Eqs. 1-2) blended into the true gap's force by the weight
// w = min(1, max |n - 2| / 0.5) over both bodies' exponents: w = 0 (two ellipsoids) is elliptic
// Hertz exactly, and no coarse contact is solved.

#include <vector>

#include "sqdem/mechanics/normal_law.hpp"
#include "sqdem/truegap/pair_gap.hpp"

namespace sqdem {

/// The weight of the true gap against elliptic Hertz for the pair's exponents (above).
double trueGapWeight(const Superquadric& A, const Superquadric& B);

class TrueGapCurve {
 public:
  /// The pair's true gap at its pose, its relative radii (elliptic Hertz's, with the exact e^2),
  /// the effective modulus E* (Pa), the weight and the coarse grid's cells per side.
  TrueGapCurve(const PairGap& gap, const RelativeRadii& radii, double effectiveModulus, double weight, int cells);

  /// Force (N), stiffness (N/m) and area (m^2) at the overlap (m); not acting at overlap <= 0.
  /// Solves the two rungs around the overlap when first needed; throws std::runtime_error when
  /// the overlap is R_ref / 2 or more or a rung's contact fails (pair_contact.hpp).
  NormalResponse at(double overlap);
  /// The stored energy (J): the integral of the force from 0 (solves every rung below).
  double energy(double overlap);

  /// Rungs solved so far (each a coarse half-space contact).
  int solvedRungs() const;

 private:
  struct Rung {
    double force = 0.0, area = 0.0;
    bool solved = false;
  };
  static constexpr int lowestRung = -20, rungCount = 20;  // delta_k = 2^k R_ref, k = -20 ... -1

  const Rung& rung(int k);
  double rungOverlap(int k) const;
  /// The segment of the ladder holding the overlap (its lower rung).
  int segment(double overlap) const;

  PairGap gap_;
  NormalContact hertz_;
  double weight_;
  int cells_;
  std::vector<Rung> rungs_;
};

}  // namespace sqdem
