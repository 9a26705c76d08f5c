// Recursive coordinate bisection (distributed/decomposition.hpp) on a settled bed: every point
// lies in exactly one sub-domain, the sub-domains tile the box, and each rank's cost is its share
// of the total to within the cut tolerance (the largest single cost per level of cuts), for 1-8
// ranks and a bed that fills only the bottom fifth of a box periodic in x and y.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "decomposition_points.hpp"
#include "sqdem/distributed/decomposition.hpp"

namespace sqdem {
namespace {

TEST(Decomposition, BisectionSharesTheCostAndTilesTheBox) {
  const Domain box = testing::bedBox();
  const auto [points, costs] = testing::settledBed(box, 5000);
  const double largest = *std::max_element(costs.begin(), costs.end());
  double total = 0.0;
  for (const double c : costs) total += c;
  const SerialCommunicator one;
  for (int ranks = 1; ranks <= 8; ++ranks) {
    const std::vector<SubDomain> parts = bisect(box, points, costs, ranks, one);
    ASSERT_EQ(parts.size(), static_cast<std::size_t>(ranks));
    std::vector<double> cost(ranks, 0.0);
    for (std::size_t i = 0; i < points.size(); ++i) {
      int owners = 0;
      for (const SubDomain& s : parts) owners += s.owns(points[i]);
      ASSERT_EQ(owners, 1) << "point " << i << " at " << points[i].transpose();
      cost[ownerOf(parts, points[i])] += costs[i];
    }
    // The sub-domains clipped to the box fill it without overlap: their volumes add up to it.
    double volume = 0.0;
    for (const SubDomain& s : parts) volume += (s.hi.cwiseMin(box.hi) - s.lo.cwiseMax(box.lo)).cwiseMax(0.0).prod();
    EXPECT_NEAR(volume, box.length().prod(), 1e-12 * box.length().prod()) << ranks << " ranks";
    const double levels = std::ceil(std::log2(ranks));
    for (int r = 0; r < ranks; ++r) {
      EXPECT_NEAR(cost[r], total / ranks, levels * largest + 1e-9 * total) << "rank " << r << " of " << ranks;
    }
  }
}

}  // namespace
}  // namespace sqdem
