#pragma once
// The frictionless normal contact of two elastic bodies with an arbitrary gap, each taken as a
// half-space (docs/contact_laws.md, "The boundary-element reference"): the gap h(x, y) >= 0
// between the two undeformed surfaces over their common tangent plane, the bodies pressed
// together by the approach delta; the pressure p >= 0 and the gap after deformation
// g = h - delta + u[p] >= 0 are complementary (p g = 0). u[p] is the sum of both surfaces'
// normal displacements.
//
// Boundary elements: a grid of nx x ny cells of edges hx, hy, the pressure uniform on each cell,
// u at each cell's centre the sum over the cells of Love's rectangle solution
// (love_influence.hpp), a discrete convolution: summed directly on grids of up to 32 x 32 cells,
// by FFT on larger ones, padded to twice their size (no wrap-around: Liu, Wang & Liu 2000,
// Wear 243, 101-111, "DC-FFT"). The complementarity
// problem is solved by the conjugate gradients with an active set of Polonsky & Keer (1999,
// Wear 231, 206-219): at a prescribed approach, or at a prescribed load (their algorithm, the
// approach then the mean gap over the contact).

#include <memory>
#include <vector>

namespace sqdem {

/// The undeformed gap on a grid of cell centres x_i = x0 + (i + 1/2) hx, y_j = y0 + (j + 1/2) hy.
struct GapGrid {
  int nx = 0, ny = 0;
  double hx = 0.0, hy = 0.0;  ///< (m) cell edges
  double x0 = 0.0, y0 = 0.0;  ///< (m) the grid's low corner
  std::vector<double> gap;    ///< (m) per cell, i + nx j; its minimum is where the bodies first touch

  double x(int i) const { return x0 + (i + 0.5) * hx; }
  double y(int j) const { return y0 + (j + 0.5) * hy; }
};

struct HalfspaceContact {
  double approach = 0.0;  ///< delta (m): prescribed, or the solution at a prescribed load
  double force = 0.0;     ///< (N) the pressure's integral
  double area = 0.0;      ///< (m^2) the cells in contact (p > 0)
  std::vector<double> pressure;  ///< (Pa) per cell
  int iterations = 0;
  bool converged = false;
  bool reachesEdge = false;  ///< pressure on the grid's outermost cells: the grid is too small
};

/// Precomputes the influence of the grid's cells on each other (Love's kernel, or its FFT) and
/// solves contacts on it. Gaps of +infinity mark cells that cannot touch; NaN is refused. One
/// solver serves one thread at a time, every member function included (its FFT keeps plans, its
/// direct sum a list of the loaded cells).
class HalfspaceSolver {
 public:
  /// effectiveModulus E* (Pa) of the pair; the grid is copied.
  HalfspaceSolver(const GapGrid& grid, double effectiveModulus);
  ~HalfspaceSolver();
  HalfspaceSolver(const HalfspaceSolver&) = delete;
  HalfspaceSolver& operator=(const HalfspaceSolver&) = delete;

  /// The contact at the approach delta (m) to the relative pressure change `tolerance`; none
  /// (converged, no force) at delta <= 0.
  HalfspaceContact atApproach(double approach, double tolerance = 1e-10, int maxIterations = 5000) const;
  /// The contact carrying the load W > 0 (N).
  HalfspaceContact atLoad(double load, double tolerance = 1e-10, int maxIterations = 5000) const;
  /// u[p] at every cell centre (m) for the cells' pressures p (Pa).
  std::vector<double> displacement(const std::vector<double>& pressure) const;

 private:
  HalfspaceContact solve(double approach, double load, double tolerance, int maxIterations) const;
  struct Convolution;
  GapGrid grid_;
  double effectiveModulus_;
  std::unique_ptr<Convolution> convolution_;
};

}  // namespace sqdem
