#pragma once
// A settled bed for the decomposition tests: points in the bottom fifth of a box periodic in x
// and y (a few below the floor, as particles may leave an open direction), costs 1-3.

#include <random>
#include <utility>
#include <vector>

#include "sqdem/geometry/domain.hpp"

namespace sqdem::testing {

inline Domain bedBox() { return {Vec3::Zero(), Vec3(2.0, 1.0, 3.0), {true, true, false}}; }

inline std::pair<std::vector<Vec3>, std::vector<double>> settledBed(const Domain& box, int n) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> points;
  std::vector<double> costs;
  for (int i = 0; i < n; ++i) {
    const double z = i % 500 == 0 ? -0.01 * u(rng) : 0.2 * box.hi.z() * u(rng) * u(rng);
    points.emplace_back(box.hi.x() * u(rng), box.hi.y() * u(rng), z);
    costs.push_back(1.0 + 2.0 * u(rng));
  }
  return {points, costs};
}

}  // namespace sqdem::testing
