#include "sqdem/analysis/pore_diffusion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include "sqdem/analysis/voxel_operator.hpp"

namespace sqdem {
namespace {

/// A voxel's neighbours on the image: a voxel, a reservoir, or nothing (a closed face).
struct Grid {
  const VoxelImage& image;
  int axis;
  bool periodic;

  static constexpr std::int64_t inlet = -1, outlet = -2, closed = -3;

  std::array<int, 3> coordinates(std::size_t v) const {
    const auto nx = static_cast<std::size_t>(image.size[0]), ny = static_cast<std::size_t>(image.size[1]);
    return {static_cast<int>(v % nx), static_cast<int>((v / nx) % ny), static_cast<int>(v / (nx * ny))};
  }
  /// The neighbour of voxel c one step (s = -1, +1) along direction d.
  std::int64_t neighbour(std::array<int, 3> c, int d, int s) const {
    c[d] += s;
    if (c[d] < 0 || c[d] >= image.size[d]) {
      if (d == axis) return c[d] < 0 ? inlet : outlet;
      if (!periodic) return closed;
      c[d] = (c[d] + image.size[d]) % image.size[d];
    }
    return static_cast<std::int64_t>(image.index(c[0], c[1], c[2]));
  }
  /// D0 A / d across a face normal to d, D0 = 1.
  double conductance(int d) const {
    const Vec3& h = image.voxel;
    return h[(d + 1) % 3] * h[(d + 2) % 3] / h[d];
  }
};

/// The pore voxels a flood from the reservoir `from` reaches.
std::vector<std::uint8_t> reachedFrom(const Grid& grid, std::int64_t from) {
  const VoxelImage& image = grid.image;
  std::vector<std::uint8_t> reached(image.count(), 0);
  std::vector<std::size_t> front;
  for (std::size_t v = 0; v < image.count(); ++v) {
    const std::array<int, 3> c = grid.coordinates(v);
    if (image.pore[v] && (grid.neighbour(c, grid.axis, -1) == from || grid.neighbour(c, grid.axis, +1) == from)) {
      reached[v] = 1;
      front.push_back(v);
    }
  }
  while (!front.empty()) {
    const std::size_t v = front.back();
    front.pop_back();
    const std::array<int, 3> c = grid.coordinates(v);
    for (int d = 0; d < 3; ++d) {
      for (const int s : {-1, 1}) {
        const std::int64_t w = grid.neighbour(c, d, s);
        if (w >= 0 && image.pore[w] && !reached[w]) {
          reached[w] = 1;
          front.push_back(static_cast<std::size_t>(w));
        }
      }
    }
  }
  return reached;
}

}  // namespace

PoreDiffusion solvePoreDiffusion(const VoxelImage& image, int axis, bool periodic, double tolerance) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("solvePoreDiffusion: the axis must be 0, 1 or 2");
  if (image.count() == 0 || image.pore.size() != image.count()) throw std::invalid_argument("solvePoreDiffusion: an empty image");
  const Grid grid{image, axis, periodic};
  PoreDiffusion result;
  result.axis = axis;
  result.porosity = image.porosity();
  const std::vector<std::uint8_t> fromInlet = reachedFrom(grid, Grid::inlet), fromOutlet = reachedFrom(grid, Grid::outlet);
  std::vector<std::uint8_t> connected(image.count(), 0);
  for (std::size_t v = 0; v < image.count(); ++v) {
    result.percolates = result.percolates || (fromInlet[v] && fromOutlet[v]);
    connected[v] = fromInlet[v] || fromOutlet[v];
  }
  if (!result.percolates) {  // no path: D_eff = 0; the connected voxels take their reservoir's value
    result.concentration.assign(image.count(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t v = 0; v < image.count(); ++v) {
      if (connected[v]) result.concentration[v] = fromInlet[v] ? 1.0 : 0.0;
    }
    result.tortuosityFactor = std::numeric_limits<double>::infinity();
    return result;
  }
  // The finite-volume system A c = b over the connected pore voxels.
  VoxelOperator A(image.size);
  std::vector<double> b(image.count(), 0.0), guess(image.count(), 0.0);
  const auto voxels = static_cast<std::int64_t>(image.count());
#pragma omp parallel for schedule(static)
  for (std::int64_t v = 0; v < voxels; ++v) {  // each voxel writes its own row
    if (!connected[v]) continue;
    const std::array<int, 3> c = grid.coordinates(v);
    guess[v] = 1.0 - (c[axis] + 0.5) / image.size[axis];  // the open box's linear profile
    for (int d = 0; d < 3; ++d) {
      const double g = grid.conductance(d);
      for (const int s : {-1, 1}) {
        const std::int64_t w = grid.neighbour(c, d, s);
        if (w == Grid::inlet || w == Grid::outlet) {
          A.diagonal[v] += 2.0 * g;  // half a voxel to the reservoir
          if (w == Grid::inlet) b[v] += 2.0 * g;
        } else if (w >= 0 && connected[w] && w != v) {
          A.diagonal[v] += g;
          if (s == 1) A.face[d][v] += g;
        }
      }
    }
  }
  SpdSolution solution =
      solveVoxelOperator(A, b, std::move(guess), tolerance, std::max<long>(1000, 20L * (image.size[0] + image.size[1] + image.size[2])));
  result.iterations = solution.iterations;
  result.converged = solution.converged;
  // The fluxes out of the inlet and into the outlet reservoir.
  double in = 0.0, out = 0.0;
  std::vector<double>& concentration = solution.x;
  for (std::size_t v = 0; v < image.count(); ++v) {
    if (!connected[v]) {
      concentration[v] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    const std::array<int, 3> c = grid.coordinates(v);
    const double g = 2.0 * grid.conductance(axis);
    if (grid.neighbour(c, axis, -1) == Grid::inlet) in += g * (1.0 - concentration[v]);
    if (grid.neighbour(c, axis, +1) == Grid::outlet) out += g * concentration[v];
  }
  result.concentration = std::move(concentration);
  const Vec3 length = image.voxel.cwiseProduct(Vec3(image.size[0], image.size[1], image.size[2]));
  const double area = length[(axis + 1) % 3] * length[(axis + 2) % 3];
  result.diffusivityRatio = in * length[axis] / area;
  result.tortuosityFactor = result.porosity / result.diffusivityRatio;
  result.fluxImbalance = std::abs(in - out) / in;
  return result;
}

}  // namespace sqdem
