#pragma once
// The centres placed so far by random sequential addition, binned in a uniform grid of cells at
// least `reach` wide along each direction (reach >= the largest r_i + r_j the insertion can ask
// for), so that a candidate meets only the centres of its own and the adjacent cells: an
// insertion of N particles costs O(N) instead of O(N^2).
//
// Why a skipped centre cannot fail the overlap test |minimumImage(x - c)| > r + r_c: the cells
// visited around x's cell k are, along each direction d, k-1, k, k+1, clamped to the grid along a
// non-periodic direction and taken modulo n_d along a periodic one (all n_d cells when n_d < 3).
// A centre c that is skipped lies, along some direction d, in a cell j with |j - k| >= 2
// (non-periodic), or with both j - k and k - j at least 2 modulo n_d (periodic). Cell j holds
// lo + j s <= c_d <= lo + (j+1) s (s = L / n_d >= reach + 1e-12 L), as every centre lies in
// [lo, hi] along d (the loader keeps regions and explicit centres inside the domain, periodic
// ones are wrapped into [lo, hi)): clamping only moves a centre at hi into the last cell. So
// |x_d - c_d| >= s and, along a periodic d, L - |x_d - c_d| >= s too; the image shift
// round(d / L) in {-1, 0, 1} leaves a component at least the smaller of the two, and the norm is
// at least any component. Rounding (binning, subtraction, image shift, norm: each correctly
// rounded, hence monotone) moves these by a few ulps of L, far below the 1e-12 L margin, and the
// computed r + r_c is at most reach (both rounded sums of the bounds), so the computed test is
// true, as if c had been tested. A conjunction of side-effect-free tests does not depend on their
// order, so every accept/reject decision is the full scan's.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sqdem/geometry/domain.hpp"

namespace sqdem::detail {

class InsertionGrid {
 public:
  /// Cells of the domain at least reach (+ 1e-12 L) wide; at most ~4 x expectedCentres of them
  /// (wider cells when the domain is large for the particles: coarser, never wrong).
  InsertionGrid(const Domain& domain, double reach, std::size_t expectedCentres);

  /// Adds centre index i (i == the number of centres added before) at x.
  void add(std::uint32_t i, const Vec3& x);

  /// test(j) for every centre j in the cells around x, each once, until one returns false.
  template <class Test>
  bool allOf(const Vec3& x, Test&& test) const {
    std::array<std::array<int, 3>, 3> cells{};  // per direction the cells visited
    std::array<int, 3> count{};
    for (int d = 0; d < 3; ++d) {
      const int k = cellOf(x, d);
      const int first = periodic_[d] ? k - 1 : std::max(k - 1, 0);
      count[d] = periodic_[d] ? std::min(n_[d], 3) : std::min(k + 1, n_[d] - 1) - first + 1;
      for (int a = 0; a < count[d]; ++a) cells[d][a] = (first + a + n_[d]) % n_[d];
    }
    for (int a = 0; a < count[0]; ++a) {
      for (int b = 0; b < count[1]; ++b) {
        const std::size_t row = (static_cast<std::size_t>(cells[0][a]) * n_[1] + cells[1][b]) * n_[2];
        for (int c = 0; c < count[2]; ++c) {
          for (std::int32_t j = head_[row + cells[2][c]]; j >= 0; j = next_[j]) {
            if (!test(static_cast<std::uint32_t>(j))) return false;
          }
        }
      }
    }
    return true;
  }

 private:
  int cellOf(const Vec3& x, int d) const {
    return static_cast<int>(std::clamp(std::floor((x(d) - lo_(d)) / cell_(d)), 0.0, n_[d] - 1.0));
  }

  Vec3 lo_, cell_;
  std::array<bool, 3> periodic_;
  std::array<int, 3> n_;
  std::vector<std::int32_t> head_, next_;  // per cell the last centre added, per centre the one before
};

}  // namespace sqdem::detail
