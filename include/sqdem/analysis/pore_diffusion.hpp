#pragma once
// Steady diffusion through the pore phase of a voxel image (docs/electrode_analysis.md, "Pore
// transport"): Fick's law in the pore voxels, no flux into the solid, concentration 1 in a
// reservoir against the box's low face along the transport axis and 0 in one against its high
// face, periodic along the other two axes (or closed: no flux). Finite volumes on the voxels:
// between two face-neighbouring pore voxels the conductance D0 A / d (A the shared face, d the
// distance of the centres), to a reservoir D0 A / (d / 2). The system of the unknown
// concentrations is symmetric positive definite, a seven-point operator on the voxel grid
// (voxel_operator.hpp: conjugate gradients with a multigrid preconditioner). Pore voxels connected
// to no reservoir carry no flux and are left out.
//
// D_eff / D0 = J L / (A_box D0 (c_in - c_out)), J the flux out of the inlet reservoir, and the
// tortuosity factor tau = eps D0 / D_eff (D_eff = D0 eps / tau, the definition of TauFactor,
// Cooper et al. 2016, SoftwareX 5, 203-210; tau = 1 for straight channels, tau >= 1). Some
// authors call tau^(1/2) the tortuosity, or use the MacMullin number N_M = D0 / D_eff = tau / eps.

#include <vector>

#include "sqdem/analysis/voxel_image.hpp"

namespace sqdem {

struct PoreDiffusion {
  int axis = 2;                   ///< transport along x, y or z (0, 1, 2)
  double porosity = 0.0;          ///< eps: pore voxels over all
  bool percolates = false;        ///< a pore path joins the two reservoirs
  double diffusivityRatio = 0.0;  ///< D_eff / D0 (0 without a path)
  double tortuosityFactor = 0.0;  ///< eps D0 / D_eff (infinite without a path)
  double fluxImbalance = 0.0;     ///< |J_in - J_out| / J_in: the solution's conservation
  long iterations = 0;            ///< conjugate-gradient iterations
  bool converged = true;          ///< to the tolerance, within the iteration limit
  std::vector<double> concentration;  ///< per voxel, c_in = 1, c_out = 0; solid and unconnected voxels NaN
};

/// Solves the image's pore diffusion along `axis`, `periodic` along the two others, to the
/// relative residual `tolerance` (|r| / |b|). Throws std::invalid_argument for an empty image or
/// an axis outside 0-2.
PoreDiffusion solvePoreDiffusion(const VoxelImage& image, int axis, bool periodic, double tolerance = 1e-10);

}  // namespace sqdem
