#pragma once
// The rungs of the true-gap law (mechanics/true_gap_law.hpp) solved from the pair's true gap:
// at delta_k, the half-space contact of the gap on cells x cells (pair_contact.hpp).

#include "sqdem/mechanics/true_gap_law.hpp"
#include "sqdem/truegap/pair_gap.hpp"

namespace sqdem {

/// A ladder for the pair: R_ref and the weight of its exponents, no rung solved.
TrueGapRungs trueGapLadder(const Superquadric& A, const Superquadric& B);

/// Solves rungs first ... last of the ladder not yet solved, with E* (Pa). False, the rung marked
/// failed and the rest left unsolved, when a contact fails (pair_contact.hpp's reasons, or no
/// cell in contact).
bool solveRungs(TrueGapRungs& rungs, const PairGap& gap, double effectiveModulus, int cells, int first, int last);

}  // namespace sqdem
