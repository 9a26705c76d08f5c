#pragma once
// Particle state set between steps (the Python module's setters, docs/python.md): every field of
// this process's particles at once, from n rows of k values (row-major, in storage order). The
// values are checked before any is set: std::invalid_argument naming the row and the field, on
// every rank when any rank's values fail (distributed/agreed.hpp); the change then goes through
// Simulation::editParticles. Collective across ranks.

#include <span>

#include "sqdem/scene/simulation.hpp"

namespace sqdem {

/// Centres (m), n x 3: finite, within the domain along its axes that are not periodic.
void setPositions(Simulation& simulation, std::span<const double> rows);
/// Velocities (m/s), n x 3: finite.
void setVelocities(Simulation& simulation, std::span<const double> rows);
/// Orientations, n x 4 quaternions (x, y, z, w) body -> world: finite and not zero; normalised.
/// The angular velocities are kept (the momentum follows the new orientation).
void setOrientations(Simulation& simulation, std::span<const double> rows);
/// Angular velocities (rad/s, world frame), n x 3: finite; the momentum follows.
void setAngularVelocities(Simulation& simulation, std::span<const double> rows);

}  // namespace sqdem
