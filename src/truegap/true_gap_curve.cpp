#include "sqdem/truegap/true_gap_curve.hpp"

#include <bit>
#include <stdexcept>

#include "sqdem/truegap/true_gap_rungs.hpp"

namespace sqdem {

TrueGapCurve::TrueGapCurve(const PairBody& A, const PairBody& B, const ContactGeometry& contact, const RelativeRadii& radii,
                           double effectiveModulus, int cells)
    : gap_(A, B, contact),
      hertz_{radii, hertzFactors(radii.ratio(), EccentricityMethod::Exact), effectiveModulus},
      law_{cells},
      rungs_(trueGapLadder(A.shape, B.shape)) {}

NormalContact TrueGapCurve::solvedTo(double overlap, bool fromLowest) {
  NormalContact c = hertz_;
  c.trueGap = &rungs_;
  if (!(rungs_.weight > 0.0 && overlap > 0.0)) return c;
  const int segment = rungs_.segment(overlap);
  if (!solveRungs(rungs_, gap_, hertz_.effectiveModulus, law_.cells, fromLowest ? TrueGapRungs::lowest : segment, segment + 1)) {
    throw std::runtime_error("the true-gap law: a rung's half-space contact failed (no convergence, or pressure at the grid's edge)");
  }
  return c;
}

NormalResponse TrueGapCurve::at(double overlap) {
  TrueGapLaw::History none;
  return law_.force(solvedTo(overlap, false), overlap, none);
}

double TrueGapCurve::energy(double overlap) { return law_.energy(solvedTo(overlap, true), overlap); }

int TrueGapCurve::solvedRungs() const { return std::popcount(rungs_.solved); }

}  // namespace sqdem
