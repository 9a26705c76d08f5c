// The insertion grid (src/scene/insertion_grid.hpp) against the full scan it replaces: for random
// centres and candidates, in boxes periodic along any set of directions and with 1, 2, 3 or many
// cells along each, the grid's verdict on "clear of every centre" is the scan's, and no centre is
// tested twice. Centres sit also exactly on the domain's faces and on cell boundaries.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "insertion_grid.hpp"

namespace sqdem {
namespace {

TEST(InsertionGrid, ClearOfEveryCentreExactlyWhenTheFullScanIs) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int rejected = 0, accepted = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Domain domain;
    domain.lo = Vec3(-1.0 + unit(rng), 2.0 * unit(rng), -3.0);
    const double reach = 0.05 + 0.3 * unit(rng);
    // Lengths of 2-30 reaches: from a single cell (2 reaches, +margin) to many.
    domain.hi = domain.lo + reach * Vec3(2.0 + 28.0 * unit(rng), 2.0 + 10.0 * unit(rng), 2.0 + 3.0 * unit(rng));
    for (int d = 0; d < 3; ++d) domain.periodic[d] = (trial >> d) & 1;
    const auto inDomain = [&] {
      Vec3 x;
      for (int d = 0; d < 3; ++d) {
        const double u = unit(rng);  // a tenth of the coordinates exactly on a face
        x(d) = u < 0.05 ? domain.lo(d) : u < 0.1 ? domain.hi(d) : domain.lo(d) + unit(rng) * domain.length()(d);
      }
      return domain.wrap(x);
    };
    const int count = 1 + static_cast<int>(200 * unit(rng));
    std::vector<Vec3> centres;
    std::vector<double> radii;
    detail::InsertionGrid grid(domain, reach, count);
    for (int i = 0; i < count; ++i) {
      centres.push_back(inDomain());
      radii.push_back(0.5 * reach * unit(rng));
      grid.add(static_cast<std::uint32_t>(i), centres.back());
    }
    for (int q = 0; q < 50; ++q) {
      const Vec3 x = inDomain();
      const double r = 0.5 * reach * unit(rng);
      const auto clear = [&](std::uint32_t j) { return domain.minimumImage(x - centres[j]).norm() > r + radii[j]; };
      bool scan = true;
      for (int j = 0; j < count; ++j) scan = scan && clear(j);
      std::vector<int> tested(count, 0);
      const bool viaGrid = grid.allOf(x, [&](std::uint32_t j) {
        ++tested[j];
        return clear(j);
      });
      ASSERT_EQ(viaGrid, scan) << "trial " << trial << " query " << q;
      for (int j = 0; j < count; ++j) ASSERT_LE(tested[j], 1) << "centre " << j << " tested twice";
      (scan ? accepted : rejected) += 1;
    }
  }
  // Both verdicts occur often enough for the comparison to mean something.
  EXPECT_GT(accepted, 2000);
  EXPECT_GT(rejected, 2000);
}

}  // namespace
}  // namespace sqdem
