// Whole-run benchmark of the engine (a timing harness with medians; numbers are printed, never
// asserted): a dense, fully periodic bed of ~10^4 particles on a simple-cubic lattice (affinely
// stretched for ellipsoids, so each particle touches its six neighbours with a 0.5 % overlap,
// mean coordination ~6), small random tilts and velocities, run on 1 and 2 threads.
// Reports particle-steps per second, detector iterations per call and the time per step stage.
//
// usage: bench_engine [particles per edge, default 22] [steps per sample, default 40] [case 0-3]

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "dense_bed.hpp"
#include "median.hpp"
#include "sqdem/world/world.hpp"

using namespace sqdem;

int main(int argc, char** argv) {
  const int edge = argc > 1 ? std::atoi(argv[1]) : 22;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 40;
  const int only = argc > 3 ? std::atoi(argv[3]) : -1;
  std::printf("dense periodic bed, %d^3 = %d particles, %d steps per sample, median of 5 samples\n", edge,
              edge * edge * edge, steps);
  for (int index = 0; index < 4; ++index) {
    if (only >= 0 && index != only) continue;
    const Case& c = denseBedCases()[index];
    for (const int threads : {1, 2}) {
      omp_set_num_threads(threads);
      World world = denseBed(c, edge, 1);
      for (int s = 0; s < 5; ++s) world.step();  // first contacts are cold solves
      const StepTiming before = world.timing();
      const ContactStatistics statsBefore = world.statistics();
      std::vector<double> rates;
      for (int sample = 0; sample < 5; ++sample) {
        const auto t0 = std::chrono::steady_clock::now();
        for (int s = 0; s < steps; ++s) world.step();
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        rates.push_back(static_cast<double>(world.particles().size()) * steps / wall);
      }
      const StepTiming& t = world.timing();
      const double total = (t.integration - before.integration) + (t.broadPhase - before.broadPhase) +
                           (t.contacts - before.contacts) + (t.reduction - before.reduction) + (t.ghosts - before.ghosts);
      const auto share = [&](double now, double then) { return 100.0 * (now - then) / total; };
      const ContactStatistics& st = world.statistics();
      const double calls = static_cast<double>(st.detectorCalls - statsBefore.detectorCalls);
      std::size_t pairContacts = 0;
      for (const ContactView k : world.contacts()) pairContacts += k.onWall() ? 0 : 1;
      std::printf("%-44s %d thread(s): %.3g particle-steps/s | Z = %.2f | detector %.2f it/call, %.0f %% confirmed | "
                  "integration %.1f %%, broad phase %.1f %%, contacts (detection and laws) %.1f %%, reduction %.1f %%, "
                  "ghosts %.1f %%\n",
                  c.name, threads, median(rates), 2.0 * pairContacts / world.particles().size(),
                  calls > 0 ? (st.detectorIterations - statsBefore.detectorIterations) / calls : 0.0,
                  calls > 0 ? 100.0 * (st.detectorConfirmations - statsBefore.detectorConfirmations) / calls : 0.0,
                  share(t.integration, before.integration), share(t.broadPhase, before.broadPhase),
                  share(t.contacts, before.contacts), share(t.reduction, before.reduction), share(t.ghosts, before.ghosts));
    }
  }
  return 0;
}
