#pragma once
// The boundary-element reference for a pair of superquadrics (docs/contact_laws.md, "The
// boundary-element reference"): the true gap of the two undeformed surfaces over their common
// tangent plane at the detector's contact, and the half-space contact of that gap
// (halfspace/halfspace_contact.hpp) at a rigid approach delta along the normal.
//
// The plane: through the midpoint of the two contact points, normal n (A towards B), its axes
// t1 along the contact ellipse's major axis (mechanics/elliptic.hpp) and t2 = n x t1. Above the
// plane point q, the gap is the distance along n from A's top to B's bottom
// (contact/surface_along_line.hpp), plus the detector's overlap: the gap at the pose where the
// bodies just touch, B moved back along n (a translation along n shifts the gap uniformly).
// Half-space theory takes both surfaces as flat on the contact's scale: the small-slope
// approximation of every Hertz-type law.

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/halfspace/halfspace_contact.hpp"

namespace sqdem {

struct PairBody {
  const Superquadric& shape;
  Pose pose;
};

/// The touching gap on cells x cells covering the region where it is below `approach` (m), with
/// a margin: the contact at that approach lies inside it (there u = delta - h > 0). Throws
/// std::runtime_error when no point has a gap below the approach or the region is unbounded.
GapGrid touchingGap(const PairBody& A, const PairBody& B, const ContactGeometry& contact, double approach, int cells);

/// The half-space contact of the pair at the approach delta (m): force (N) and area (m^2) for
/// the effective modulus E* (Pa), on cells x cells. Throws std::runtime_error when the solver
/// does not converge or the pressure reaches the grid's edge.
HalfspaceContact boundaryElementContact(const PairBody& A, const PairBody& B, const ContactGeometry& contact, double approach,
                                        double effectiveModulus, int cells = 128);

}  // namespace sqdem
