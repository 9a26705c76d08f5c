#pragma once
// The electronic network of a bed (docs/electrode_analysis.md, "Electronic network"): a node per
// particle (its id), a conductance per contact from the contact's ellipse (the law's area, the
// Hertz aspect of the pair's curvatures: Interactions::ellipses), electrodes normal to z, periodic
// (or cut) in x and y; conductor_network.hpp solves it.
//
// A contact spot of semi-axes a >= b on a body of conductivity sigma spreads the current into it
// with Holm's constriction resistance of an elliptic spot on a half-space,
//   R = K(e) / (2 pi sigma a),  e^2 = 1 - b^2 / a^2   (a circle: K = pi / 2, R = 1 / (4 sigma a)),
// the resistance of an equipotential elliptic disc, half that of its capacitance in full space
// (Holm, *Electric Contacts: Theory and Application*, Springer 1967, Secs. 4-5); a contact joins
// its two sides in series, 1 / g = R_A + R_B. The particle's bulk beyond the constriction adds
// nothing: the spreading resistance already runs to infinity in the half-space, and the finite
// body changes it by O(a / R_vol) (Batchelor & O'Brien 1977, Proc. R. Soc. Lond. A 355, 313-333,
// for spheres), the approximation of the DEM conduction models (Vargas & McCarthy 2001, AIChE J. 47,
// 1052-1059: conductance 2 k a).
//
// Electrodes along z: the low one at zLow is the floor wall's contacts (their spots, the wall's
// side ideal unless its material conducts) when the floor lies there, else every particle the
// plane z = zLow cuts, held ideally (its bulk a conductor); the high one at zHigh the particles its
// plane cuts. The network holds the particles whose centres lie in [zLow, zHigh) (the volume
// the in-plane conductivities refer to: the box's). Along an axis that is not periodic the box's
// faces are such cut electrodes too.

#include <span>

#include "sqdem/analysis/conductor_network.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

/// Holm's spreading resistance (Ohm) of an elliptic spot, semi-axes major >= minor > 0 (m), on a
/// half-space of conductivity (S/m); 0 for an infinite conductivity.
double spreadingResistance(double major, double minor, double conductivity);

/// The world's network (one process: every particle owned) between electrodes at zLow < zHigh
/// (m), x and y over the domain; `spots` the world's contact ellipses (World::contactEllipses,
/// by store slot); conductivity (S/m) per material index, infinite for an ideal
/// conductor (a metal wall). Throws std::invalid_argument for a conductivity that is not > 0, a
/// particle material whose conductivity is infinite, a world spread over several ranks, or a
/// particle that reaches through the whole box along an axis with electrodes (a short circuit).
ConductorNetwork electronicNetwork(const World& world, std::span<const ContactEllipse> spots, std::span<const double> conductivity,
                                   double zLow, double zHigh);

}  // namespace sqdem
