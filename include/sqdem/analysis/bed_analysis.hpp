#pragma once
// The electrode analysis of a bed (docs/electrode_analysis.md): in the box of the domain's x and
// y and [zLow, zHigh) in z, its porosity and the pore phase's diffusion along x, y and z on voxel
// images of N and 2 N voxels along the longest edge (the answer and its convergence), the
// electronic network through the contact spots, the specific surface, the coordination and their
// profiles through the thickness. What `sqdem analyse` prints.

#include <array>
#include <optional>
#include <vector>

#include "sqdem/analysis/conductor_network.hpp"
#include "sqdem/analysis/pore_diffusion.hpp"
#include "sqdem/analysis/voxel_image.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

struct BedAnalysisOptions {
  std::optional<double> zLow;   ///< (m); default: the floor wall, else the domain's bottom
  std::optional<double> zHigh;  ///< (m); default: zLow + equivalentBedHeight (packing_measures.hpp)
  int voxels = 64;              ///< N along the box's longest edge (the fine image 2 N)
  /// Per material (S/m); infinite: an ideal conductor (a metal wall); one value per material.
  std::vector<double> conductivity;
};

/// A slice of the profiles through the thickness.
struct BedSlice {
  double zLow = 0.0, zHigh = 0.0;  ///< (m)
  double porosity = 0.0;           ///< of the fine image's voxel layers whose centres it holds
  double coordination = 0.0;       ///< mean particle contacts of the particles whose centres it holds
  std::size_t particles = 0;
};

struct BedAnalysis {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  ///< the analysed box (m)
  std::size_t particles = 0;        ///< whose centres lie in it
  double porosity = 0.0;            ///< of the fine image
  double coordination = 0.0;        ///< mean particle contacts per particle in the box
  double specificSurface = 0.0;     ///< solid surface per box volume (1/m = m^2/m^3)
  std::array<PoreDiffusion, 3> pores, finePores;  ///< along x, y, z at N and 2 N (concentrations: the fine z's only)
  std::array<double, 2> voxelEdge{0.0, 0.0};      ///< (m) the longest voxel edge of the N and 2 N images
  std::array<int, 2> voxelsAlongLongest{0, 0};    ///< of the N and 2 N images
  VoxelImage fineImage;
  ConductorNetwork network;
  std::array<NetworkConduction, 3> conduction;    ///< along x, y, z
  double referenceConductivity = 0.0;  ///< (S/m) of the material with the most particle volume in the box
  std::vector<BedSlice> profile;
  struct Seconds {
    double voxels = 0.0, pores = 0.0, network = 0.0;
  } seconds;
};

/// The analysis of the world's state (one process; contacts from its last computation). Throws
/// std::invalid_argument for a box that is empty or holds no particle's centre, voxels < 4, or
/// what electronicNetwork refuses (conductivities that do not fit, a box too thin).
BedAnalysis analyseBed(const World& world, const BedAnalysisOptions& options);

}  // namespace sqdem
