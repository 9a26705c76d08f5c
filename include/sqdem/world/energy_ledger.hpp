#pragma once
// The energy ledger of a run (scene key output.energy, for compression scenes): the work done on
// the particles by the walls (kinematic bodies) and by gravity, against where it went, every
// term accumulated step by step since the ledger started (J):
//
//   W_bodies + W_gravity + W_edits = dE_kin + dU + D_plastic + D_damping + D_tangential + D_drag
//                                    + dU_bonds + D_bonds + residual
//
//   W_bodies      sum over walls of -(F_n + F_{n+1}) / 2 . v dt - (T_n + T_{n+1}) / 2 . w dt, with F, T
//                 the force and torque the particles exert on the wall (about its reference
//                 point), v its velocity and w its spin vector during the step
//   W_gravity     g . sum m v_{n+1/2} dt (exact: the drift moves x by v_{n+1/2} dt)
//   W_edits       the kinetic energy given by state set between steps (World::particlesEdited);
//                 a particle moved into an overlap stores elastic energy no work paid for: it
//                 shows as negative D_plastic
//   U             the elastic energy the contacts' normal laws store now (StoredEnergyLaw)
//   D_plastic     the work absorbed by the contacts' rate-independent normal forces less dU: the
//                 dents of a plastic law (for an elastic law it measures the quadrature error)
//   D_damping     absorbed by the contacts' normal viscous forces
//   D_tangential  absorbed by the tangential forces: sliding (friction) and the Mindlin springs'
//                 current elastic energy
//   D_drag        c sum m |v_{n+1/2}|^2 dt of the background drag
//   U_bonds       the elastic energy of the intact bonds now (parallel_bond.hpp)
//   D_bonds       the work absorbed by the bonds less dU_bonds: the energy a bond held as it broke
//                 (released to nothing: the bond is gone), and the quadrature error
// Contact terms: ContactEnergy (contact_store.hpp) and contact_work.hpp. Each term's
// quadrature is that of velocity Verlet (trapezoidal in the forces, the drift's velocity), so the
// residual measures what the integration of rotation (NO_SQUISH) and the contacts' lever arms
// leave unbalanced and should stay well below 1 % of the work done.

#include <vector>

namespace sqdem {

class World;
struct Wall;

struct EnergyLedger {
  double bodies = 0.0, gravity = 0.0, edits = 0.0;  ///< work done on the particles (J)
  double normal = 0.0, damping = 0.0, tangential = 0.0, drag = 0.0;  ///< absorbed (J)
  double bonds = 0.0;                                ///< absorbed by the bonds (J)
  double stored = 0.0, bondStored = 0.0;             ///< U and U_bonds now (J)
  double initialKinetic = 0.0, initialStored = 0.0, initialBondStored = 0.0;  ///< E_kin, U and U_bonds when the ledger started (J)
  bool started = false;                              ///< at the first force computation

  /// Starts the ledger at the world's state (forces computed).
  void start(const World& world);
  /// Adds the step just taken: `before` are the walls as they were before it (their loads).
  void addStep(const World& world, const std::vector<Wall>& before);

  double plastic() const { return normal - (stored - initialStored); }
  double bondDissipation() const { return bonds - (bondStored - initialBondStored); }
  double residual(double kinetic) const {
    return bodies + gravity + edits - (kinetic - initialKinetic) - normal - damping - tangential - drag - bonds;
  }
};

}  // namespace sqdem
