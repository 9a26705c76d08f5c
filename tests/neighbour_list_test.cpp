// Both broad-phase searches (cell list, FCL AABB tree) return exactly the pairs of an all-pairs
// nearest-image search: bounding spheres closer than the skin (closed form), with the same
// periodic image offsets, on polydisperse sets in open, partly and fully periodic boxes; every
// pair oriented by id (the lower id is a, b seen at position[b] + shift), whatever the slots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "sqdem/world/neighbour_list.hpp"

namespace sqdem {
namespace {

struct Set {
  Domain domain;
  std::vector<Vec3> position;
  std::vector<double> radius;
  double skin;
  std::vector<std::uint32_t> id;
  ParticleCloud cloud() const { return {position, radius, id}; }
};

Set randomSet(std::array<bool, 3> periodic, Vec3 hi, int n, double rMin, double rMax, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Set s{{Vec3::Zero(), hi, periodic}, {}, {}, 0.1 * rMin};
  for (int i = 0; i < n; ++i) {
    s.position.emplace_back(u(rng) * hi.x(), u(rng) * hi.y(), u(rng) * hi.z());
    s.radius.push_back(rMin + (rMax - rMin) * std::pow(u(rng), 3.0));
  }
  s.id.resize(n);
  std::iota(s.id.begin(), s.id.end(), 0u);
  if (seed % 2 == 0) std::shuffle(s.id.begin(), s.id.end(), rng);  // slots not in id order
  return s;
}

std::vector<CandidatePair> allPairs(const Set& s) {
  std::vector<CandidatePair> pairs;
  const Vec3 L = s.domain.length();
  for (std::uint32_t i = 0; i < s.position.size(); ++i) {
    for (std::uint32_t j = i + 1; j < s.position.size(); ++j) {
      Vec3 shift = Vec3::Zero();
      for (int d = 0; d < 3; ++d) {
        if (s.domain.periodic[d]) shift(d) = -L(d) * std::round((s.position[j](d) - s.position[i](d)) / L(d));
      }
      const double reach = s.radius[i] + s.radius[j] + s.skin;
      if (((s.position[j] - s.position[i]) + shift).squaredNorm() >= reach * reach) continue;
      pairs.push_back(s.id[i] < s.id[j] ? CandidatePair{i, j, shift} : CandidatePair{j, i, Vec3(-shift)});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const CandidatePair& x, const CandidatePair& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return pairs;
}

void expectSame(const std::vector<CandidatePair>& expected, const std::vector<CandidatePair>& got, const char* what) {
  ASSERT_EQ(expected.size(), got.size()) << what;
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(expected[k].a, got[k].a) << what << " pair " << k;
    EXPECT_EQ(expected[k].b, got[k].b) << what << " pair " << k;
    EXPECT_EQ(expected[k].shift, got[k].shift) << what << " pair " << k;
  }
}

TEST(NeighbourList, BothSearchesMatchAllPairs) {
  const std::array<bool, 3> open{false, false, false}, xy{true, true, false}, all{true, true, true};
  const Set sets[] = {
      randomSet(open, Vec3(1.0, 1.0, 1.0), 800, 0.01, 0.06, 1),
      randomSet(xy, Vec3(1.0, 0.8, 1.2), 800, 0.01, 0.1, 2),   // 1:10 size spread, as the NMC bed
      randomSet(all, Vec3(1.0, 1.0, 1.0), 1000, 0.02, 0.05, 3),
      randomSet(all, Vec3(0.5, 2.0, 1.0), 300, 0.05, 0.1, 4),  // x too narrow for three cells
  };
  for (const Set& s : sets) {
    const auto expected = allPairs(s);
    ASSERT_GT(expected.size(), 100u);
    expectSame(expected, cellListPairs(s.domain, s.cloud(), s.skin), "cell list");
    expectSame(expected, aabbTreePairs(s.domain, s.cloud(), s.skin), "AABB tree");
  }
}

}  // namespace
}  // namespace sqdem
