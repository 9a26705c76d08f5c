// Broad-phase benchmark (timing harness with medians; printed, never asserted): the time to build
// the candidate list with the cell list and with FCL's dynamic AABB tree (neighbour_list.hpp) on
// the kinds of scenes sqdem runs. Positions are random in a cube (overlaps allowed: only the
// search is timed), skin 0.1 x the smallest radius. The search runs in open space (a periodic
// box's images are ghosts, more particles to it). The electrode cases are the number mix of a
// 96 : 4 wt% NMC (4700 kg/m^3) : carbon-binder (930 kg/m^3) recipe (insert.recipe) with binder
// particles 1/q the NMC's size: 17 % of the solid volume is binder, so 1 particle in
// 1 + 0.21 q^3 is NMC (q = 10: 1 in 211; q = 50: 1 in 26,000).
//
// usage: bench_broad_phase [particles, default 10000]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <numeric>
#include <random>

#include "median.hpp"
#include "sqdem/world/neighbour_list.hpp"

using namespace sqdem;

namespace {

struct SceneKind {
  const char* name;
  double rMin, rMax;      ///< bounding radii (m): uniform in radius, or bimodal
  double largeFraction;   ///< > 0: bimodal, this fraction has rMax, the rest rMin
  double solidFraction;   ///< of the cube
};

}  // namespace

/// The number fraction of NMC particles in the electrode recipe with binder 1/q their size.
double nmcNumberFraction(double q) {
  const double binder = (0.04 / 930.0) / (0.96 / 4700.0 + 0.04 / 930.0);  // the binder's share of the volume
  return 1.0 / (1.0 + binder / (1.0 - binder) * q * q * q);
}

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 10000;
  const SceneKind kinds[] = {
      {"dense, monodisperse", 1.0, 1.0, 0.0, 0.55},
      {"dense, radii 1:10 (NMC bed)", 1.0, 10.0, 0.0, 0.55},
      {"dense, bimodal 1:20, 1 % large", 1.0, 20.0, 0.01, 0.55},
      {"dilute gas, monodisperse", 1.0, 1.0, 0.0, 0.02},
      {"dilute gas, radii 1:10", 1.0, 10.0, 0.0, 0.02},
      {"electrode NMC:CBD 96:4 wt%, 1:10", 1.0, 10.0, nmcNumberFraction(10.0), 0.55},
      {"electrode NMC:CBD 96:4 wt%, 1:20", 1.0, 20.0, nmcNumberFraction(20.0), 0.55},
      {"electrode NMC:CBD 96:4 wt%, 1:50", 1.0, 50.0, nmcNumberFraction(50.0), 0.55},
  };
  std::printf("broad phase, %d particles, median of 7 builds\n", n);
  std::printf("%-36s %10s %14s %14s %8s\n", "scene", "pairs", "cell list (ms)", "AABB tree (ms)", "ratio");
  for (const SceneKind& k : kinds) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> radius(n);
    double volume = 0.0;
    for (double& r : radius) {
      r = k.largeFraction > 0.0 ? (u(rng) < k.largeFraction ? k.rMax : k.rMin) : k.rMin + (k.rMax - k.rMin) * u(rng);
      volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    }
    // A cube holding the particles at solidFraction.
    const double side = std::cbrt(volume / k.solidFraction);
    std::vector<Vec3> position(n);
    for (Vec3& x : position) x = Vec3(u(rng) * side, u(rng) * side, u(rng) * side);
    const double skin = 0.1 * k.rMin;
    std::vector<std::uint32_t> id(n);
    std::iota(id.begin(), id.end(), 0u);
    const ParticleCloud cloud{position, radius, id};
    std::vector<double> cell, tree;
    std::size_t pairs = 0;
    for (int sample = 0; sample < 7; ++sample) {
      auto t0 = std::chrono::steady_clock::now();
      pairs = cellListPairs(cloud, skin).size();
      auto t1 = std::chrono::steady_clock::now();
      aabbTreePairs(cloud, skin);
      auto t2 = std::chrono::steady_clock::now();
      cell.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      tree.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    }
    std::printf("%-36s %10zu %14.2f %14.2f %7.2fx\n", k.name, pairs, median(cell), median(tree),
                median(tree) / median(cell));
  }
  return 0;
}
