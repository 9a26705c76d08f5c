#pragma once
// The half-space contact of a pair's true gap (docs/contact_laws.md, "The boundary-element
// reference"): the gap (pair_gap.hpp) on a grid over the region where it is below the approach
// (gap_region.hpp), pressed by that approach (halfspace/halfspace_contact.hpp). At 128 x 128
// cells it is the reference of the blocky contact laws; at 16 x 16 the true-gap law's
// (true_gap_curve.hpp).

#include "sqdem/halfspace/halfspace_contact.hpp"
#include "sqdem/truegap/pair_gap.hpp"

namespace sqdem {

/// A gap's half-space contact, and how far it reaches from the contact point along the plane's
/// axes t1, t2 (pair_gap.hpp): the largest |x| and |y| of the cells in contact (m).
struct GapContact : HalfspaceContact {
  double reach1 = 0.0, reach2 = 0.0;
};

/// The contact at the approach delta (m) for the effective modulus E* (Pa) on cells x cells: force
/// (N), area (m^2) and reach. The grid's margin grows (4 %, 20 %, 50 % of the region's extent) while the
/// pressure reaches its edge. Throws std::runtime_error when the solver does not converge or the
/// pressure reaches the widest grid's edge. `tolerance`: the solver's relative pressure change at
/// convergence (halfspace_contact.hpp).
GapContact gapContact(const PairGap& gap, double approach, double effectiveModulus, int cells, double tolerance = 1e-10);

/// The same for two posed bodies and the detector's contact between them.
HalfspaceContact boundaryElementContact(const PairBody& A, const PairBody& B, const ContactGeometry& contact, double approach,
                                        double effectiveModulus, int cells = 128);

}  // namespace sqdem
