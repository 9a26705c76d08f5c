#pragma once
// The pore space of a bed as a voxel image (docs/electrode_analysis.md, "Pore transport"): a box
// cut into N_x x N_y x N_z voxels of edges h_x, h_y, h_z (near-cubes: N_d = round(L_d / h) for the
// edge h = L_max / N of the longest axis, so that the box and its periods stay exact), each pore
// or solid by whether its centre lies inside a particle (the superquadric's inside test g < 1 in
// the particle's frame), the particles wrapped along the box's periodic axes. Voxel (i, j, k) is at
// index i + N_x (j + N_y k), its centre at origin + (h_x (i + 1/2), h_y (j + 1/2), h_z (k + 1/2)).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/math/types.hpp"

namespace sqdem {

struct VoxelImage {
  std::array<int, 3> size{0, 0, 0};  ///< voxels along x, y, z
  Vec3 origin = Vec3::Zero();        ///< (m) the box's low corner
  Vec3 voxel = Vec3::Zero();         ///< (m) a voxel's edges h_x, h_y, h_z
  std::vector<std::uint8_t> pore;    ///< per voxel: 1 pore, 0 solid

  std::size_t count() const { return static_cast<std::size_t>(size[0]) * size[1] * size[2]; }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(size[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(size[1]) * k);
  }
  /// Pore voxels over all voxels.
  double porosity() const;
};

/// A particle to voxelise: its shape, centre (m) and orientation (body to world).
struct PlacedShape {
  const Superquadric* shape;
  Vec3 centre;
  Quat orientation;
};

/// The image of the box [lo, hi] with `voxelsAlongLongest` voxels along its longest edge.
/// Particles are wrapped along the `periodic` axes (the box's length their period).
VoxelImage voxelise(std::span<const PlacedShape> particles, const Vec3& lo, const Vec3& hi, const std::array<bool, 3>& periodic,
                    int voxelsAlongLongest);

}  // namespace sqdem
