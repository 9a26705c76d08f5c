#pragma once
// The normal surface displacement of an elastic half-space under a uniform pressure p on the
// rectangle |x'| <= a, |y'| <= b (Love 1929, Phil. Trans. R. Soc. A 228, 377-420; Johnson 1985,
// Contact Mechanics, Eq. 3.25), for two bodies in contact with the effective modulus
// E* = ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)^-1 (their displacements add):
//
//   u(x, y) = p / (pi E*) [ (x + a) ln((y + b + r++) / (y - b + r+-))
//                         + (y + b) ln((x + a + r++) / (x - a + r-+))
//                         + (x - a) ln((y - b + r--) / (y + b + r-+))
//                         + (y - b) ln((x - a + r--) / (x + a + r+-)) ],
//
// r+- = ((x + a)^2 + (y - b)^2)^(1/2) and so on. At the centre of a square (a = b) the
// bracket is 8 a ln(1 + 2^(1/2)).

#include <vector>

namespace sqdem {

/// The bracket above: u (pi E* / p) at (x, y) of the rectangle of half-sides a, b (m).
double loveRectangleDisplacement(double x, double y, double a, double b);

/// The bracket for the cells of a grid of hx x hy cells (m) pressed one at a time: at the
/// centre offsets (di hx, dj hy), 0 <= di < nx, 0 <= dj < ny, as [di + nx dj] (the bracket is even
/// in x and in y). The cells' corners lie on one lattice, ((m - 1/2) hx, (l - 1/2) hy), and each
/// logarithm above is of the ratio of two neighbouring corners' sums s + r, shared by the two
/// cells beside their edge: 2 (nx + 1)(ny + 1) roots and ~2 nx ny logarithms instead of 8 roots and
/// 4 logarithms per cell (docs/performance.md, "Cheaper rungs, second round"). Taken in units of
/// hx (the bracket is homogeneous of degree 1 in lengths): the same terms, to rounding.
std::vector<double> loveGridDisplacements(int nx, int ny, double hx, double hy);

}  // namespace sqdem
