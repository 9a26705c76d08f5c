// Recursive coordinate bisection across MPI ranks (distributed/decomposition.hpp), run under
// mpirun with 1-4 ranks: each rank holds a share of the points (dealt out by index), and the
// sub-domains are, bit for bit, those of one process holding all of them (every reduction of
// the bisection is exact: sums by ExactSum, extrema and counts by nature).

#include <gtest/gtest.h>

#include "decomposition_points.hpp"
#include "sqdem/distributed/decomposition.hpp"
#include "sqdem/distributed/mpi_communicator.hpp"

namespace sqdem {
namespace {

TEST(MpiDecomposition, SubDomainsDoNotDependOnHowThePointsAreSpread) {
  const std::shared_ptr<Communicator> ranks = worldCommunicator();
  const Domain box = testing::bedBox();
  const auto [points, costs] = testing::settledBed(box, 5000);
  std::vector<Vec3> mine;
  std::vector<double> myCosts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (static_cast<int>(i % ranks->size()) != ranks->rank()) continue;
    mine.push_back(points[i]);
    myCosts.push_back(costs[i]);
  }
  for (int parts : {1, 2, 3, 5, 8}) {
    const std::vector<SubDomain> spread = bisect(box, mine, myCosts, parts, *ranks);
    const std::vector<SubDomain> whole = bisect(box, points, costs, parts, SerialCommunicator());
    for (int r = 0; r < parts; ++r) {
      EXPECT_EQ(spread[r].lo, whole[r].lo) << parts << " parts, part " << r;
      EXPECT_EQ(spread[r].hi, whole[r].hi) << parts << " parts, part " << r;
    }
  }
}

}  // namespace
}  // namespace sqdem
