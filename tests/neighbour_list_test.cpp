// The broad phase against all-pairs searches. Both searches (cell list, FCL AABB tree) return
// exactly the pairs of an open-space all-pairs search: bounding spheres closer than the skin
// (closed form), every pair oriented by id (the lower id is a), whatever the slots. With the
// periodic images as ghosts (distributed/ghosts.hpp), the neighbour list holds every pair of
// the nearest-image all-pairs search once, A owned, B at its nearest image of A, on
// polydisperse sets in open, partly and fully periodic boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "sqdem/distributed/ghosts.hpp"
#include "sqdem/world/neighbour_list.hpp"

namespace sqdem {
namespace {

struct Set {
  Domain domain;
  ParticleStore particles;
  double skin;
  double largest = 0.0;
};

Set randomSet(std::array<bool, 3> periodic, Vec3 hi, int n, double rMin, double rMax, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Set s{{Vec3::Zero(), hi, periodic}, {}, 0.1 * rMin};
  for (int i = 0; i < n; ++i) {
    const double r = rMin + (rMax - rMin) * std::pow(u(rng), 3.0);
    s.particles.add(0, 0, Vec3(u(rng) * hi.x(), u(rng) * hi.y(), u(rng) * hi.z()), Quat::Identity(), 1.0, Vec3::Ones(), r);
    s.largest = std::max(s.largest, r);
  }
  if (seed % 2 == 0) std::shuffle(s.particles.id.begin(), s.particles.id.end(), rng);  // slots not in id order
  return s;
}

bool byPair(const CandidatePair& x, const CandidatePair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; }

/// Every pair of slots closer than the skin, oriented by id, sorted: open space.
std::vector<CandidatePair> openAllPairs(const ParticleCloud& cloud, double skin) {
  std::vector<CandidatePair> pairs;
  for (std::uint32_t i = 0; i < cloud.position.size(); ++i) {
    for (std::uint32_t j = i + 1; j < cloud.position.size(); ++j) {
      const double reach = cloud.radius[i] + cloud.radius[j] + skin;
      if ((cloud.position[j] - cloud.position[i]).squaredNorm() < reach * reach) pairs.push_back(oriented(cloud, i, j));
    }
  }
  std::sort(pairs.begin(), pairs.end(), byPair);
  return pairs;
}

void expectSame(const std::vector<CandidatePair>& expected, const std::vector<CandidatePair>& got, const char* what) {
  ASSERT_EQ(expected.size(), got.size()) << what;
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(expected[k].a, got[k].a) << what << " pair " << k;
    EXPECT_EQ(expected[k].b, got[k].b) << what << " pair " << k;
  }
}

const std::array<bool, 3> open{false, false, false}, xy{true, true, false}, all{true, true, true};

TEST(NeighbourList, BothSearchesMatchAllPairsInOpenSpace) {
  for (unsigned seed : {1u, 2u}) {
    Set s = randomSet(open, Vec3(1.0, 0.8, 1.2), 1000, 0.01, 0.1, seed);  // 1:10 size spread, as the NMC bed
    const ParticleStore& p = s.particles;
    const ParticleCloud cloud{p.position, p.boundingRadius, p.id};
    const auto expected = openAllPairs(cloud, s.skin);
    ASSERT_GT(expected.size(), 100u);
    expectSame(expected, cellListPairs(cloud, s.skin), "cell list");
    expectSame(expected, aabbTreePairs(cloud, s.skin), "AABB tree");
  }
}

TEST(NeighbourList, PeriodicImagesAsGhostsGiveEveryNearestImagePairOnce) {
  const Set sets[] = {
      randomSet(open, Vec3(1.0, 1.0, 1.0), 800, 0.01, 0.06, 1),
      randomSet(xy, Vec3(1.0, 0.8, 1.2), 800, 0.01, 0.1, 2),
      randomSet(all, Vec3(1.0, 1.0, 1.0), 1000, 0.02, 0.05, 3),
      randomSet(all, Vec3(0.5, 2.0, 1.0), 300, 0.05, 0.1, 4),  // x narrow: two cells' width
  };
  for (BroadPhase search : {BroadPhase::CellList, BroadPhase::AabbTree}) {
    for (Set s : sets) {
      ParticleStore& p = s.particles;
      const std::size_t n = p.size();
      const Domain& box = s.domain;
      // The nearest-image pairs by id: (lower id, higher id) -> B's position seen from A.
      std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, Vec3>> expected;
      for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = i + 1; j < n; ++j) {
          const auto [a, b] = p.id[i] < p.id[j] ? std::pair(i, j) : std::pair(j, i);
          const Vec3 d = box.minimumImage(p.position[b] - p.position[a]);
          const double reach = p.boundingRadius[a] + p.boundingRadius[b] + s.skin;
          if (d.norm() < reach - 1e-12) expected.push_back({{p.id[a], p.id[b]}, p.position[a] + d});
        }
      }
      std::sort(expected.begin(), expected.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      ASSERT_GT(expected.size(), 100u);

      Ghosts ghosts;
      ghosts.build(p, p.position, box, 2.0 * s.largest + s.skin, {wholeBox(box)}, SerialCommunicator());
      NeighbourList list(s.skin, search);
      list.rebuild(p, p.boundingRadius);
      std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, Vec3>> found;
      for (const CandidatePair& c : list.pairs()) {
        ASSERT_LT(c.a, n) << "A is owned";
        ASSERT_EQ(p.id[c.b < n ? c.b : ghosts.localOwners()[c.b - n]], p.id[c.b]) << "a ghost carries its owner's id";
        found.push_back({{p.id[c.a], p.id[c.b]}, p.position[c.b]});
      }
      std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      // Pairs at the margin (within 1e-12 of the reach, where the two distances round apart) are
      // allowed either way: the closed form leaves them out, the list may hold them.
      std::size_t k = 0;
      for (const auto& [pair, where] : expected) {
        while (k < found.size() && found[k].first < pair) ++k;
        ASSERT_LT(k, found.size()) << "pair " << pair.first << "-" << pair.second << " missing";
        ASSERT_EQ(found[k].first, pair) << "pair " << pair.first << "-" << pair.second << " missing";
        EXPECT_LT((found[k].second - where).norm(), 1e-12) << "B not at its nearest image";
      }
      for (std::size_t m = 1; m < found.size(); ++m) ASSERT_NE(found[m - 1].first, found[m].first) << "a pair twice";
      EXPECT_LE(found.size(), expected.size() + expected.size() / 1000);
    }
  }
}

// broad_phase: auto (automaticBroadPhase): the cell list while its cells (2 r_max + skin wide)
// would hold at most 30 particles at 0.6 of the volume, the tree beyond. Equal radii: 0.6 x 2.1^3
// / (4 pi / 3) = 1.3 per cell; one radius-20 particle per 100 of radius 1: 0.6 x 40.1^3 /
// (4 pi / 3 x (8000 + 99) / 100) = 114.
TEST(NeighbourList, AutomaticBroadPhaseTakesTheTreeWhereCellsWouldBeCrowded) {
  EXPECT_EQ(automaticBroadPhase(std::vector<double>(100, 1.0), 0.1), BroadPhase::CellList);
  std::vector<double> bimodal(100, 1.0);
  bimodal[0] = 20.0;
  EXPECT_EQ(automaticBroadPhase(bimodal, 0.1), BroadPhase::AabbTree);
  // The threshold, with equal radii 1 and the skin that makes the cell 30 particles' room.
  const double side = std::cbrt(30.0 * 4.0 / 3.0 * std::numbers::pi / 0.6);
  EXPECT_EQ(automaticBroadPhase(std::vector<double>(10, 1.0), side * (1.0 - 1e-9) - 2.0), BroadPhase::CellList);
  EXPECT_EQ(automaticBroadPhase(std::vector<double>(10, 1.0), side * (1.0 + 1e-9) - 2.0), BroadPhase::AabbTree);
  EXPECT_EQ(automaticBroadPhase(std::vector<double>{}, 0.1), BroadPhase::CellList);
}

}  // namespace
}  // namespace sqdem
