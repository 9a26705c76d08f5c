#pragma once
// The shape-class pair of a contact: which detector path it takes (docs/architecture.md, "A step"). Chosen once
// per candidate from the two shapes (spheres are ellipsoids are superquadrics: the most special
// class both bodies belong to).

#include <cstdint>

#include "sqdem/dynamics/wall.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {

enum class PairKind : std::uint8_t {
  SphereSphere,      ///< closed form; a round contact (below)
  SphereWall,        ///< closed form; a round contact
  EllipsoidPair,     ///< common-normal solve on gauges without powers (n1 = n2 = 2)
  SuperquadricPair,  ///< common-normal solve, general exponents
  ParticleWall,      ///< closed form through the support map
  ParticleCylinder,  ///< a one-dimensional search (closed form for a sphere); never round
  ParticleMesh,      ///< one feature of a triangle mesh (plane, line or point contact)
};

/// Two spheres, or a sphere and a plane: both relative radii are R* = rA rB / (rA + rB) (r on a
/// plane) and the contact is a circle, so the curvature-exact law is exactly the law on the
/// volume-equivalent spheres (the radius cap, capFactor sqrt(rA rB) > R*, never binds) and
/// elliptic Mindlin is circular Mindlin: no curvatures are computed.
constexpr bool round(PairKind kind) { return kind == PairKind::SphereSphere || kind == PairKind::SphereWall; }
/// Body B is a wall.
constexpr bool withWall(PairKind kind) {
  return kind == PairKind::SphereWall || kind == PairKind::ParticleWall || kind == PairKind::ParticleCylinder ||
         kind == PairKind::ParticleMesh;
}

inline PairKind pairKind(const Superquadric& A, const Superquadric& B) {
  if (A.isSphere() && B.isSphere()) return PairKind::SphereSphere;
  if (A.isEllipsoid() && B.isEllipsoid()) return PairKind::EllipsoidPair;
  return PairKind::SuperquadricPair;
}
/// A sphere on a cylinder is not round: the cylinder's curvature differs along and around its
/// axis. A sphere on a mesh is not taken as round either (its edges and vertices are solved as
/// lines and points, a face as a plane: one kernel for every feature).
inline PairKind wallPairKind(const Superquadric& A, const Wall& wall) {
  return std::visit(PerShape{[&](const PlaneWall&) { return A.isSphere() ? PairKind::SphereWall : PairKind::ParticleWall; },
                             [](const CylinderWall&) { return PairKind::ParticleCylinder; },
                             [](const MeshWall&) { return PairKind::ParticleMesh; }},
                    wall.surface);
}

}  // namespace sqdem
