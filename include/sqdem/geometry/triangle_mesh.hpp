#pragma once
// A triangle mesh in its body frame: the surface of a kinematic body given as an STL file
// (io/stl_mesh.hpp reads and repairs it). Triangles list their vertices counter-clockwise seen
// from the side their normal points to; in a closed mesh that is outwards.

#include <array>
#include <cstdint>
#include <vector>

#include "sqdem/math/types.hpp"

namespace sqdem {

struct TriangleMesh {
  std::vector<Vec3> vertices;                          ///< (m)
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< vertex indices

  /// Unit normal of triangle t: (v1 - v0) x (v2 - v0), normalised.
  Vec3 normal(std::size_t t) const;
  /// Total area (m^2).
  double area() const;
  /// Enclosed volume by the divergence theorem, sum of (v0 . (v1 x v2)) / 6 (m^3): positive for a
  /// closed, outward-oriented mesh.
  double volume() const;
  /// Every edge is shared by exactly two triangles, traversed in opposite directions.
  bool closed() const;
};

}  // namespace sqdem
