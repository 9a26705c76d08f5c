// Cell-list search of the candidate pairs (neighbour_list.hpp), in open space: a grid over the
// particles' bounding box.
#include <algorithm>
#include <array>
#include <cmath>

#include "sqdem/world/neighbour_list.hpp"

namespace sqdem {

std::vector<CandidatePair> cellListPairs(const ParticleCloud& cloud, double skin) {
  const std::vector<Vec3>& position = cloud.position;
  const std::vector<double>& radius = cloud.radius;
  std::vector<CandidatePair> pairs;
  const std::size_t n = position.size();
  if (n < 2) return pairs;

  Vec3 lo = position[0], hi = position[0];
  for (const Vec3& x : position) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double maxRadius = *std::max_element(radius.begin(), radius.end());
  const double width = 2.0 * maxRadius + skin;
  // Cells at least `width` wide (the last one along each direction wider); a sparse cloud gets
  // fewer, larger cells, so the grid never holds many more cells than particles.
  std::array<double, 3> fit{};
  for (int d = 0; d < 3; ++d) fit[d] = std::max(1.0, std::floor((hi(d) - lo(d)) / width));
  const double largestGrid = std::max(27.0, 4.0 * static_cast<double>(n));
  while (fit[0] * fit[1] * fit[2] > largestGrid) {
    double& widest = *std::max_element(fit.begin(), fit.end());
    widest = std::max(1.0, std::floor(widest / 2.0));
  }
  std::array<int, 3> cells{};
  Vec3 cellSize;
  for (int d = 0; d < 3; ++d) {
    cells[d] = static_cast<int>(fit[d]);
    cellSize(d) = cells[d] == 1 ? 1.0 : (hi(d) - lo(d)) / cells[d];
  }
  const auto cellOf = [&](const Vec3& x) {
    std::array<int, 3> c{};
    for (int d = 0; d < 3; ++d) c[d] = std::clamp(static_cast<int>(std::floor((x(d) - lo(d)) / cellSize(d))), 0, cells[d] - 1);
    return c;
  };
  const auto flat = [&](const std::array<int, 3>& c) { return (c[2] * cells[1] + c[1]) * cells[0] + c[0]; };

  // Counting sort of particles into cells (deterministic order: by slot within a cell).
  std::vector<int> start(static_cast<std::size_t>(cells[0]) * cells[1] * cells[2] + 1, 0), cellIndex(n);
  for (std::size_t i = 0; i < n; ++i) ++start[(cellIndex[i] = flat(cellOf(position[i]))) + 1];
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::uint32_t> sorted(n);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) sorted[fill[cellIndex[i]]++] = static_cast<std::uint32_t>(i);

  for (std::size_t i = 0; i < n; ++i) {
    const std::array<int, 3> ci = cellOf(position[i]);
    std::array<int, 3> from{}, to{};
    for (int d = 0; d < 3; ++d) {
      from[d] = std::max(ci[d] - 1, 0);
      to[d] = std::min(ci[d] + 1, cells[d] - 1);
    }
    for (int z = from[2]; z <= to[2]; ++z) {
      for (int y = from[1]; y <= to[1]; ++y) {
        for (int x = from[0]; x <= to[0]; ++x) {
          const int c = flat({x, y, z});
          for (int k = start[c]; k < start[c + 1]; ++k) {
            const std::uint32_t j = sorted[k];
            if (j <= i) continue;
            const auto a = static_cast<std::uint32_t>(i);
            if (withinSkin(cloud, a, j, candidateDistanceSquared(cloud, a, j), skin)) pairs.push_back(oriented(cloud, a, j));
          }
        }
      }
    }
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const CandidatePair& x, const CandidatePair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  return pairs;
}

}  // namespace sqdem
