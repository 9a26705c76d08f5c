#pragma once
// Where a line meets a superquadric's surface (docs/contact_laws.md, "The true gap"): the gap of
// two bodies over their common tangent plane is the distance, along the normal, from the lower
// body's top to the upper body's bottom above each point of the plane.
//
// The body's gauge g (superquadric.hpp, g = 1 on the surface) is convex and 1-homogeneous, so
// along a line it is a convex function of the line's parameter: Newton's method from a point
// outside the body towards it descends monotonically onto the first crossing g = 1 and never
// overshoots, and a slope >= 0 while g > 1 proves the line misses the body.

#include <limits>

#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {

/// The largest t with q + t d on the body's surface (the body's far side along d, seen from
/// +infinity: its top for d its "up"), or -infinity when the line q + t d misses the body;
/// d a unit vector (world). Newton starts from `start` where the line is there outside the body
/// on the far side (g > 1, dg/dt > 0: a guess near the answer, e.g. a neighbouring line's), else
/// from beyond the bounding sphere; either start gives the same crossing.
double surfaceFarthestAlong(const Superquadric& shape, const Pose& pose, const Vec3& q, const Vec3& d,
                            double start = std::numeric_limits<double>::infinity());

}  // namespace sqdem
