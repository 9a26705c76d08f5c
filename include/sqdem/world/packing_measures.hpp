#pragma once
// Packing measures of a bed resting on the bottom of the domain (gravity along -z).
//
//   bulk solid fraction  volume of the particles whose centres lie in the slab
//                        [z_bottom + 2 R_max, z_top - 2 R_max] over the slab volume Lx Ly h,
//                        z_bottom = domain.lo.z, z_top = the highest particle top, R_max the
//                        largest bounding radius (boundary layers excluded); if the bed is too
//                        thin for a slab, the whole bed [z_bottom, z_top] is used;
//   between-walls fraction  with a bottom (+z) and a top (-z) wall: all particle volume over
//                        Lx Ly (z_top wall - z_bottom wall), the compressed-box measure;
//   mean coordination    2 N_pp / N over all particles (particle-particle contacts; walls and
//                        rattlers included), and over particles with >= 2 contacts.

#include "sqdem/world/world.hpp"

namespace sqdem {

struct PackingMeasures {
  double solidFraction = 0.0;
  double slabHeight = 0.0;             ///< (m)
  double meanCoordination = 0.0;
  double meanCoordinationNonRattlers = 0.0;
  double bedHeight = 0.0;              ///< z_top - z_bottom (m)
  double betweenWallsFraction = 0.0;   ///< 0 without a pair of opposed z walls
};

/// Normal pressure on wall w: |F . n| over the box cross-section normal to the wall's dominant
/// axis (Pa).
double wallPressure(const World& world, std::size_t w);

PackingMeasures measurePacking(const World& world);

/// Particle-particle contacts per particle (walls excluded).
std::vector<int> coordinationNumbers(const World& world);

}  // namespace sqdem
