#pragma once
// Where two bodies pressed together may touch: the region of the tangent plane where their true
// gap (pair_gap.hpp) is below the approach, convex since the gap is. Found along 16 rays from
// the contact, each ray's crossing of the level by power-law steps kept in a bracket, the rays
// spread evenly over an ellipse that is refined to the crossings' principal axes and aspect
// until both settle; thin regions (an edge on a face: aspects of 1e-3) are followed as well as
// round ones (docs/contact_laws.md, "The true gap").

#include "sqdem/halfspace/halfspace_contact.hpp"
#include "sqdem/truegap/pair_gap.hpp"

namespace sqdem {

/// The region's principal axes on the tangent plane (in the gap's t1, t2 coordinates) and its
/// extent along them (m), the contact at 0; the gap's level (m) that bounds it.
struct GapRegion {
  Vec2 major = Vec2::UnitX();  ///< unit
  double low1 = 0.0, high1 = 0.0, low2 = 0.0, high2 = 0.0;
  double level = 0.0;

  Vec2 minor() const { return {-major.y(), major.x()}; }
};

/// The region where the gap is below `level` (m). Throws std::runtime_error when the gap at the
/// contact is not below the level or the region is unbounded.
GapRegion gapRegion(const PairGap& gap, double level);

/// The gap on cells x cells covering the region, widened on each side by `margin` times its
/// extent; the grid's x axis is the region's major axis. Cells where the gap is known to be at or
/// above the region's level are left +infinity (they cannot touch: halfspace_contact.hpp), so the
/// grid serves approaches up to that level only.
GapGrid gapGrid(const PairGap& gap, const GapRegion& region, int cells, double margin);

}  // namespace sqdem
