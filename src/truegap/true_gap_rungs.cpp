#include "sqdem/truegap/true_gap_rungs.hpp"

#include <exception>

#include "sqdem/truegap/pair_contact.hpp"

namespace sqdem {
namespace {

/// The relative pressure change at which a rung's solve stops: its force then within 4e-6 of the
/// converged one (1e-6 on average over the rungs of the peer n = 6 bed; measured with the
/// solver's earlier start, linear in the interference), far inside the coarse grid's error
/// (~2e-3); half the iterations of 1e-10.
constexpr double rungTolerance = 1e-5;

}  // namespace

TrueGapRungs trueGapLadder(const Superquadric& A, const Superquadric& B) {
  TrueGapRungs rungs;
  rungs.length = referenceVolumeRadius(A, B);
  rungs.weight = trueGapWeight(A.n1(), A.n2(), B.n1(), B.n2());
  return rungs;
}

RungSolution solveRung(const TrueGapRungs& rungs, int k, const PairGap& gap, double effectiveModulus, int cells) {
  try {
    const GapContact c = gapContact(gap, rungs.overlap(k), effectiveModulus, cells, rungTolerance);
    return {c.force, c.area, c.reach1, c.reach2};
  } catch (const std::exception&) {  // (inside the engine's parallel loops: nothing may escape)
    return {};
  }
}

void take(TrueGapRungs& rungs, int k, const RungSolution& solution) {
  if (solution.failed()) {
    rungs.fail(k);
  } else {
    rungs.set(k, solution.force, solution.area, solution.reach1, solution.reach2);
  }
}

bool solveRungs(TrueGapRungs& rungs, const PairGap& gap, double effectiveModulus, int cells, int first, int last) {
  for (int k = first; k <= last; ++k) {
    if (rungs.has(k)) continue;
    take(rungs, k, solveRung(rungs, k, gap, effectiveModulus, cells));
    if (rungs.failed(k)) return false;
  }
  return true;
}

}  // namespace sqdem
