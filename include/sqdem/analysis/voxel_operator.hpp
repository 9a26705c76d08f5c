#pragma once
// A seven-point finite-volume operator on a voxel grid and its solver (docs/electrode_analysis.md,
// "Pore transport"): per cell a diagonal and the conductances to its +x, +y, +z neighbours, so
// (A x)_c = d_c x_c - sum over the six faces of g x_neighbour. The grid wraps along every axis;
// a face that does not conduct (a closed or a reservoir face, or a solid cell) has g = 0. A cell
// with d = 0 is no unknown (solid, or pore connected to no reservoir): it stays 0.
//
// Solved by conjugate gradients preconditioned with one V-cycle of aggregation multigrid: cells
// merged in blocks of 2 x 2 x 2 (an axis shorter than 4 cells is not merged), the coarse operator
// the Galerkin product P^T A P of the piecewise-constant interpolation P, again a seven-point
// operator on the grid of blocks, down to at most 512 cells, solved there by a dense Cholesky
// factorisation; two damped Jacobi sweeps (weight 6/7) before and after the coarse correction,
// which is scaled by 1.8: piecewise-constant interpolation leaves the coarse correction of smooth
// error about half as large as it should be, and an over-correction below 2 mends that while the
// cycle stays a symmetric positive-definite preconditioner (Braess 1995, Computing 55, 379-393;
// docs/electrode_analysis.md gives the measured iterations). Every loop runs over cells or blocks
// and every dot product adds fixed chunks in a fixed order: the same bits with any thread count.

#include <array>
#include <vector>

#include "sqdem/analysis/spd_solve.hpp"

namespace sqdem {

struct VoxelOperator {
  std::array<int, 3> size{0, 0, 0};      ///< cells along x, y, z; cell (i, j, k) at i + nx (j + ny k)
  std::vector<double> diagonal;          ///< per cell; 0: no unknown
  std::array<std::vector<double>, 3> face;  ///< per cell, the conductance to its +x, +y, +z neighbour (wrapped)

  explicit VoxelOperator(std::array<int, 3> cells);
  std::size_t count() const { return diagonal.size(); }
  /// y = A x.
  void apply(const std::vector<double>& x, std::vector<double>& y) const;
};

/// Solves A x = b from `guess` to the relative residual |b - A x| / |b| <= tolerance, in at most
/// maxIterations iterations. x is 0 on the cells that are no unknowns.
SpdSolution solveVoxelOperator(const VoxelOperator& A, const std::vector<double>& b, std::vector<double> guess,
                               double tolerance, long maxIterations);

}  // namespace sqdem
