#pragma once
// Cubic interpolation on a uniform grid: the four nodes around a position and their 4-point
// Lagrange weights (the interpolating cubic through them), for the tables of mechanics/.

#include <algorithm>
#include <array>

namespace sqdem {

struct CubicStencil {
  int first = 0;                   ///< the stencil's first node
  std::array<double, 4> weight{};  ///< of nodes first .. first + 3
};

/// The stencil at x (in units of the grid step from node 0) on a grid of `intervals` >= 3
/// intervals: the position sits between the second and third node inside the grid, and the
/// stencil is clamped to the grid near its ends (one-sided there, extrapolating outside it).
inline CubicStencil cubicStencil(double x, int intervals) {
  CubicStencil c;
  c.first = std::clamp(static_cast<int>(x) - 1, 0, intervals - 3);
  const double s = x - c.first;
  c.weight = {-(s - 1) * (s - 2) * (s - 3) / 6.0, s * (s - 2) * (s - 3) / 2.0, -s * (s - 1) * (s - 3) / 2.0,
              s * (s - 1) * (s - 2) / 6.0};
  return c;
}

}  // namespace sqdem
