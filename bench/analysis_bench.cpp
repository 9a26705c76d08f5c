// The electrode analysis' cost (issue 29; docs/electrode_analysis.md, "Cost"): time and peak
// memory of the electronic network of a dense bed (the benchmarks' lattice of 1:0.8:0.6
// ellipsoids in elliptic Hertz contact, ~6 contacts each: dense_bed.hpp) and of the pore
// diffusion on its voxel image. One case per process, so that the peak memory is the case's:
//
//   bench_analysis network N     N ~ particles (a cube of round(N^(1/3)) per edge)
//   bench_analysis pores V       V^3 voxels (near enough: the box is 44 x 44.8 x 44.4 mm) of a
//                                22 x 28 x 37 bed, the diffusion along z
//
// prints the phases' wall times (s) and the process's peak resident memory (MiB). Numbers, not
// asserted.

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "dense_bed.hpp"
#include "sqdem/analysis/conductor_network.hpp"
#include "sqdem/analysis/electronic_network.hpp"
#include "sqdem/analysis/pore_diffusion.hpp"
#include "sqdem/analysis/voxel_image.hpp"

namespace {

using namespace sqdem;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double peakMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

/// The lattice with `cells` particles along x, y, z.
World bed(const Eigen::Vector3i& cells) {
  const Case& ellipsoids = denseBedCases()[0];
  World world = denseBed(ellipsoids, cells, 7, false);
  world.computeForces();
  return world;
}

int network(double particles) {
  const int edge = static_cast<int>(std::lround(std::cbrt(particles)));
  auto t = Clock::now();
  const World world = bed(Eigen::Vector3i(edge, edge, edge));
  const double build = since(t);
  t = Clock::now();
  const ConductorNetwork net = electronicNetwork(world, world.contactEllipses(), std::vector<double>{1.0}, world.domain().lo.z(), world.domain().hi.z());
  const double assemble = since(t);
  std::printf("network: %zu particles, %zu contacts; bed built and its contacts computed %.2f s; network assembled %.3f s\n",
              net.nodes, net.links.size(), build, assemble);
  for (int axis = 0; axis < 3; ++axis) {
    t = Clock::now();
    const NetworkConduction c = solveConduction(net, axis);
    std::printf("  along %c: %.3f s, %ld CG iterations, sigma_eff / sigma %.5g\n", "xyz"[axis], since(t), c.iterations, c.conductivity);
  }
  std::printf("  peak memory %.0f MiB\n", peakMiB());
  return 0;
}

int pores(int voxels) {
  const World world = bed(Eigen::Vector3i(22, 28, 37));  // a near cube: 44 x 44.8 x 44.4 mm
  const ParticleStore& p = world.particles();
  std::vector<PlacedShape> placed(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) placed[i] = {&world.shapes()[p.shape[i]], p.position[i], p.orientation[i]};
  auto t = Clock::now();
  const VoxelImage image = voxelise(placed, world.domain().lo, world.domain().hi, {true, true, false}, voxels);
  const double voxelising = since(t);
  t = Clock::now();
  const PoreDiffusion z = solvePoreDiffusion(image, 2, true);
  std::printf("pores: %d x %d x %d voxels (%zu particles), porosity %.4f; voxelised %.2f s; diffusion along z %.2f s, "
              "%ld CG iterations, tau %.4f; peak memory %.0f MiB\n",
              image.size[0], image.size[1], image.size[2], p.size(), z.porosity, voxelising, since(t), z.iterations,
              z.tortuosityFactor, peakMiB());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string what = argc == 3 ? argv[1] : "";
  if (what == "network") return network(std::stod(argv[2]));
  if (what == "pores") return pores(std::stoi(argv[2]));
  std::fprintf(stderr, "usage: bench_analysis network N | pores V\n");
  return 2;
}
