#pragma once
// Packing measures of a bed resting on the bottom of the domain (gravity along -z).
//
//   bulk solid fraction  particle volume inside the slab [z_bottom + 2 R, z_bottom + H - 2 R]
//                        (exact for ellipsoids; other shapes count where their centre lies)
//                        over the slab volume Lx Ly h, with z_bottom = domain.lo.z, R the mean
//                        volume-equivalent radius and H = 2 (volume-weighted mean centre height)
//                        the height of a uniform bed with the same centroid (so the rough top
//                        and the wall layer are excluded); a bed thinner than 6 R uses
//                        [z_bottom, highest particle top];
//   between-walls fraction  with a bottom (+z) and a top (-z) wall: all particle volume over
//                        Lx Ly (z_top wall - z_bottom wall), the compressed-box measure;
//   assembly stress      sigma = (1/V) sum_contacts l (x) f (Love-Weber, compression positive,
//                        symmetrised): l = x_b - x_a (periodic image) and f the force on b for
//                        particle pairs, l = x_c - x_a and f the force on the wall for wall
//                        contacts; V = Lx Ly (wall gap, or H for a bed)
//   mean coordination    2 N_pp / N over all particles (particle-particle contacts; walls and
//                        rattlers included), and over particles with >= 2 contacts;
//   yielded fraction     of the force-carrying contacts (walls included), those whose law
//                        says they carry a plastic dent (NormalResponse::yielded);
//   largest overlap ratio  the largest overlap over the volume-equivalent radius of the
//                        smaller body (a wall's contact: of its particle).

#include "sqdem/geometry/pose.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

struct PackingMeasures {
  double solidFraction = 0.0;
  double slabHeight = 0.0;             ///< (m)
  double meanCoordination = 0.0;
  double meanCoordinationNonRattlers = 0.0;
  double bedHeight = 0.0;              ///< z_top - z_bottom (m)
  double betweenWallsFraction = 0.0;   ///< 0 without a pair of opposed z walls
  Mat3 stress = Mat3::Zero();          ///< (Pa), compression positive
  double stressVolume = 0.0;           ///< V of the stress average (m^3)
  double yieldedFraction = 0.0;
  double largestOverlapRatio = 0.0;    ///< delta / R_vol (-)
};


PackingMeasures measurePacking(const World& world);

/// A plate (a plane wall facing -z) pressing the bed onto the floor (the plane wall facing +z).
struct PlateMeasures {
  double gap = 0.0;       ///< plate z - floor z (m)
  double pressure = 0.0;  ///< World::wallPressure (Pa)
  double porosity = 0.0;  ///< 1 - V_solid / (A gap), A the plate's cross-section of the box
};
/// std::invalid_argument when wall `plate` is not a plate of a scene with a floor (the scene
/// reader's rule for stages that press).
PlateMeasures measurePlate(const World& world, std::size_t plate);
/// The floor: the first plane wall facing +z, if any.
const PlaneWall* floorWall(const World& world);
/// The particles' volume (m^3).
double solidVolume(const World& world);
/// The height above z = bottom of the uniform layer with the bed's volume centroid,
/// 2 sum V_i (z_i - bottom) / sum V_i (m): exact sums, reduced over the ranks.
double equivalentBedHeight(const World& world, double bottom);

/// Volume of a body between the planes z = lo and z = hi (m^3). Ellipsoids exactly: the
/// cross-section normal to z is an ellipse of area (3V / 4h) (1 - t^2/h^2), t = z - z_c, with
/// h = |diag(a, b, c) R^T e_z| the half-height; other superquadrics count wholly where their
/// centre lies.
double volumeInSlab(const Superquadric& shape, const Pose& pose, double lo, double hi);

/// Particle-particle contacts per particle (walls excluded).
std::vector<int> coordinationNumbers(const World& world);

}  // namespace sqdem
