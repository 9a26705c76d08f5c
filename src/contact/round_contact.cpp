#include "sqdem/contact/round_contact.hpp"

#include <algorithm>

namespace sqdem {
namespace {

RoundContact separated(double gap) { return {.status = ContactStatus::Separated, .overlap = -std::max(gap, 0.0)}; }

}  // namespace

RoundContact detectSpheres(const Vec3& centreA, double rA, const Vec3& centreB, double rB, double cutoff) {
  const Vec3 d = centreB - centreA;
  const double distance = d.norm();
  if (distance - rA - rB > cutoff) return separated(distance - rA - rB);
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

RoundContact detectSphereWall(const Vec3& centre, double r, const Plane& wall, double cutoff) {
  RoundContact c;
  c.normal = -wall.normal;
  c.pointA = centre + r * c.normal;
  c.overlap = (wall.point - c.pointA).dot(wall.normal);
  if (-c.overlap > cutoff) return separated(-c.overlap);
  c.status = ContactStatus::Converged;
  c.pointB = c.pointA + c.overlap * wall.normal;
  return c;
}

}  // namespace sqdem
