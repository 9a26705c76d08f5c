#pragma once
// Turns a validated Scene into a ready World: samples each particle's shape from its family,
// inserts particles at random non-overlapping positions (bounding spheres, periodic images and
// walls respected) with random orientations (uniform on SO(3)), sets the interaction table and
// the time step. Deterministic for a given scene seed.

#include "sqdem/scene/scene.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

/// Throws SceneError (naming the insertion) when the region cannot hold the particles.
World buildWorld(const Scene& scene);

/// The Rayleigh time of the world's smallest particle (s), longer by E^-1/2 under reduced
/// stiffness (the scene's smallest reduced_stiffness).
double rayleighTime(const Scene& scene, const World& world);

/// The automatic time step of a built world (s): `fraction` x rayleighTime, with bonds at most
/// `fraction` x World::bondTimeStep, and with a declared impact_velocity at most the Hertz
/// collision time over steps_per_collision.
double automaticTimeStep(const Scene& scene, const World& world, double fraction);

}  // namespace sqdem
