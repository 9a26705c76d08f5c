// The reduction seam across MPI ranks (mpi_communicator.hpp), run under mpirun with 1-4 ranks:
// every rank adds its share of the same addends (dealt out by rank), and the reduced exact sums
// equal, bit for bit, the one-process ExactSum of all of them (math/exact_sum.hpp: exact, so
// independent of the split); counts, maxima, minima and decisions are the ranks' closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "sqdem/distributed/mpi_communicator.hpp"

namespace sqdem {
namespace {

std::vector<double> addends(int n) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> mantissa(-2.0, 2.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  std::vector<double> xs(n);
  for (double& x : xs) x = std::ldexp(mantissa(rng), exponent(rng));
  return xs;
}

TEST(MpiCommunicator, ExactSumsAreTheOneProcessSums) {
  const std::shared_ptr<Communicator> ranks = worldCommunicator();
  const int r = ranks->rank(), size = ranks->size();
  const std::vector<double> xs = addends(10007);
  std::array<ExactSum, 2> share, whole;  // the addends, and their squares
  for (std::size_t i = 0; i < xs.size(); ++i) {
    whole[0].add(xs[i]);
    whole[1].add(xs[i] * xs[i]);
    if (static_cast<int>(i % size) != r) continue;
    share[0].add(xs[i]);
    share[1].add(xs[i] * xs[i]);
  }
  ranks->sum(share);
  EXPECT_EQ(share[0].value(), whole[0].value());
  EXPECT_EQ(share[1].value(), whole[1].value());
  std::printf("rank %d of %d: sum %.17g\n", r, size, share[0].value());
}

TEST(MpiCommunicator, CountsExtremaAndDecisions) {
  const std::shared_ptr<Communicator> ranks = worldCommunicator();
  const int r = ranks->rank(), size = ranks->size();
  EXPECT_EQ(ranks->sum(static_cast<long long>(r + 1)), static_cast<long long>(size) * (size + 1) / 2);
  EXPECT_EQ(ranks->max(static_cast<double>(r)), size - 1.0);
  EXPECT_EQ(ranks->min(static_cast<double>(r) - 0.5), -0.5);
  EXPECT_EQ(ranks->any(r == size - 1), true);
  EXPECT_EQ(ranks->any(false), false);
  ExactSum inf;
  inf.add(r == 0 ? HUGE_VAL : 1.0);
  EXPECT_EQ(ranks->sum(inf), HUGE_VAL);
}

}  // namespace
}  // namespace sqdem
