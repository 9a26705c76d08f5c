#pragma once
// Particle files (CSV): the explicit state of a set of particles, read by a scene's
// `insert: [{file: ...}]` and written by `sqdem run` when it completes
// (`<name>_final_particles.csv`). One header line, then one row per particle, SI units:
//   material      the name of a scene material
//   a, b, c       semi-axes (m, > 0);  n1, n2  exponents in [2, 50]
//   x, y, z       centre (m);  qw, qx, qy, qz  unit quaternion, body -> world
//   vx, vy, vz    velocity (m/s);  wx, wy, wz  angular velocity, world frame (rad/s)
// Numbers are written with 17 significant digits: a written state reads back bit for bit, but
// for the orientation (normalised again) and the angular velocity (kept as the conjugate
// momentum), which agree to round-off. Contact histories are not part of it: a checkpoint is
// what continues a run exactly.
// (Hand-written rather than a CSV library: a fixed table of one name and 18 numbers, no quoting.)

#include <filesystem>
#include <string>
#include <vector>

#include "sqdem/scene/scene.hpp"

namespace sqdem {

/// The particles of the file at `path`, for `materials`; throws SceneError("file:line: 'column':
/// message") for a wrong header, row, number, material, semi-axis, exponent or quaternion.
std::vector<ParticleSpec> readParticleFile(const std::filesystem::path& path, const std::vector<NamedMaterial>& materials);

/// Writes the world's particles (in id order) to `path`, atomically; across ranks gathered on
/// rank 0, which writes the file (collective).
void writeParticleFile(const std::filesystem::path& path, const World& world, const std::vector<NamedMaterial>& materials);

}  // namespace sqdem
