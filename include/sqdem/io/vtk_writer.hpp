#pragma once
// ParaView-ready VTK XML time series (ASCII): one `<name>_particles_NNNNN.vtu` per frame (vertex
// cells at the particle centres) and, optionally, `<name>_contacts_NNNNN.vtp` (one line per
// particle-particle contact) and, when there are walls, `<name>_walls_NNNNN.vtp` (their
// surfaces within the box: io/wall_surfaces.hpp), each listed in `<name>_particles.pvd` /
// `<name>_contacts.pvd` / `<name>_walls.pvd`.
// Every file is written atomically; the .pvd is rewritten after each frame so it always lists
// complete frames only.
//
// Particle point data: id, velocity (m/s), angular_velocity (rad/s), force (N), torque (N m),
// quaternion [w x y z] (body -> world), semi_axes (m), exponents [n1 n2], volume_radius (m),
// coordination (particle-particle contacts), and shape_tensor = R diag(2a, 2b, 2c) R^T: ParaView's
// Tensor Glyph filter with its default sphere (radius 0.5) and "extract eigenvalues" draws each
// particle's ellipsoid. Contact cell data: normal_force (N), overlap (m), area (m^2). Wall cell
// data: wall (its index in the scene), force (N, what the particles exert on it).

#include <filesystem>
#include <string>
#include <vector>

#include "sqdem/world/world.hpp"

namespace sqdem {

class VtkSeries {
 public:
  VtkSeries(std::filesystem::path directory, std::string name, bool contacts);
  void writeFrame(const World& world);

 private:
  void writeWalls(const World& world);
  void writeCollection(const std::string& kind, const std::vector<std::pair<double, std::string>>& entries) const;

  std::filesystem::path directory_;
  std::string name_;
  bool contacts_;
  std::vector<std::pair<double, std::string>> particleFrames_, contactFrames_, wallFrames_;
};

}  // namespace sqdem
