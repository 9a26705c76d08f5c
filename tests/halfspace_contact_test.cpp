// The boundary-element reference solver (halfspace/halfspace_contact.hpp) against closed forms:
// Love's rectangle at its centre, 8 a ln(1 + 2^(1/2)) (Johnson 1985, Contact Mechanics, Eq. 3.25);
// two spheres (Hertz: F = 4/3 E* R^(1/2) delta^(3/2), a = (R delta)^(1/2), p0 = 2 E* a / (pi R);
// Johnson Eqs. 4.22-4.23) and two elliptic paraboloids (Johnson Sec. 4.2(c): the elliptic Hertz
// force and ellipse from the eccentricity's equation, 004 Eqs. 1, 2, 13, which
// mechanics/elliptic.hpp solves), with the convergence in the grid printed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>
#include <cstdio>
#include <limits>
#include <numbers>

#include "sqdem/halfspace/halfspace_contact.hpp"
#include "sqdem/halfspace/love_influence.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {
namespace {

/// The gap x^2 / (2 Rx) + y^2 / (2 Ry) on n x n cells over the square of half-width w.
GapGrid paraboloid(double Rx, double Ry, double w, int n) {
  GapGrid grid;
  grid.nx = grid.ny = n;
  grid.hx = grid.hy = 2.0 * w / n;
  grid.x0 = grid.y0 = -w;
  grid.gap.resize(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) grid.gap[i + static_cast<std::size_t>(n) * j] = grid.x(i) * grid.x(i) / (2.0 * Rx) + grid.y(j) * grid.y(j) / (2.0 * Ry);
  }
  return grid;
}

TEST(LoveInfluence, TheCentreOfASquareAndFarAway) {
  EXPECT_NEAR(loveRectangleDisplacement(0.0, 0.0, 1.5, 1.5), 8.0 * 1.5 * std::log(1.0 + std::numbers::sqrt2), 1e-13);
  // Far away the rectangle acts as a point load P = 4 a b p: u = P / (pi E* r) (Boussinesq).
  const double r = 1e3;
  EXPECT_NEAR(loveRectangleDisplacement(0.6 * r, 0.8 * r, 0.5, 2.0) / (4.0 * 0.5 * 2.0 / r), 1.0, 1e-6);
  // Symmetric in x and y; on the edge lines the finite limit.
  EXPECT_DOUBLE_EQ(loveRectangleDisplacement(0.3, -0.7, 1.0, 0.5), loveRectangleDisplacement(-0.3, 0.7, 1.0, 0.5));
  EXPECT_TRUE(std::isfinite(loveRectangleDisplacement(1.0, 2.0, 1.0, 0.5)));
}

// The surface displacement of a pressure field is the sum over the loaded cells of Love's
// rectangle (its definition), whichever way the solver sums it: directly on a 20 x 40 grid (up to
// 32 x 32 cells' worth; rows of 20 cells in register blocks of sixteen, the last one partial) and on
// rows shorter than a block (9, 8, 1 cells), by FFT on a 40 x 40 one.
TEST(HalfspaceContact, TheDisplacementIsTheSumOfLovesRectangles) {
  for (const auto& [nx, ny] : {std::pair{20, 40}, std::pair{9, 5}, std::pair{8, 3}, std::pair{1, 7}, std::pair{40, 40}}) {
    GapGrid grid;
    grid.nx = nx, grid.ny = ny, grid.hx = 0.3, grid.hy = 0.7;
    grid.gap.assign(static_cast<std::size_t>(nx) * ny, 1.0);
    const double E = 2.5;
    const HalfspaceSolver solver(grid, E);
    std::vector<double> p(grid.gap.size());
    for (std::size_t k = 0; k < p.size(); ++k) p[k] = (k % 7 == 0 || k % 11 == 3) ? 1.0 + 0.1 * static_cast<double>(k % 13) : 0.0;
    const std::vector<double> u = solver.displacement(p);
    double largest = 0.0;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        double sum = 0.0;
        for (int sj = 0; sj < ny; ++sj) {
          for (int si = 0; si < nx; ++si) {
            sum += p[si + static_cast<std::size_t>(nx) * sj] * loveRectangleDisplacement((i - si) * grid.hx, (j - sj) * grid.hy, 0.5 * grid.hx, 0.5 * grid.hy);
          }
        }
        sum /= std::numbers::pi * E;
        largest = std::max(largest, std::abs(u[i + static_cast<std::size_t>(nx) * j] / sum - 1.0));
      }
    }
    std::printf("%d x %d cells: largest relative difference from the definition %.2e\n", nx, ny, largest);
    EXPECT_LT(largest, 1e-13);
  }
}

/// Love's bracket (love_influence.hpp) in long double, a reference for the double ones, and the
/// size of its terms m ln(n / d) for their rounding, sum |m| (1 + |ln(n / d)|).
struct LongBracket {
  long double value = 0, termSize = 0;
};
LongBracket loveBracketLong(long double x, long double y, long double a, long double b) {
  const auto sum = [](long double s, long double t) {  // s + (s^2 + t^2)^(1/2), t^2 / (r - s) for s < 0
    const long double r = std::sqrt(s * s + t * t);
    return s >= 0 ? s + r : t * t / (r - s);
  };
  LongBracket bracket;
  const auto add = [&](long double m, long double n, long double d) {
    if (m == 0) return;
    const long double logarithm = std::log(n / d);
    bracket.value += m * logarithm, bracket.termSize += std::abs(m) * (1 + std::abs(logarithm));
  };
  const long double xp = x + a, xm = x - a, yp = y + b, ym = y - b;
  add(xp, sum(yp, xp), sum(ym, xp)), add(yp, sum(xp, yp), sum(xm, yp)), add(xm, sum(ym, xm), sum(yp, xm)), add(ym, sum(xm, ym), sum(xp, ym));
  return bracket;
}

// The grid's brackets, from the logarithms shared along its cells' edges, against Love's bracket
// at each cell's centre in long double: on square, oblong and thin cells (aspects 1e-3 to 10, as
// the true gap's regions are: gap_region.hpp), on square and oblong grids, up to 96 cells, the
// boundary-element example's. Far from a cell its four terms cancel (to ~cell / distance of their
// size), so each bracket is held to its terms' rounding: each term m ln(n / d) rounds by a few
// ulps of |m| (1 + |ln(n / d)|) (the sums n, d and their ratio by ~3 ulps each, the logarithm
// and the product by one), their sum by as many: 16 ulps of the terms' size. The per-cell
// bracket's own difference is printed beside.
TEST(HalfspaceContact, TheGridsBracketsAreLovesAtEachCell) {
  static_assert(std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits + 8, "a reference finer than double");
  constexpr double ulp = std::numeric_limits<double>::epsilon();
  for (const auto& [nx, ny, hx, hy] : {std::tuple{16, 16, 1e-5, 1e-5}, std::tuple{16, 16, 0.3, 0.7}, std::tuple{16, 16, 2e-6, 2e-9},
                                       std::tuple{24, 24, 1.0, 10.0}, std::tuple{16, 9, 1e-5, 4e-6}, std::tuple{7, 24, 0.5, 0.2},
                                       std::tuple{96, 96, 3e-6, 1e-6}}) {
    const std::vector<double> grid = loveGridDisplacements(nx, ny, hx, hy);
    double largest = 0.0, largestCell = 0.0, largestOverRounding = 0.0;
    for (int dj = 0; dj < ny; ++dj) {
      for (int di = 0; di < nx; ++di) {
        const LongBracket love = loveBracketLong(di * static_cast<long double>(hx), dj * static_cast<long double>(hy), 0.5L * hx, 0.5L * hy);
        const double cell = loveRectangleDisplacement(di * hx, dj * hy, 0.5 * hx, 0.5 * hy);
        const long double difference = std::abs(grid[di + static_cast<std::size_t>(nx) * dj] - love.value);
        largest = std::max(largest, static_cast<double>(difference / love.value));
        largestCell = std::max(largestCell, static_cast<double>(std::abs(cell - love.value) / love.value));
        largestOverRounding = std::max(largestOverRounding, static_cast<double>(difference / (16 * ulp * love.termSize)));
      }
    }
    std::printf("%d x %d cells of %g x %g m: largest relative difference from Love's bracket (long double) %.2e (per cell %.2e), "
                "%.2f of the terms' rounding bound\n", nx, ny, hx, hy, largest, largestCell, largestOverRounding);
    EXPECT_LT(largestOverRounding, 1.0);
  }
}

TEST(HalfspaceContact, TwoSpheresGiveHertz) {
  const double R = 1e-5, E = 1e11, delta = 1e-8, a = std::sqrt(R * delta);
  const double force = 4.0 / 3.0 * E * std::sqrt(R) * std::pow(delta, 1.5), p0 = 2.0 * E * a / (std::numbers::pi * R);
  double previous = 1.0;
  for (const int n : {32, 64, 128}) {
    const GapGrid grid = paraboloid(R, R, 1.3 * a, n);
    const HalfspaceSolver solver(grid, E);
    const HalfspaceContact c = solver.atApproach(delta);
    const double error = c.force / force - 1.0, radius = std::sqrt(c.area / std::numbers::pi);
    const double peak = *std::max_element(c.pressure.begin(), c.pressure.end());
    std::printf("n = %d: F/F_Hertz - 1 = %+.2e, contact radius %+.2f cells from a, p_max/p0 - 1 = %+.2e, %d iterations\n", n, error,
                (radius - a) / grid.hx, peak / p0 - 1.0, c.iterations);
    ASSERT_TRUE(c.converged);
    EXPECT_FALSE(c.reachesEdge);
    EXPECT_LT(std::abs(error), previous);
    EXPECT_LT(std::abs(radius - a), 2.0 * grid.hx);
    previous = std::abs(error);
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(HalfspaceContact, ALoadGivesTheApproachOfThatLoad) {
  const double R = 1e-5, E = 1e11, delta = 1e-8, a = std::sqrt(R * delta);
  const HalfspaceSolver solver(paraboloid(R, R, 1.3 * a, 96), E);
  const HalfspaceContact byApproach = solver.atApproach(delta);
  const HalfspaceContact byLoad = solver.atLoad(byApproach.force);
  ASSERT_TRUE(byLoad.converged);
  EXPECT_NEAR(byLoad.approach / delta, 1.0, 1e-8);
  EXPECT_NEAR(byLoad.force / byApproach.force, 1.0, 1e-12);
  const double p0 = 2.0 * E * a / (std::numbers::pi * R);  // Hertz's peak pressure
  for (std::size_t k = 0; k < byLoad.pressure.size(); ++k) EXPECT_NEAR(byLoad.pressure[k], byApproach.pressure[k], 1e-7 * p0);
}

TEST(HalfspaceContact, EllipticParaboloidsGiveEllipticHertzWithASymmetricPressure) {
  const double Rx = 4e-5, Ry = 1e-5, E = 1e11, delta = 1e-8;
  const HertzFactors f = hertzFactors(Ry / Rx, EccentricityMethod::Exact);
  const double Rc = Rx * Ry / (Rx + Ry);
  const double force = ellipticHertzForce(E, Rc, delta, f.gamma), area = ellipticHertzArea(Rc, delta, f.beta);
  // The semi-axes: pi a b = area, b / a = (1 - e^2)^(1/2), a along x (the larger radius).
  const double a = std::sqrt(area / (std::numbers::pi * std::sqrt(1.0 - f.e2))), b = a * std::sqrt(1.0 - f.e2);
  double previous = 1.0;
  for (const int n : {48, 96, 192}) {
    GapGrid grid = paraboloid(Rx, Ry, 1.3 * a, n);
    grid.hy = 2.6 * b / n;  // cells of the ellipse's aspect
    grid.y0 = -1.3 * b;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) grid.gap[i + static_cast<std::size_t>(n) * j] = grid.x(i) * grid.x(i) / (2.0 * Rx) + grid.y(j) * grid.y(j) / (2.0 * Ry);
    }
    const HalfspaceSolver solver(grid, E);
    const HalfspaceContact c = solver.atApproach(delta);
    const double error = c.force / force - 1.0;
    // The ellipse's semi-axes from the contact cells along the axes through the centre.
    int alongX = 0, alongY = 0;
    for (int i = 0; i < n; ++i) alongX += c.pressure[i + static_cast<std::size_t>(n) * (n / 2)] > 0.0;
    for (int j = 0; j < n; ++j) alongY += c.pressure[n / 2 + static_cast<std::size_t>(n) * j] > 0.0;
    std::printf("n = %d: F/F_Hertz - 1 = %+.2e, area/A_Hertz - 1 = %+.2e, semi-axes %+.2f, %+.2f cells from a, b; %d iterations\n", n,
                error, c.area / area - 1.0, (0.5 * alongX * grid.hx - a) / grid.hx, (0.5 * alongY * grid.hy - b) / grid.hy, c.iterations);
    ASSERT_TRUE(c.converged);
    EXPECT_LT(std::abs(error), previous);
    EXPECT_LT(std::abs(0.5 * alongX * grid.hx - a), 2.0 * grid.hx);
    EXPECT_LT(std::abs(0.5 * alongY * grid.hy - b), 2.0 * grid.hy);
    previous = std::abs(error);
    // A gap symmetric in x and in y gives a pressure symmetric in both.
    double asymmetry = 0.0, peak = 0.0;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const double v = c.pressure[i + static_cast<std::size_t>(n) * j];
        peak = std::max(peak, v);
        asymmetry = std::max({asymmetry, std::abs(v - c.pressure[(n - 1 - i) + static_cast<std::size_t>(n) * j]),
                              std::abs(v - c.pressure[i + static_cast<std::size_t>(n) * (n - 1 - j)])});
      }
    }
    EXPECT_LT(asymmetry, 1e-9 * peak);
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(HalfspaceContact, NoInterferenceNoPressureAndBadInputRefused) {
  const GapGrid grid = paraboloid(1e-5, 1e-5, 1e-7, 16);
  const HalfspaceSolver solver(grid, 1e11);
  const HalfspaceContact c = solver.atApproach(-1e-9);
  EXPECT_TRUE(c.converged);
  EXPECT_EQ(c.force, 0.0);
  EXPECT_THROW(solver.atLoad(0.0), std::invalid_argument);
  EXPECT_THROW(HalfspaceSolver(grid, 0.0), std::invalid_argument);
  GapGrid bad = grid;
  bad.gap.pop_back();
  EXPECT_THROW(HalfspaceSolver(bad, 1e11), std::invalid_argument);
}

}  // namespace
}  // namespace sqdem
