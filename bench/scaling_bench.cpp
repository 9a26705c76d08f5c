// Scaling benchmark under mpirun (a timing harness; numbers are printed, never asserted): the
// dense periodic bed of bench_engine (dense_bed.hpp) with edge^3 particles per rank, the lattice
// repeated R = fx fy fz times (the rank count's factors spread over x, y, z as evenly as they go:
// 2 ranks 2 x 1 x 1, 4 ranks 2 x 2 x 1, 8 ranks 2 x 2 x 2), so that each rank's share is the
// one-rank bed, a cube with neighbours on every side: weak scaling is the time per step at R
// ranks against one. Every rank builds
// the whole bed and keeps its sub-domain's particles (World::setCommunicator), as `sqdem run` does.
// Prints, for the timed steps: time per step (the slowest rank's), particle-steps per second, the
// ranks' shares of ghosts and communication, the halo (ghosts per rank; messages, bytes and
// reductions per step per rank, the quantities of the communication model in
// docs/performance.md) and memory (peak and final resident set, summed over the ranks).
//
// usage: mpirun -np R bench_scaling [particles per rank along an edge, default 46 (97,336)]
//                                   [timed steps, default 100] [case 0-3, default 0]

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "dense_bed.hpp"
#include "sqdem/distributed/mpi_communicator.hpp"

using namespace sqdem;

namespace {

/// A line of /proc/self/status in bytes (VmHWM: peak resident set, VmRSS: now).
double statusBytes(const std::string& key) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(key + ":", 0) == 0) return 1024.0 * std::atof(line.c_str() + key.size() + 1);  // kB
  }
  return 0.0;
}

/// The rank count's prime factors, each given to the direction with the fewest cells so far.
Eigen::Vector3i repeats(int ranks) {
  Eigen::Vector3i f(1, 1, 1);
  std::vector<int> primes;
  for (int p = 2; ranks > 1; ++p) {
    for (; ranks % p == 0; ranks /= p) primes.push_back(p);
  }
  for (auto p = primes.rbegin(); p != primes.rend(); ++p) {
    int d;
    f.minCoeff(&d);
    f(d) *= *p;
  }
  return f;
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::shared_ptr<Communicator> ranks = worldCommunicator();
  const int edge = argc > 1 ? std::atoi(argv[1]) : 46;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 100;
  const int index = argc > 3 ? std::atoi(argv[3]) : 0;
  if (edge < 2 || steps < 1 || index < 0 || index > 3) {
    if (ranks->rank() == 0) std::fprintf(stderr, "usage: bench_scaling [edge >= 2] [steps >= 1] [case 0-3]\n");
    return 2;
  }
  const Case& c = denseBedCases()[index];
  const int rankCount = ranks->size();
  const bool speaks = ranks->rank() == 0;

  auto start = std::chrono::steady_clock::now();
  const Eigen::Vector3i f = repeats(rankCount);
  World world = denseBed(c, edge * f, 1);
  const double build = ranks->max(seconds(start));
  start = std::chrono::steady_clock::now();
  world.setCommunicator(ranks);
  for (int s = 0; s < 5; ++s) world.step();  // the first contacts are cold solves
  const double setUp = ranks->max(seconds(start));

  const Communicator::Traffic before = ranks->traffic();
  const StepTiming timingBefore = world.timing();
  start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) world.step();
  const double mine = seconds(start);
  const double wall = ranks->max(mine);
  const Communicator::Traffic& after = ranks->traffic();
  const double ghostShare = (world.timing().ghosts - timingBefore.ghosts) / mine;

  const long long particles = ranks->sum(static_cast<long long>(world.particles().size()));
  const long long ghosts = ranks->sum(static_cast<long long>(world.particles().ghostCount));
  const long long contacts = ranks->sum(static_cast<long long>(world.contacts().size()));
  const double perStep = 1.0 / steps;
  const double messages = ranks->max((after.messages - before.messages) * perStep);
  const double bytes = ranks->max((after.bytes - before.bytes) * perStep);
  const double reductions = ranks->max((after.reductions - before.reductions) * perStep);
  const auto total = [&](double value) {
    ExactSum share;
    share.add(value);
    return ranks->sum(share);
  };
  const double peak = total(statusBytes("VmHWM")), now = total(statusBytes("VmRSS"));
  const double largestGhostShare = ranks->max(ghostShare);
  const double smallestGhostShare = ranks->min(ghostShare);
  if (!speaks) return 0;
  std::printf("%s: %d rank(s) (%d x %d x %d) x %d thread(s), %lld particles (%d^3 per rank), %lld contacts\n", c.name,
              rankCount, f.x(), f.y(), f.z(), omp_get_max_threads(), particles, edge, contacts);
  std::printf("  time per step %.4f s, %.3g particle-steps/s (%.3g per rank); set-up: bed %.2f s, "
              "decomposition and 5 steps %.2f s\n",
              wall / steps, particles * steps / wall, particles * steps / wall / rankCount, build, setUp);
  std::printf("  ghosts and communication %.1f-%.1f %% of a rank's time; imbalance %.3f\n", 100.0 * smallestGhostShare,
              100.0 * largestGhostShare, world.imbalance());
  std::printf("  halo per rank: %.0f ghosts, per step %.1f messages, %.0f bytes, %.1f reductions (largest rank)\n",
              static_cast<double>(ghosts) / rankCount, messages, bytes, reductions);
  std::printf("  memory (all ranks): peak %.1f MB (%.0f B per particle), at the end %.1f MB (%.0f B per particle)\n",
              peak / 1e6, peak / particles, now / 1e6, now / particles);
  return 0;
}
