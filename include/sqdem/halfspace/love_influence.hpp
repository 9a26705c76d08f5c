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

namespace sqdem {

/// The bracket above: u (pi E* / p) at (x, y) of the rectangle of half-sides a, b (m).
double loveRectangleDisplacement(double x, double y, double a, double b);

}  // namespace sqdem
