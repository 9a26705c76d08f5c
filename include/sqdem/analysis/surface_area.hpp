#pragma once
// A superquadric's surface area (m^2), for the specific surface of a bed: an ellipsoid's in
// closed form (Legendre's, through the incomplete elliptic integrals F and E: for a >= b >= c,
// A = 2 pi c^2 + 2 pi a b / sin(phi) (E(phi, k) sin^2(phi) + F(phi, k) cos^2(phi)), cos(phi) = c / a,
// k^2 = a^2 (b^2 - c^2) / (b^2 (a^2 - c^2)); NIST DLMF 19.33.2), any other shape's from its
// tessellation (superquadric_tessellation.hpp) at two resolutions, extrapolated (Richardson: the
// quads' area converges as 1 / N^2).

#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {

double surfaceArea(const Superquadric& shape);

}  // namespace sqdem
