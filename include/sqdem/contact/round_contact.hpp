#pragma once
// Round contacts: sphere-sphere and sphere-plane in closed form. Both bodies' curvatures are
// known (1/r, or 0 for the plane) and the contact is a circle, so the engine's round kernels
// need nothing but the normal, the overlap and the two surface points: this small record is
// what they solve for (ContactGeometry, with curvature tensors and body-frame points, is built
// from it only for a single query, detector.hpp).

#include <algorithm>

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/geometry/plane.hpp"

namespace sqdem {

struct RoundContact {
  ContactStatus status = ContactStatus::Separated;
  /// Along the normal (m): > 0 interpenetration, < 0 the gap (for Separated: minus the gap
  /// beyond the cut-off).
  double overlap = 0.0;
  Vec3 normal = Vec3::UnitZ();  ///< unit, from A towards B
  Vec3 pointA = Vec3::Zero();   ///< surface point of A (world, m)
  Vec3 pointB = Vec3::Zero();   ///< surface point of B (world, m)

  bool converged() const { return status == ContactStatus::Converged; }
};

/// Beyond the cut-off: Separated, with the gap as a negative overlap.
inline RoundContact separatedRound(double gap) {
  return {.status = ContactStatus::Separated, .overlap = -std::max(gap, 0.0)};
}

/// Spheres of centres cA, cB and radii rA, rB; pairs further apart than cutoff are Separated.
/// Coincident centres are Degenerate (normal +z, overlap rA + rB). Inline, as the next one: the
/// engine's round kernels call them once per candidate and step.
inline RoundContact detectSpheres(const Vec3& centreA, double rA, const Vec3& centreB, double rB, double cutoff) {
  const Vec3 d = centreB - centreA;
  const double distance = d.norm();
  if (distance - rA - rB > cutoff) return separatedRound(distance - rA - rB);
  RoundContact c;
  if (!(distance > 0.0)) {  // coincident centres: any direction separates them by rA + rB
    c.status = ContactStatus::Degenerate;
    c.overlap = rA + rB;
  } else {
    c.status = ContactStatus::Converged;
    c.normal = d / distance;
    c.overlap = rA + rB - distance;
  }
  c.pointA = centreA + rA * c.normal;
  c.pointB = centreB - rB * c.normal;
  return c;
}

/// A sphere (body A) against a wall: the normal is -wall.normal, A's point the sphere's deepest
/// point towards the wall, B's its projection on the plane.
inline RoundContact detectSphereWall(const Vec3& centre, double r, const Plane& wall, double cutoff) {
  RoundContact c;
  c.normal = -wall.normal;
  c.pointA = centre + r * c.normal;
  c.overlap = (wall.point - c.pointA).dot(wall.normal);
  if (-c.overlap > cutoff) return separatedRound(-c.overlap);
  c.status = ContactStatus::Converged;
  c.pointB = c.pointA + c.overlap * wall.normal;
  return c;
}

}  // namespace sqdem
