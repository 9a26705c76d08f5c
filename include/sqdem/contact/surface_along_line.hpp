#pragma once
// Where a line meets a superquadric's surface (docs/contact_laws.md, "The true gap"): the gap of
// two bodies over their common tangent plane is the distance, along the normal, from the lower
// body's top to the upper body's bottom above each point of the plane.
//
// The body's inside-outside function F = g^n1 (superquadric.hpp, F = 1 on the surface; no root
// to take, unlike the gauge g) is convex, so along a line it is a convex function of the line's
// parameter: Newton's method from a point beyond the body's far side descends monotonically onto
// the crossing F = 1 and never overshoots, and a slope <= 0 while F > 1 there proves the line
// misses the body. Near the crossing (a neighbouring line's answer as the start) it converges
// quadratically in 2-3 steps; far from it the steps are Newton's on g (1-homogeneous, nearly
// linear along the line), computed from F.

#include <limits>

#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {

/// The largest t with q + t d on the body's surface (the body's far side along d, seen from
/// +infinity: its top for d its "up"), or -infinity when the line q + t d misses the body;
/// d a unit vector (world). Newton starts from `start` where the line is there outside the body
/// on the far side (F > 1, dF/dt > 0: a guess near the answer, e.g. a neighbouring line's), else
/// from where the line leaves the sphere around the body's box; either start gives the same
/// crossing to Newton's tolerance (~1e-16 of the body's size).
double surfaceFarthestAlong(const Superquadric& shape, const Pose& pose, const Vec3& q, const Vec3& d,
                            double start = std::numeric_limits<double>::infinity());

}  // namespace sqdem
