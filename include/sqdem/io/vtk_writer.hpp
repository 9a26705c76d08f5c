#pragma once
// ParaView-ready time series, written through VTK (vtk_xml.hpp: binary, zlib-compressed .vtp),
// each frame's files listed in a .pvd collection:
//   <name>_particles.pvd  one vertex per particle centre with its state (glyph users);
//   <name>_surfaces.pvd   every particle's surface, tessellated in its pose (true shapes with no
//                         recipe; resolution N = output.surface_resolution, 6 N^2 quads each,
//                         geometry/superquadric_tessellation.hpp; 0: not written);
//   <name>_contacts.pvd   one line per contact (output.contacts): between the two centres, or
//                         from the centre to the contact point on a wall;
//   <name>_walls.pvd      the walls' surfaces within the box (io/wall_surfaces.hpp);
//   <name>_bonds.pvd      one line per intact bond (a scene with bonds): between the two
//                         centres, or from the centre to the bond's centre on a wall.
// With the first frame, <name>_view.py (paraview_script.hpp) opens them in ParaView.
// Every file is written atomically; a .pvd is rewritten after each frame so it lists complete
// frames only. Across MPI ranks each frame is a piece per rank, `<name>_<kind>_NNNNN_<rank>.vtp`
// (its owned particles, the contacts it computed), and a `<name>_<kind>_NNNNN.pvtp` that lists
// them, written by VTK's parallel writer (vtk_xml.hpp); the walls, global bodies, as one .vtp by
// rank 0, which also writes the .pvd and the script. (VTK writes the pieces in place, not
// atomically: a frame is listed in the .pvd once rank 0's piece is written.)
//
// Particle point data: id, velocity (m/s), angular_velocity (rad/s), force (N), torque (N m),
// quaternion [w x y z] (body -> world), semi_axes (m), exponents [n1 n2], volume_radius (m),
// coordination (particle-particle contacts), and shape_tensor = R diag(2a, 2b, 2c) R^T, which a
// Tensor Glyph with its default sphere (radius 0.5), eigenvalues extracted and Scale Factor 1
// draws as the particle's ellipsoid.
// Surface point data (Float32, each particle's values on its vertices): id, velocity,
// angular_velocity, force, coordination, volume_radius.
// Contact cell data: id_a, id_b (particle ids; id_b = -1 on a wall), wall (its index, -1 between
// particles), point (m), normal (unit, from A to B), normal_force (N, > 0 compressive),
// normal_force_vector, tangential_force (N, acting on B; A receives the opposite),
// overlap (m, < 0 a gap), area (m^2).
// Bond cell data (the bond's loads at the frame's poses, docs/bonds.md): id_a, id_b, wall (as
// for contacts), centre (m), normal_force (N, > 0 in tension), shear_force (N, on B), moment
// (N m, twisting + bending, on B), tensile_stress and shear_stress (Pa, Eq. 11's sigma and tau),
// utilisation (max(sigma / sigma_c, tau / tau_c), < 1).
// Wall cell data: wall (its index in the scene), force (N, what the particles exert on it),
// torque (N m, about its reference point), velocity (m/s).

#include <filesystem>
#include <string>
#include <vector>

#include "sqdem/io/poly_data.hpp"
#include "sqdem/io/vtk_xml.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

struct VtkOutputOptions {
  bool contacts = true;
  int surfaceResolution = 0;  ///< N of the particles' surfaces; 0: not written
  VtkCompression compression = VtkCompression::ZLib;
};

class VtkSeries {
 public:
  VtkSeries(std::filesystem::path directory, std::string name, VtkOutputOptions options);
  void writeFrame(const World& world);

 private:
  struct Series {
    const char* kind;
    std::vector<std::pair<double, std::string>> frames;
  };
  /// A frame of `series`: in one process a .vtp; across ranks every rank's piece and rank 0's
  /// .pvtp. Rank 0 lists it in the .pvd.
  void write(Series& series, double time, const PolyData& frame, const Communicator& ranks) const;

  std::filesystem::path directory_;
  std::string name_;
  VtkOutputOptions options_;
  Series particles_{"particles", {}}, surfaces_{"surfaces", {}}, contacts_{"contacts", {}}, walls_{"walls", {}}, bonds_{"bonds", {}};
};

}  // namespace sqdem
