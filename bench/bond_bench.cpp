// What bonds cost (issue 28; numbers printed, never asserted): the benchmarks' dense periodic bed
// held still (dense_bed.hpp: each particle touching its six lattice neighbours, at rest, so both
// runs step the same state and their contacts cost the same) stepped as it is, and again with a
// parallel bond on every touching pair (World::formBonds; docs/bonds.md), at the same time step.
// Prints particle-steps per second both ways and the cost per bond and step: the time the bonded
// bed's step takes more, over its bonds. Spheres also turn once bonded (a bond fixes their
// frames: World::fitTurns), which the difference includes. (A moving bed would not do: the bonds
// hold it near rest while the free one moves, and its contacts then cost differently.) Even
// still, the n = 6 blocks touch face to face at zero overlap, where round-off leaves some pairs
// just apart and some just in contact: the free bed's detector then takes ~1.8 Newton iterations
// per call, the bonded one's ~0.9 (the bonds hold every pair at its pose), so there the bonded bed
// steps faster and the difference is not the bonds' cost; the detector's work is printed for both.
//
// usage: bench_bonds [particles per edge, default 16] [steps per sample, default 40]

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "dense_bed.hpp"
#include "median.hpp"

using namespace sqdem;

namespace {

/// Seconds per step, the median of 5 samples of `steps` steps.
double secondsPerStep(World& world, int steps) {
  for (int s = 0; s < 5; ++s) world.step();
  std::vector<double> samples;
  for (int sample = 0; sample < 5; ++sample) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) world.step();
    samples.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / steps);
  }
  return median(samples);
}

/// The detector's work per call over the world's run so far: Newton iterations, and the share of
/// warm answers confirmed without evaluating a surface (warm_skip.hpp).
void printDetectorWork(const char* what, const World& world) {
  const ContactStatistics& s = world.statistics();
  const double calls = static_cast<double>(std::max<long long>(s.detectorCalls, 1));
  std::printf("    %s: %.3f detector iterations per call, %.1f %% confirmed without evaluation, %zu contacts acting\n", what,
              static_cast<double>(s.detectorIterations) / calls, 100.0 * static_cast<double>(s.detectorConfirmations) / calls,
              world.contacts().size());
}

}  // namespace

int main(int argc, char** argv) {
  const int edge = argc > 1 ? std::atoi(argv[1]) : 16;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 40;
  std::printf("dense periodic bed held still, %d^3 = %d particles, %d steps per sample, median of 5 samples\n", edge, edge * edge * edge,
              steps);
  for (const int index : {0, 2, 3}) {
    const Case& c = denseBedCases()[index];
    for (const int threads : {1, 2}) {
      omp_set_num_threads(threads);
      World plain = denseBed(c, edge, 1, true);
      World bonded = denseBed(c, edge, 1, true);
      // Cement of the particles' own stiffness, k_n = E / (2 R) (Potyondy & Cundall 2004's E_c / (R_A + R_B)),
      // too strong to break here: every bond acts at every step.
      const double R = c.shape.volumeEquivalentRadius(), E = bonded.materials()[0].youngsModulus;
      ContactModel model = bonded.contactModel(0, 0);
      model.bond = ParallelBond{0.5, E / (2.0 * R), E / (5.0 * R), 1e3 * E, 1e3 * E};
      bonded.setContactModel(0, 0, model);
      const std::size_t bonds = bonded.formBonds(0.01);
      const double tPlain = secondsPerStep(plain, steps), tBonded = secondsPerStep(bonded, steps);
      const double n = static_cast<double>(plain.particles().size());
      std::printf("%-44s %d thread(s): %.3g particle-steps/s without bonds, %.3g with %zu bonds (%.2f per particle); "
                  "%.1f ns per bond and step (%.0f %% more per step)\n",
                  c.name, threads, n / tPlain, n / tBonded, bonds, bonds / n, 1e9 * (tBonded - tPlain) / static_cast<double>(bonds),
                  100.0 * (tBonded / tPlain - 1.0));
      printDetectorWork("without bonds", plain);
      printDetectorWork("with bonds   ", bonded);
    }
  }
}
