#pragma once
// The rungs of the true-gap law (mechanics/true_gap_law.hpp) solved from the pair's true gap:
// at delta_k, the half-space contact of the gap on cells x cells (pair_contact.hpp).

#include "sqdem/mechanics/true_gap_law.hpp"
#include "sqdem/truegap/pair_gap.hpp"

namespace sqdem {

/// A ladder for the pair: R_ref and the weight of its exponents, no rung solved.
TrueGapRungs trueGapLadder(const Superquadric& A, const Superquadric& B);

/// A rung's half-space contact: force (N), area (m^2) and reach along t1 and t2 (m), all 0 where
/// it failed (pair_contact.hpp's reasons, or no cell in contact).
struct RungSolution {
  double force = 0.0, area = 0.0, reach1 = 0.0, reach2 = 0.0;
  bool failed() const { return !(force > 0.0 && area > 0.0 && reach1 >= 0.0 && reach2 >= 0.0); }
};

/// Rung k's contact on the pair's gap with E* (Pa), without touching the ladder (threads may
/// solve a contact's rungs side by side); `take` enters it.
RungSolution solveRung(const TrueGapRungs& rungs, int k, const PairGap& gap, double effectiveModulus, int cells);
/// Rung k set from its solution, or marked failed.
void take(TrueGapRungs& rungs, int k, const RungSolution& solution);

/// Solves rungs first ... last of the ladder not yet solved, with E* (Pa). False, the rung marked
/// failed and the rest left unsolved, when a contact fails (pair_contact.hpp's reasons, or no
/// cell in contact).
bool solveRungs(TrueGapRungs& rungs, const PairGap& gap, double effectiveModulus, int cells, int first, int last);

}  // namespace sqdem
