#include "sqdem/analysis/voxel_operator.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <utility>

namespace sqdem {
namespace {

using Vector = std::vector<double>;

/// Cells of a grid row by row: a row is the nx cells of one (j, k), its neighbours' rows wrapped.
struct Rows {
  std::array<int, 3> n;
  std::int64_t count() const { return static_cast<std::int64_t>(n[1]) * n[2]; }
  std::size_t start(std::int64_t row) const { return static_cast<std::size_t>(row) * n[0]; }
  /// The row one step (s = -1, +1) along y (d = 1) or z (d = 2), wrapped.
  std::size_t neighbour(std::int64_t row, int d, int s) const {
    int j = static_cast<int>(row % n[1]), k = static_cast<int>(row / n[1]);
    if (d == 1) j = (j + s + n[1]) % n[1];
    else k = (k + s + n[2]) % n[2];
    return start(static_cast<std::int64_t>(j) + static_cast<std::int64_t>(n[1]) * k);
  }
};

/// a . b summed in chunks of a fixed length, the chunks' sums added in order: the same bits with
/// any thread count.
double dot(const Vector& a, const Vector& b) {
  constexpr std::int64_t chunk = 4096;
  const auto n = static_cast<std::int64_t>(a.size()), chunks = (n + chunk - 1) / chunk;
  Vector sums(static_cast<std::size_t>(chunks));
#pragma omp parallel for schedule(static)
  for (std::int64_t c = 0; c < chunks; ++c) {
    double s = 0.0;
    for (std::int64_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i) s += a[i] * b[i];
    sums[c] = s;
  }
  double total = 0.0;
  for (const double s : sums) total += s;
  return total;
}

/// y = a x + y over all cells.
void axpy(double a, const Vector& x, Vector& y) {
  const auto n = static_cast<std::int64_t>(x.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) y[i] += a * x[i];
}

/// One level of the hierarchy: its operator, how its cells merge into the next level's blocks,
/// and the work vectors of a V-cycle.
struct Level {
  explicit Level(const VoxelOperator& op) : A(op) {}
  const VoxelOperator& A;             ///< the fine operator or a coarse one
  std::array<int, 3> merge{1, 1, 1};  ///< cells per block along x, y, z
  Vector x, b, r;
};

/// Calls visit(C, c) for every block C of the grid `coarse` and each of its cells c on the grid
/// `n` (blocks of merge[d] cells, the last one along an axis possibly shorter), parallel over
/// the blocks.
template <class Visit>
void forEachBlockCell(const std::array<int, 3>& n, const std::array<int, 3>& merge, const std::array<int, 3>& coarse, Visit visit) {
  const std::int64_t rows = static_cast<std::int64_t>(coarse[1]) * coarse[2];
#pragma omp parallel for schedule(static)
  for (std::int64_t row = 0; row < rows; ++row) {
    const int J = static_cast<int>(row % coarse[1]), K = static_cast<int>(row / coarse[1]);
    for (int I = 0; I < coarse[0]; ++I) {
      const std::size_t C = static_cast<std::size_t>(I) + static_cast<std::size_t>(coarse[0]) * static_cast<std::size_t>(row);
      for (int k = K * merge[2]; k < std::min(n[2], (K + 1) * merge[2]); ++k) {
        for (int j = J * merge[1]; j < std::min(n[1], (J + 1) * merge[1]); ++j) {
          for (int i = I * merge[0]; i < std::min(n[0], (I + 1) * merge[0]); ++i) {
            visit(C, std::array<int, 3>{i, j, k},
                  static_cast<std::size_t>(i) + static_cast<std::size_t>(n[0]) * (j + static_cast<std::size_t>(n[1]) * k));
          }
        }
      }
    }
  }
}

std::array<int, 3> coarseSize(const std::array<int, 3>& n, const std::array<int, 3>& merge) {
  return {(n[0] + merge[0] - 1) / merge[0], (n[1] + merge[1] - 1) / merge[1], (n[2] + merge[2] - 1) / merge[2]};
}

/// The Galerkin coarse operator P^T A P of blocks of merge[d] cells (1 or 2) along each axis.
VoxelOperator coarsened(const VoxelOperator& A, const std::array<int, 3>& merge) {
  const std::array<int, 3>& n = A.size;
  VoxelOperator next(coarseSize(n, merge));
  forEachBlockCell(n, merge, next.size, [&](std::size_t C, const std::array<int, 3>& at, std::size_t c) {
    next.diagonal[C] += A.diagonal[c];
    for (int d = 0; d < 3; ++d) {
      const double g = A.face[d][c];
      if (g == 0.0) continue;
      // The +d neighbour in the same block (an inner face: P^T A P adds -g twice to the
      // diagonal) or in the next block along d.
      if ((at[d] + 1) % n[d] / merge[d] == at[d] / merge[d]) next.diagonal[C] -= 2.0 * g;
      else next.face[d][C] += g;
    }
  });
  return next;
}

/// One V-cycle of the hierarchy: z ~ A^-1 r, linear and symmetric in r (the same smoothing before
/// and after the coarse correction).
class Multigrid {
 public:
  explicit Multigrid(const VoxelOperator& fine) {
    levels_.emplace_back(fine);
    constexpr std::size_t coarsest = 512;  // cells solved directly
    for (;;) {
      Level& level = levels_.back();
      bool merges = false;
      for (int d = 0; d < 3; ++d) {
        level.merge[d] = level.A.size[d] >= 4 ? 2 : 1;
        merges = merges || level.merge[d] == 2;
      }
      if (level.A.count() <= coarsest || !merges) {
        level.merge = {1, 1, 1};
        break;
      }
      coarse_.push_back(coarsened(level.A, level.merge));
      levels_.emplace_back(coarse_.back());
    }
    for (std::size_t l = 0; l < levels_.size(); ++l) {
      Level& level = levels_[l];
      level.r.assign(level.A.count(), 0.0);
      if (l > 0) level.x = level.b = level.r;  // the finest level's b and x are the caller's
    }
    factorCoarsest();
  }

  /// z = M^-1 r.
  void precondition(const Vector& r, Vector& z) { cycle(0, r, z); }

 private:
  static constexpr double damping = 6.0 / 7.0;  // damped Jacobi for the seven-point stencil
  static constexpr double overCorrection = 1.8;
  static constexpr int sweeps = 2;  // before and after the coarse correction

  void factorCoarsest() {
    const VoxelOperator& A = levels_.back().A;
    const std::array<int, 3>& n = A.size;
    for (std::size_t c = 0; c < A.count(); ++c) {
      if (A.diagonal[c] > 0.0) unknown_.push_back(c);
    }
    std::vector<std::int64_t> row(A.count(), -1);
    for (std::size_t u = 0; u < unknown_.size(); ++u) row[unknown_[u]] = static_cast<std::int64_t>(u);
    const auto m = static_cast<Eigen::Index>(unknown_.size());
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(m, m);
    const std::array<std::size_t, 3> step{1, static_cast<std::size_t>(n[0]), static_cast<std::size_t>(n[0]) * n[1]};
    for (const std::size_t c : unknown_) {
      const std::int64_t u = row[c];
      dense(u, u) += A.diagonal[c];
      const std::array<int, 3> at{static_cast<int>(c % n[0]), static_cast<int>(c / n[0] % n[1]), static_cast<int>(c / step[2])};
      for (int d = 0; d < 3; ++d) {
        if (A.face[d][c] == 0.0) continue;
        const std::size_t w = at[d] + 1 < n[d] ? c + step[d] : c - step[d] * (n[d] - 1);
        dense(u, row[w]) -= A.face[d][c];
        dense(row[w], u) -= A.face[d][c];
      }
    }
    coarsest_.compute(dense);
  }

  void cycle(std::size_t l, const Vector& b, Vector& x) {
    Level& level = levels_[l];
    if (l + 1 == levels_.size()) {
      Eigen::VectorXd coarseB(static_cast<Eigen::Index>(unknown_.size()));
      for (std::size_t u = 0; u < unknown_.size(); ++u) coarseB[u] = b[unknown_[u]];
      const Eigen::VectorXd solved = coarsest_.solve(coarseB);
      std::fill(x.begin(), x.end(), 0.0);
      for (std::size_t u = 0; u < unknown_.size(); ++u) x[unknown_[u]] = solved[u];
      return;
    }
    smooth(level, b, x, true);
    level.A.apply(x, level.r);
    Level& next = levels_[l + 1];
    std::fill(next.b.begin(), next.b.end(), 0.0);
    forEachBlockCell(level.A.size, level.merge, next.A.size,
                     [&](std::size_t C, const std::array<int, 3>&, std::size_t c) { next.b[C] += b[c] - level.r[c]; });
    cycle(l + 1, next.b, next.x);
    forEachBlockCell(level.A.size, level.merge, next.A.size,
                     [&](std::size_t C, const std::array<int, 3>&, std::size_t c) {
                       if (level.A.diagonal[c] > 0.0) x[c] += overCorrection * next.x[C];  // no unknown stays 0
                     });
    smooth(level, b, x, false);
  }

  /// `sweeps` damped Jacobi sweeps x += w D^-1 (b - A x), the first from x = 0 if `fromZero`.
  void smooth(Level& level, const Vector& b, Vector& x, bool fromZero) {
    const VoxelOperator& A = level.A;
    const auto cells = static_cast<std::int64_t>(A.count());
    for (int s = 0; s < sweeps; ++s) {
      if (s == 0 && fromZero) {
#pragma omp parallel for schedule(static)
        for (std::int64_t c = 0; c < cells; ++c) x[c] = A.diagonal[c] > 0.0 ? damping * b[c] / A.diagonal[c] : 0.0;
        continue;
      }
      A.apply(x, level.r);
#pragma omp parallel for schedule(static)
      for (std::int64_t c = 0; c < cells; ++c) {
        if (A.diagonal[c] > 0.0) x[c] += damping * (b[c] - level.r[c]) / A.diagonal[c];
      }
    }
  }

  std::deque<VoxelOperator> coarse_;  ///< the coarse levels' operators (a deque: a Level refers to its own)
  std::deque<Level> levels_;
  std::vector<std::size_t> unknown_;  ///< the coarsest grid's cells that are unknowns
  Eigen::LLT<Eigen::MatrixXd> coarsest_;
};

}  // namespace

VoxelOperator::VoxelOperator(std::array<int, 3> cells)
    : size(cells), diagonal(static_cast<std::size_t>(cells[0]) * cells[1] * cells[2], 0.0), face{diagonal, diagonal, diagonal} {}

void VoxelOperator::apply(const Vector& x, Vector& y) const {
  const Rows rows{size};
  const int nx = size[0];
#pragma omp parallel for schedule(static)
  for (std::int64_t row = 0; row < rows.count(); ++row) {
    const std::size_t c0 = rows.start(row), south = rows.neighbour(row, 1, -1), north = rows.neighbour(row, 1, +1),
                      below = rows.neighbour(row, 2, -1), above = rows.neighbour(row, 2, +1);
    const double* gx = face[0].data() + c0;
    const double* xr = x.data() + c0;
    // Cell i of the row and its x neighbours west, east (wrapped at the row's ends).
    const auto cell = [&](int i, int west, int east) {
      const std::size_t c = c0 + i;
      return diagonal[c] * xr[i] - gx[i] * xr[east] - gx[west] * xr[west] - face[1][c] * x[north + i] -
             face[1][south + i] * x[south + i] - face[2][c] * x[above + i] - face[2][below + i] * x[below + i];
    };
    y[c0] = cell(0, nx - 1, nx > 1 ? 1 : 0);
    for (int i = 1; i < nx - 1; ++i) y[c0 + i] = cell(i, i - 1, i + 1);
    if (nx > 1) y[c0 + nx - 1] = cell(nx - 1, nx - 2, 0);
  }
}

SpdSolution solveVoxelOperator(const VoxelOperator& A, const Vector& b, Vector guess, double tolerance, long maxIterations) {
  Multigrid preconditioner(A);
  const std::size_t n = A.count();
  SpdSolution solution{std::move(guess), 0, false};
  Vector& x = solution.x;
  for (std::size_t c = 0; c < n; ++c) {
    if (A.diagonal[c] == 0.0) x[c] = 0.0;
  }
  Vector r(n), z(n), p(n), q(n);
  A.apply(x, r);
  for (std::size_t c = 0; c < n; ++c) r[c] = b[c] - r[c];
  const double bNorm = std::sqrt(dot(b, b));
  if (bNorm == 0.0) return {Vector(n, 0.0), 0, true};
  preconditioner.precondition(r, z);
  p = z;
  double rz = dot(r, z);
  for (;;) {
    if (std::sqrt(dot(r, r)) <= tolerance * bNorm) {
      solution.converged = true;
      break;
    }
    if (solution.iterations == maxIterations) break;
    ++solution.iterations;
    A.apply(p, q);
    const double alpha = rz / dot(p, q);
    axpy(alpha, p, x);
    axpy(-alpha, q, r);
    preconditioner.precondition(r, z);
    const double rzNext = dot(r, z), beta = rzNext / rz;
    rz = rzNext;
#pragma omp parallel for schedule(static)
    for (std::int64_t c = 0; c < static_cast<std::int64_t>(n); ++c) p[c] = z[c] + beta * p[c];
  }
  return solution;
}

}  // namespace sqdem
