#pragma once
// The least penetration of two overlapping convex bodies: the minimum over unit n of the support
// gap h_A(n) + h_B(-n) (detector.hpp), which is the distance from the origin to the boundary of
// the Minkowski difference K = A - B. Found by the expanding polytope algorithm (EPA; van den
// Bergen 2001, docs/references.md) on the bodies' exact support maps: a polytope whose vertices
// are support points of K, so inscribed in it, grows at the face nearest the origin by the support
// point along that face's normal. The nearest face's distance is a lower bound of the least
// penetration and the support gap along its normal an upper bound; it stops when they agree to
// the tolerance. It needs no start and, converged, brackets the global minimum, where a descent
// finds the minimum of the basin it starts in. Coordinates are scaled by the pair's length scale L.
//
// Hand-written rather than libccd's ccdGJKPenetration (FCL's dependency): on superquadric pairs
// libccd's EPA stopped with bounds 0.298 and 0.576 L of a pair whose least penetration is 0.306 L,
// and reported a lower bound of 3e-9 L on a pair overlapping by 3e-12 L; FCL's corrected EPA works
// only on FCL's own shape types.

#include <optional>

#include "pair_surfaces.hpp"

namespace sqdem::detail {

struct Penetration {
  Vec3 normal;  ///< unit, A's frame, from A towards B: the sampled direction of least support gap
  /// The nearest face's distance once the polytope encloses the origin (m), else -infinity: the
  /// least penetration is at least this.
  double lowerBound = 0.0;
  double upperBound = 0.0;  ///< the support gap along normal (m): the least penetration is at most this
  bool converged = false;   ///< the bounds agree to the tolerance
  int iterations = 0;       ///< support points of K taken
};

/// EPA until the bounds agree to relativeTolerance * L (at most 600 support points); nothing when
/// the bodies do not overlap (a face of the polytope separates the origin from K) or the start
/// is flat. Unconverged bounds are still bounds.
std::optional<Penetration> penetrationDepth(const PairFrame& f, double relativeTolerance);

}  // namespace sqdem::detail
