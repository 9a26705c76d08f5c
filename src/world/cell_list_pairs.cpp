// Cell-list search of the candidate pairs (neighbour_list.hpp).
#include <algorithm>
#include <array>
#include <cmath>

#include "sqdem/world/neighbour_list.hpp"

namespace sqdem {
namespace {

/// Periodic directions with fewer cells than this are searched all-pairs (nearest image).
constexpr int minimumPeriodicCells = 3;

}  // namespace

std::vector<CandidatePair> cellListPairs(const Domain& domain, const ParticleCloud& cloud, double skin) {
  const std::vector<Vec3>& position = cloud.position;
  const std::vector<double>& radius = cloud.radius;
  std::vector<CandidatePair> pairs;
  const std::size_t n = position.size();
  if (n < 2) return pairs;

  const double maxRadius = *std::max_element(radius.begin(), radius.end());
  const double width = 2.0 * maxRadius + skin;
  std::array<int, 3> cells{};
  Vec3 cellSize;
  // Cells at least `width` wide; a sparse domain (few particles in a huge box) gets fewer,
  // larger cells, so the grid never holds many more cells than particles.
  std::array<double, 3> fit{};
  for (int d = 0; d < 3; ++d) fit[d] = std::max(1.0, std::floor(domain.length()(d) / width));
  const double largestGrid = std::max(27.0, 4.0 * static_cast<double>(n));
  while (fit[0] * fit[1] * fit[2] > largestGrid) {
    double& widest = *std::max_element(fit.begin(), fit.end());
    widest = std::max(1.0, std::floor(widest / 2.0));
  }
  for (int d = 0; d < 3; ++d) {
    cells[d] = static_cast<int>(fit[d]);
    if (domain.periodic[d] && cells[d] < minimumPeriodicCells) cells[d] = 1;  // all-pairs along d
    cellSize(d) = domain.length()(d) / cells[d];
  }
  const auto cellOf = [&](const Vec3& x) {
    std::array<int, 3> c{};
    for (int d = 0; d < 3; ++d) {
      c[d] = std::clamp(static_cast<int>(std::floor((x(d) - domain.lo(d)) / cellSize(d))), 0, cells[d] - 1);
    }
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
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const std::array<int, 3> offset{dx, dy, dz};
          std::array<int, 3> cj{};
          Vec3 shift = Vec3::Zero();
          bool inside = true;
          for (int d = 0; d < 3; ++d) {
            if (cells[d] == 1) {
              if (offset[d] != 0) inside = false;  // a single cell is its own only neighbour
              cj[d] = 0;
              continue;
            }
            cj[d] = ci[d] + offset[d];
            if (cj[d] < 0 || cj[d] >= cells[d]) {
              if (!domain.periodic[d]) { inside = false; continue; }
              shift(d) = cj[d] < 0 ? -domain.length()(d) : domain.length()(d);
              cj[d] = (cj[d] + cells[d]) % cells[d];
            }
          }
          if (!inside) continue;
          const int c = flat(cj);
          for (int k = start[c]; k < start[c + 1]; ++k) {
            const std::uint32_t j = sorted[k];
            if (j <= i) continue;
            // A single periodic cell along d: take the nearest image of j (the same seen from
            // either side: round(-x) = -round(x)).
            Vec3 s = shift;
            for (int d = 0; d < 3; ++d) {
              if (cells[d] == 1 && domain.periodic[d]) {
                const double L = domain.length()(d), dd = position[j](d) - position[i](d);
                s(d) = -L * std::round(dd / L);
              }
            }
            const auto a = static_cast<std::uint32_t>(i);
            if (withinSkin(cloud, a, j, candidateDistanceSquared(cloud, a, j, s), skin)) pairs.push_back(oriented(cloud, a, j, s));
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
