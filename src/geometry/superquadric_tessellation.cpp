#include "sqdem/geometry/superquadric_tessellation.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace sqdem {

SurfaceGrid surfaceGrid(int resolution) {
  if (resolution < 1) throw std::invalid_argument("tessellate: resolution must be >= 1");
  const int N = resolution;
  SurfaceGrid t;
  // A cube vertex by its integer grid coordinates (i, j, k) in [0, N]^3, shared between faces.
  std::unordered_map<long, std::uint32_t> index;
  const auto vertex = [&](int i, int j, int k) {
    const long key = (static_cast<long>(i) * (N + 1) + j) * (N + 1) + k;
    const auto [at, added] = index.try_emplace(key, static_cast<std::uint32_t>(t.angles.size()));
    if (added) {
      const auto angle = [N](int m) { return std::tan(0.25 * std::numbers::pi * (2.0 * m / N - 1.0)); };
      const Vec3 d = Vec3(angle(i), angle(j), angle(k)).normalized();  // the grid's outer coordinate is tan(+-pi/4) = +-1
      t.angles.push_back({std::asin(d.z()), std::atan2(d.y(), d.x())});
    }
    return at->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // (axis, u, v) right-handed
    for (const int side : {0, N}) {
      for (int a = 0; a < N; ++a) {
        for (int b = 0; b < N; ++b) {
          std::array<std::uint32_t, 4> quad;
          const int corners[4][2] = {{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}};
          for (int c = 0; c < 4; ++c) {
            int g[3];
            g[axis] = side;
            g[u] = corners[c][0];
            g[v] = corners[c][1];
            quad[c] = vertex(g[0], g[1], g[2]);
          }
          // Counter-clockwise about +axis on the far side, about -axis on the near side.
          if (side == 0) std::swap(quad[1], quad[3]);
          t.quads.push_back(quad);
        }
      }
    }
  }
  return t;
}

Tessellation tessellate(const Superquadric& shape, int resolution) {
  SurfaceGrid grid = surfaceGrid(resolution);
  Tessellation t{{}, std::move(grid.quads)};
  t.points.reserve(grid.angles.size());
  for (const auto& [eta, omega] : grid.angles) t.points.push_back(shape.surfacePoint(eta, omega));
  return t;
}

}  // namespace sqdem
