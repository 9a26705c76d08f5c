#pragma once
// A superquadric's surface as a closed quadrilateral mesh in its body frame, for drawing: the
// six faces of a cube, each an N x N grid at equal angles (u = tan(pi/4 s), s uniform in
// [-1, 1]), taken to the unit sphere and from there to the surface through the parametrisation
// (Superquadric::surfacePoint at the direction's latitude and longitude), which gathers the
// vertices where a blocky shape turns its edges. Every vertex lies on the surface; the enclosed
// volume falls short by O(1 / N^2) (tessellation_test.cpp: within 1 % from N = 12). Vertices
// are shared, quads counter-clockwise seen from outside: 6 N^2 quads, 6 N^2 + 2 vertices.

#include <array>
#include <cstdint>
#include <vector>

#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {

/// The part of a tessellation every shape shares at one resolution: the vertices' latitude and
/// longitude (rad) in the parametrisation, and the quads.
struct SurfaceGrid {
  std::vector<std::array<double, 2>> angles;  ///< eta, omega per vertex
  std::vector<std::array<std::uint32_t, 4>> quads;
};

struct Tessellation {
  std::vector<Vec3> points;   ///< on the surface, body frame (m)
  std::vector<std::array<std::uint32_t, 4>> quads;
};

/// N = resolution >= 1 quads along each cube edge.
SurfaceGrid surfaceGrid(int resolution);

/// N = resolution >= 1 quads along each cube edge.
Tessellation tessellate(const Superquadric& shape, int resolution);

}  // namespace sqdem
