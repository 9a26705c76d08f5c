#include "sqdem/halfspace/halfspace_contact.hpp"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <numbers>
#include <stdexcept>

#include "sqdem/halfspace/love_influence.hpp"

namespace sqdem {

namespace {

/// The cells [first, last) of one row of the grid.
struct CellSpan {
  int first = 0, last = 0;
};

/// A loaded cell (si, sj) of the direct convolution: its pressure, and its offset in the kernel,
/// (nx - 1 - si) - (2 nx - 1) sj: added to target row j's start (2 nx - 1) (j + ny - 1) it points
/// at K(-si, j - sj), the kernel's row for that pair of rows.
struct Load {
  std::ptrdiff_t kernelOffset = 0;
  double value = 0.0;
};

/// Eight targets in GCC's vector extension (one instruction on x86-64-v4, two on v3, four on the
/// baseline).
using Octet = double __attribute__((vector_size(8 * sizeof(double))));
constexpr int lanes = 8, octets = 2;
/// Targets per register block of the direct convolution, two octets (independent chains of
/// additions, on which each load's share waits otherwise); the kernel is padded by as many values.
constexpr int block = lanes * octets;

/// u = K * p on an nx x ny grid, summed directly over the loaded cells, in each row j at the
/// cells rows[j] (u untouched elsewhere); `kernel` at offsets (di, dj),
/// (di + nx - 1) + (2 nx - 1) (dj + ny - 1), followed by `block` values of padding. Each row's
/// cells are taken in blocks of sixteen held in registers while the loads (in row order, then
/// along the row) are summed into them: the same sums in the same order, cell by cell, as adding
/// each load's share to u in turn, with one store per block instead of one per load (docs/
/// performance.md, "Cheaper rungs" and its second round). Compiled also for x86-64-v4 and v3
/// (eight and four lanes instead of two) and chosen at run time: the same sequence of operations
/// per cell either way, the same bits.
#if defined(__x86_64__) && defined(__GLIBC__) && !defined(__clang__)  // an ifunc: GCC on glibc
[[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]]
#endif
void directConvolution(const double* kernel, const Load* loads, std::size_t loadCount, double* u, int nx, int ny, const CellSpan* rows) {
  const std::ptrdiff_t row = 2 * nx - 1;
  for (int j = 0; j < ny; ++j) {
    const double* kernelRow = kernel + row * (j + ny - 1);
    for (int first = rows[j].first; first < rows[j].last; first += block) {
      Octet sum[octets] = {};
      for (std::size_t l = 0; l < loadCount; ++l) {  // u(i, j) += K(i - si, j - sj) p(si, sj), i = first ... first + 15
        const double* k = kernelRow + loads[l].kernelOffset + first;
        for (int q = 0; q < octets; ++q) {
          Octet share;
          std::memcpy(&share, k + lanes * q, sizeof share);
          sum[q] += share * loads[l].value;
        }
      }
      const int count = std::min(block, rows[j].last - first);
      for (int c = 0; c < count; ++c) u[first + c + static_cast<std::ptrdiff_t>(nx) * j] = sum[c / lanes][c % lanes];
    }
  }
}

}  // namespace

/// u = K * p on the grid: the linear convolution of the pressure with Love's kernel. On small
/// grids (at most 32 x 32 cells) by direct summation over the loaded cells, each row's span
/// rounded up to blocks of sixteen: cheaper than the two transforms below (a 16 x 16 grid: ~10 us
/// against ~85 us, measured before the blocks).
/// On larger ones by FFT on the grid padded to 2 nx x 2 ny (the kernel at offsets
/// -(n - 1) ... n - 1 wrapped, the pressure zero outside the grid: no periodic images reach the
/// grid's cells).
struct HalfspaceSolver::Convolution {
  using Complex = std::complex<double>;
  static constexpr int largestDirect = 32 * 32;
  int nx, ny, mx, my;  // the grid and the padded sizes
  std::vector<double> direct;    // the kernel at offsets (di, dj), (di + nx - 1) + (2 nx - 1) (dj + ny - 1); small grids
  std::vector<Complex> kernel;   // its padded transform; large grids
  mutable Eigen::FFT<double> fft;
  std::vector<CellSpan> wholeRows;  // every cell of every row
  mutable std::vector<Load> loads;  // the direct sum's loaded cells, kept between calls (one solver serves one thread at a time)

  Convolution(const GapGrid& grid, double effectiveModulus)
      : nx(grid.nx), ny(grid.ny), mx(2 * grid.nx), my(2 * grid.ny), wholeRows(grid.ny, CellSpan{0, grid.nx}) {
    const double scale = 1.0 / (std::numbers::pi * effectiveModulus);
    const bool small = nx * ny <= largestDirect;
    if (small) direct.resize(static_cast<std::size_t>(2 * nx - 1) * (2 * ny - 1) + block);
    else kernel.resize(static_cast<std::size_t>(mx) * my);
    // Love's solution is even in x and in y: one quadrant computed, four filled.
    const std::vector<double> quadrant = loveGridDisplacements(nx, ny, grid.hx, grid.hy);
    for (int dj = 0; dj < ny; ++dj) {
      for (int di = 0; di < nx; ++di) {
        const double k = scale * quadrant[di + static_cast<std::size_t>(nx) * dj];
        for (const int si : {di, -di}) {
          for (const int sj : {dj, -dj}) {
            if (small) direct[static_cast<std::size_t>(si + nx - 1) + static_cast<std::size_t>(2 * nx - 1) * (sj + ny - 1)] = k;
            else kernel[wrap(si, sj)] = k;
          }
        }
      }
    }
    if (!small) transform(kernel, true);
  }

  std::size_t wrap(int di, int dj) const {
    return static_cast<std::size_t>((di + mx) % mx) + static_cast<std::size_t>(mx) * static_cast<std::size_t>((dj + my) % my);
  }

  /// The 2-D transform of the padded array, forward or inverse (scaled), rows then columns.
  void transform(std::vector<Complex>& a, bool forward) const {
    std::vector<Complex> in, out;
    const auto pass = [&](int count, int length, auto at) {
      in.resize(length);
      for (int line = 0; line < count; ++line) {
        for (int k = 0; k < length; ++k) in[k] = a[at(line, k)];
        if (forward) fft.fwd(out, in);
        else fft.inv(out, in);
        for (int k = 0; k < length; ++k) a[at(line, k)] = out[k];
      }
    };
    pass(my, mx, [&](int j, int i) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(mx) * j; });
    pass(mx, my, [&](int i, int j) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(mx) * j; });
  }

  /// u at every cell, or (summed directly) at the cells `rows` only, 0 elsewhere.
  void apply(const std::vector<double>& p, const std::vector<CellSpan>& rows, std::vector<double>& u) const {
    if (direct.empty()) applyTransformed(p, u);
    else applyDirect(p, rows, u);
  }
  std::vector<double> apply(const std::vector<double>& p) const {
    std::vector<double> u;
    apply(p, wholeRows, u);
    return u;
  }

  void applyDirect(const std::vector<double>& p, const std::vector<CellSpan>& rows, std::vector<double>& u) const {
    loads.clear();
    const std::ptrdiff_t row = 2 * nx - 1;
    for (int sj = 0; sj < ny; ++sj) {
      for (int si = 0; si < nx; ++si) {
        const double load = p[si + static_cast<std::size_t>(nx) * sj];
        if (load != 0.0) loads.push_back({nx - 1 - si - row * sj, load});
      }
    }
    u.assign(p.size(), 0.0);
    directConvolution(direct.data(), loads.data(), loads.size(), u.data(), nx, ny, rows.data());
  }

  void applyTransformed(const std::vector<double>& p, std::vector<double>& u) const {
    std::vector<Complex> a(kernel.size(), 0.0);
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) a[static_cast<std::size_t>(i) + static_cast<std::size_t>(mx) * j] = p[i + static_cast<std::size_t>(nx) * j];
    }
    transform(a, true);
    for (std::size_t k = 0; k < a.size(); ++k) a[k] *= kernel[k];
    transform(a, false);
    u.resize(p.size());
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) u[i + static_cast<std::size_t>(nx) * j] = a[static_cast<std::size_t>(i) + static_cast<std::size_t>(mx) * j].real();
    }
  }
};

HalfspaceSolver::HalfspaceSolver(const GapGrid& grid, double effectiveModulus) : grid_(grid), effectiveModulus_(effectiveModulus) {
  if (grid.nx < 1 || grid.ny < 1 || !(grid.hx > 0.0) || !(grid.hy > 0.0) ||
      grid.gap.size() != static_cast<std::size_t>(grid.nx) * grid.ny) {
    throw std::invalid_argument("HalfspaceSolver: the grid needs nx, ny >= 1, cell edges > 0 and a gap per cell");
  }
  if (std::any_of(grid.gap.begin(), grid.gap.end(), [](double h) { return std::isnan(h); })) {
    throw std::invalid_argument("HalfspaceSolver: a gap is NaN (+infinity marks a cell that cannot touch)");
  }
  if (!(effectiveModulus > 0.0) || !std::isfinite(effectiveModulus)) {
    throw std::invalid_argument("HalfspaceSolver: the effective modulus must be finite and > 0");
  }
  convolution_ = std::make_unique<Convolution>(grid, effectiveModulus);
}

HalfspaceSolver::~HalfspaceSolver() = default;

std::vector<double> HalfspaceSolver::displacement(const std::vector<double>& pressure) const { return convolution_->apply(pressure); }

HalfspaceContact HalfspaceSolver::atApproach(double approach, double tolerance, int maxIterations) const {
  return solve(approach, 0.0, tolerance, maxIterations);
}

HalfspaceContact HalfspaceSolver::atLoad(double load, double tolerance, int maxIterations) const {
  if (!(load > 0.0)) throw std::invalid_argument("HalfspaceSolver::atLoad: the load must be > 0");
  return solve(0.0, load, tolerance, maxIterations);
}

HalfspaceContact HalfspaceSolver::solve(double approach, double load, double tolerance, int maxIterations) const {
  const std::vector<double>& h = grid_.gap;
  const std::size_t n = h.size();
  const double cell = grid_.hx * grid_.hy;
  const bool byLoad = load > 0.0;
  HalfspaceContact result;
  result.approach = approach;
  std::vector<double>& p = result.pressure;
  p.assign(n, 0.0);
  // The start: a uniform pressure carrying the load (Polonsky & Keer), or at an approach Hertz's
  // pressure p0 sqrt(1 - r^2 / a^2), p0 = 2 E* a / (pi R), a^2 = R delta (Johnson 1985, Sec.
  // 4.2) written in the gap h = r^2 / (2 R): (2 E* / (pi a)) sqrt(2 delta (delta / 2 - h))
  // over the cells with h < delta / 2, a the radius of their area (or, should none be there, the
  // same over the cells with h < delta); started again four times softer should a step release
  // every cell. Closer to the solution than a pressure linear in the interference: 6 % fewer
  // iterations in the peer n = 6 bed's rungs (docs/performance.md, "Cheaper rungs").
  const auto below = [&](double level) { return std::count_if(h.begin(), h.end(), [&](double g) { return g < level; }); };
  const auto interfering = below(approach), hertzian = below(0.5 * approach);
  const double level = hertzian > 0 ? 0.5 * approach : approach;
  const double radius = std::sqrt(cell * static_cast<double>(std::max<std::ptrdiff_t>(hertzian > 0 ? hertzian : interfering, 1)) / std::numbers::pi);
  double stiffness = 2.0 * effectiveModulus_ / (std::numbers::pi * radius);
  const auto seed = [&] {
    const auto finite = std::count_if(h.begin(), h.end(), [](double g) { return std::isfinite(g); });
    for (std::size_t k = 0; k < n; ++k) {
      if (!std::isfinite(h[k])) p[k] = 0.0;
      else p[k] = byLoad ? load / (cell * static_cast<double>(finite)) : stiffness * std::sqrt(std::max(2.0 * approach * (level - h[k]), 0.0));
    }
  };
  if (!byLoad && (interfering == 0 || !(approach > 0.0))) {  // (h >= 0: an approach <= 0 presses nothing)
    result.converged = true;
    return result;
  }
  seed();
  // Polonsky & Keer's Sec. 3 steps: the gap g on the contact cells (p > 0), the conjugate
  // direction t over them, the step tau, cells with p < 0 released and cells with g < 0 at
  // p = 0 taken in (the conjugacy restarted then), the load restored. The displacement u = K p
  // follows the step: p - tau t moves it by -tau K t, known from the step's length; the
  // released and taken-in cells' corrections (few) are convolved on their own.
  // At a prescribed approach only cells with h < delta can touch (u >= 0); u is summed in each row
  // over the span of those cells, 0 outside it, where h >= delta keeps g >= 0: never taken in.
  std::vector<CellSpan> rows = convolution_->wholeRows;
  if (!byLoad) {
    for (int j = 0; j < grid_.ny; ++j) {
      const double* row = h.data() + static_cast<std::size_t>(grid_.nx) * j;
      CellSpan span{grid_.nx, 0};
      for (int i = 0; i < grid_.nx; ++i) {
        if (row[i] < approach) span.first = std::min(span.first, i), span.last = i + 1;
      }
      rows[j] = span.last > 0 ? span : CellSpan{};
    }
  }
  // Off the spans p, t and the corrections stay 0: every loop below runs over the spans' cells,
  // row by row (the same sums, in the same order, as over all cells).
  std::vector<std::size_t> cells;
  for (int j = 0; j < grid_.ny; ++j) {
    for (int i = rows[j].first; i < rows[j].last; ++i) cells.push_back(static_cast<std::size_t>(grid_.nx) * j + i);
  }
  std::vector<double> g(n), t(n, 0.0), previous(n), correction(n), u, Kt, Kc;
  convolution_->apply(p, rows, u);
  double gOld = 1.0;
  bool conjugate = false;
  const auto meanOverContact = [&](const std::vector<double>& v) {
    double sum = 0.0;
    long count = 0;
    for (const std::size_t k : cells) {
      if (p[k] > 0.0) sum += v[k], ++count;
    }
    return count > 0 ? sum / static_cast<double>(count) : 0.0;
  };
  for (result.iterations = 0; result.iterations < maxIterations;) {
    ++result.iterations;
    if (std::all_of(cells.begin(), cells.end(), [&](std::size_t k) { return p[k] == 0.0; })) {
      stiffness *= 0.25;
      seed();
      convolution_->apply(p, rows, u);
      conjugate = false;
    }
    for (const std::size_t k : cells) g[k] = u[k] + h[k] - approach;
    if (byLoad) {
      const double mean = meanOverContact(g);
      for (double& v : g) v -= mean;
    }
    double G = 0.0;
    for (const std::size_t k : cells) {
      if (p[k] > 0.0) G += g[k] * g[k];
    }
    const double beta = conjugate ? G / gOld : 0.0;
    for (const std::size_t k : cells) t[k] = p[k] > 0.0 ? g[k] + beta * t[k] : 0.0;
    gOld = G;
    convolution_->apply(t, rows, Kt);
    const double shift = byLoad ? meanOverContact(Kt) : 0.0;  // r = K t, less its mean over the contact at a load
    double gt = 0.0, rt = 0.0;
    for (const std::size_t k : cells) {
      if (p[k] > 0.0) gt += g[k] * t[k], rt += (Kt[k] - shift) * t[k];
    }
    if (!(rt > 0.0)) {  // the gap already zero on the contact: nothing to do
      result.converged = G == 0.0;
      break;
    }
    const double tau = gt / rt;
    for (const std::size_t k : cells) previous[k] = p[k];
    conjugate = true;
    bool corrected = false;
    for (const std::size_t k : cells) {
      const double stepped = previous[k] - tau * t[k];  // t = 0 off the contact
      p[k] = previous[k] > 0.0 ? std::max(stepped, 0.0) : 0.0;
      if (p[k] == 0.0 && g[k] < 0.0) {  // interpenetrating without pressure
        p[k] = -tau * g[k];
        conjugate = false;
      }
      correction[k] = p[k] - stepped;  // 0 but where a cell was released or taken in
      corrected = corrected || correction[k] != 0.0;
    }
    for (const std::size_t k : cells) u[k] -= tau * Kt[k];
    if (corrected) {
      convolution_->apply(correction, rows, Kc);
      for (const std::size_t k : cells) u[k] += Kc[k];
    }
    double total = 0.0, change = 0.0;
    for (const std::size_t k : cells) total += p[k];
    if (byLoad && total > 0.0) {
      const double scale = load / (cell * total);
      for (double& v : p) v *= scale;
      for (double& v : u) v *= scale;
      total = load / cell;
    }
    for (const std::size_t k : cells) change += std::abs(p[k] - previous[k]);
    if (total > 0.0 && change <= tolerance * total) {
      result.converged = true;
      break;
    }
  }
  double total = 0.0;
  long contact = 0;
  for (int j = 0; j < grid_.ny; ++j) {
    for (int i = 0; i < grid_.nx; ++i) {
      const double v = p[i + static_cast<std::size_t>(grid_.nx) * j];
      if (v <= 0.0) continue;
      total += v, ++contact;
      result.reachesEdge = result.reachesEdge || i == 0 || j == 0 || i == grid_.nx - 1 || j == grid_.ny - 1;
    }
  }
  result.force = cell * total;
  result.area = cell * static_cast<double>(contact);
  if (byLoad) {  // the approach: the mean of u + h over the contact, where the gap closes
    u = convolution_->apply(p);  // afresh, without the steps' rounding
    for (std::size_t k = 0; k < n; ++k) g[k] = u[k] + h[k];
    result.approach = meanOverContact(g);
  }
  return result;
}

}  // namespace sqdem
