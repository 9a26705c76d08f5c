// `sqdem run scene.yaml [--threads N] [--simd PATH] [--out DIR] [--overwrite] [--resume CHECKPOINT] [--progress-every S]`: the
// command around the scene layer (scene/): parses the arguments, loads and builds the scene,
// plans the run (stage lengths, time step), restores a checkpoint, prepares DIR (default
// out/<scene name>; scene/output_directory.hpp), runs the stages (scene/stage_runner.hpp) and
// prints progress (progress_printer.hpp), a line per stage, a summary. SIGINT, SIGTERM and SIGUSR1
// ask the runner to stop after the current step with a checkpoint (exit 130); numerical trouble exits 3;
// bad input 1; bad usage 2. A resumed run writes `<name>_from_step<N>_*`.
// Under mpirun (or srun) the launched processes are the ranks of one run (docs/running.md):
// every rank loads the scene and takes its sub-domain, rank 0 prints and writes the run's files
// (stage_runner.hpp); an error in the set-up (the scene, its files, the checkpoint, the output
// directory), on any rank, exits 1 everywhere with one message; one a rank meets alone while
// running ends every rank (MPI_Abort).

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>

#include "commands.hpp"
#include "progress_printer.hpp"
#include "sqdem/distributed/agreed.hpp"
#include "sqdem/distributed/mpi_communicator.hpp"
#include "sqdem/io/run_plot.hpp"
#include "sqdem/scene/scene_loader.hpp"
#include "sqdem/scene/simulation.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem::cli {
namespace {

namespace fs = std::filesystem;

volatile std::sig_atomic_t stopSignal = 0;
extern "C" void requestStop(int signal) { stopSignal = signal; }

/// Collective: its measures are reduced over the ranks; rank 0 prints (the others' stdout goes nowhere).
void printSummary(const World& world, const RunReport& report, double wall, const FileSink& files) {
  const RunOutput& output = files.output();
  const Communicator& ranks = world.communicator();
  const ContactStatistics st = world.totalStatistics();
  const PackingMeasures m = measurePacking(world);
  const auto total = [&](std::size_t count) { return ranks.sum(static_cast<long long>(count)); };
  const long long particles = total(world.particles().size()), contacts = total(world.contacts().size());
  std::printf("summary: %ld steps in %.2f s (%.3g particle-steps/s), %lld contacts, %d neighbour-list builds\n",
              report.stepsThisRun, wall, report.stepsThisRun * static_cast<double>(particles) / wall, contacts,
              world.neighbourList().builds());
  const StepTiming& t = world.timing();
  const auto share = [&](double part) { return wall > 0.0 ? 100.0 * part / wall : 0.0; };
  std::printf("time%s: contacts (detection and laws) %.1f %%, integration %.1f %%, broad phase (%s) %.1f %%, reduction %.1f %%, "
              "%s %.1f %%, other (stages, output, checks) %.1f %%; threads waiting at the step's barriers %.1f %%\n",
              ranks.size() > 1 ? " (rank 0)" : "", share(t.contacts), share(t.integration),
              world.neighbourList().search() == BroadPhase::CellList ? "cell list" : "AABB tree", share(t.broadPhase),
              share(t.reduction), ranks.size() > 1 ? "ghosts and communication" : "ghosts", share(t.ghosts),
              share(wall - t.contacts - t.integration - t.broadPhase - t.reduction - t.ghosts), share(t.barrierWait));
  if (ranks.size() > 1) {
    std::printf("ranks: %d; load imbalance (largest / mean cost, particles + candidate contacts) %.3f at the last build, "
                "%d re-balances\n", ranks.size(), world.imbalance(), world.rebalances());
  }
  std::size_t particleBytes = 0;
  ParticleStore::forEachArray(world.particles(), [&](const auto& array) { particleBytes += array.capacity() * sizeof(array[0]); });
  const long long candidates = total(world.interactions().store().size());
  const long long contactBytes = total(world.interactions().bytes()), allParticleBytes = total(particleBytes);
  std::printf("memory: %.0f B per candidate contact (%lld candidates), %.0f B per particle\n",
              candidates ? static_cast<double>(contactBytes) / candidates : 0.0, candidates,
              static_cast<double>(allParticleBytes) / std::max<long long>(particles, 1));
  std::printf("detector: %lld calls, %.2f iterations per call, %.1f %% confirmed without evaluation, %lld unresolved, "
              "%lld deep overlaps\n",
              st.detectorCalls, st.detectorCalls ? static_cast<double>(st.detectorIterations) / st.detectorCalls : 0.0,
              st.detectorCalls ? 100.0 * static_cast<double>(st.detectorConfirmations) / st.detectorCalls : 0.0,
              st.detectorFailures, st.deepOverlaps);
  if (st.expectedDeepOverlaps > 0) {
    std::printf("  deep overlaps where the scene expects them (deep_overlaps: expected): %lld contact-steps\n", st.expectedDeepOverlaps);
  }
  if (st.detectorFailures > 0) {
    std::printf("  unresolved by status:");
    for (int k = 0; k < contactStatusCount; ++k) {
      if (st.failuresByStatus[k]) std::printf(" %lld %s;", st.failuresByStatus[k], describe(static_cast<ContactStatus>(k)));
    }
    std::printf("\n");
  }
  if (st.lostAdhesions > 0 || st.lawFailures > 0) {
    std::printf("contact laws: %lld adhesive contacts lost before their law detached them (beyond the detector's "
                "reach), %lld contacts outside their law's valid parameters (no force)\n",
                st.lostAdhesions, st.lawFailures);
  }
  if (world.interactions().store().withTrueGap) {
    std::printf("true-gap law: %lld rungs solved (half-space contacts on its coarse grid), %.3g per detector call; %lld contact-steps "
                "on elliptic Hertz where a rung failed\n",
                st.trueGapRungs, st.detectorCalls ? static_cast<double>(st.trueGapRungs) / st.detectorCalls : 0.0, st.trueGapFallbacks);
  }
  if (world.interactions().store().withBonds) {
    std::printf("bonds: %zu intact, %lld broken, %lld lost (their pair left the neighbour list intact: raise 'skin')\n",
                world.bondCount(), st.bondsBroken, st.lostBonds);
  }
  std::printf("final: solid fraction %.4f (bulk slab %.3g m), mean coordination %.3f (%.3f without rattlers), bed height %.4g m\n",
              m.solidFraction, m.slabHeight, m.meanCoordination, m.meanCoordinationNonRattlers, m.bedHeight);
  if (m.betweenWallsFraction > 0.0) std::printf("final: solid fraction between the walls %.4f\n", m.betweenWallsFraction);
  std::printf("final: largest overlap %.3g of the smaller volume radius; %.1f %% of the contacts yielded\n",
              m.largestOverlapRatio, 100.0 * m.yieldedFraction);
  std::printf("ParaView: paraview --script=%s (the particles in their shapes, the walls, the contacts; or open the "
              "series %s_{particles,surfaces,contacts,walls}.pvd)\n",
              (output.directory / (output.name + "_view.py")).string().c_str(), (output.directory / output.name).string().c_str());
  std::printf("final state: %s (a particle file: insert it into a scene with insert: [{file: ...}])\n",
              files.finalParticles().string().c_str());
  if (!files.presses().empty()) {
    const std::vector<CompressionSummary>& presses = files.presses();
    for (std::size_t n = 0; n < presses.size(); ++n) {
      const CompressionSummary& c = presses[n];
      std::printf("compression%s: peak plate pressure %.4g MPa; coating thickness before %.4g um (porosity %.4f), at the peak "
                  "%.4g um (%.4f), after %.4g um (%.4f)%s; springback %.2f %%, permanent compression %.2f %%\n",
                  presses.size() > 1 ? std::string(" ").append(std::to_string(n + 1)).c_str() : "", c.peakPressure / 1e6, c.thicknessBefore * 1e6,
                  c.porosityBefore, c.thicknessAtPeak * 1e6, c.porosityAtPeak, c.thicknessAfter * 1e6, c.porosityAfter,
                  c.released ? "" : " (the plate never let go: the last gap)", 100.0 * c.springback(), 100.0 * c.permanentCompression());
    }
    if (const auto& fit = files.compaction()) {
      std::printf("compaction (Meyer et al. 2017, porosity after each press against its peak pressure): eps_min %.4f, eps_0 %.4f, "
                  "gamma_c %.4g MPa, rms residual %.2g\n",
                  fit->porosityMin, fit->porosityStart, fit->resistance / 1e6, fit->rmsResidual);
    }
    std::printf("compression curve: %s%s\n", (output.directory / (output.name + "_compression.csv")).string().c_str(),
                files.compressionPlot() ? (", plot " + files.compressionPlot()->string()).c_str() : " (no plot: gnuplot not found)");
  }
  for (const FileSink::AnalysisSummary& a : files.analyses()) {  // rank 0's
    if (!a.error.empty()) {
      std::printf("analysis after stage '%s' failed: %s\n", a.stage.c_str(), a.error.c_str());
      continue;
    }
    std::printf("analysis after stage '%s': porosity %.4f, tortuosity factor tau_z %.3g, electronic conductivity "
                "sigma_z / sigma %.3g: %s\n", a.stage.c_str(), a.porosity, a.tortuosityZ, a.conductivityRatioZ, a.json.string().c_str());
  }
  if (ranks.rank() != 0) return;
  const std::optional<fs::path> plot = plotRun(files.log());
  std::printf("run plot: %s\n", plot ? plot->string().c_str() : "none (gnuplot not found)");
}

int runScene(const std::shared_ptr<const Communicator>& communicator, const std::string& scenePath, fs::path outDir,
             int threads, std::optional<SimdPath> simd, const std::string& resume, bool overwrite, double progressEvery) {
  const Communicator& ranks = *communicator;
  const bool speaks = ranks.rank() == 0;  // rank 0 prints and writes the run's files
  Scene scene;
  agreed<SceneError>(ranks, [&] { scene = loadScene(scenePath); });  // everything is validated before anything runs
  RunOptions options;
  options.threads = threads;
  options.simd = simd;
  options.out = outDir.empty() ? fs::path("out") / defaultRunName(scenePath) : outDir;
  options.overwrite = overwrite;
  if (!resume.empty()) options.resume = resume;
  Simulation simulation(std::move(scene), options, communicator);
  const World& world = simulation.world();
  const RunPlan& plan = simulation.plan();
  const RunProgress& start = simulation.start();
  const FileSink& files = *simulation.files();
  const RunOutput& output = files.output();
  const double dt = world.timeStep();
  const long long particles = ranks.sum(static_cast<long long>(world.particles().size()));
  if (speaks) {
    for (const std::string& w : plan.warnings) std::fprintf(stderr, "sqdem run: warning: %s\n", w.c_str());
  }
  std::printf("sqdem run: %s: %lld particles, %zu walls, dt = %.4g s (%.3g x the Rayleigh time), %d rank(s) x %d "
              "thread(s), %s kernels, output in %s\n", scenePath.c_str(), particles, world.walls().size(), dt,
              dt / plan.rayleighTime, ranks.size(), world.threads(), std::string(simdPathName(world.simdPath())).c_str(),
              output.directory.string().c_str());
  if (!resume.empty()) {
    std::printf("resumed from %s at step %lld, %s '%s'\n", resume.c_str(), static_cast<long long>(start.totalSteps),
                start.newStages ? "under this scene's stages (a new protocol, every contact history kept), from stage"
                                : "stage",
                simulation.scene().stages[start.stage].name.c_str());
  }
  std::fflush(stdout);  // seen at once when stdout is a pipe or a log file

  stopSignal = 0;
  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  std::signal(SIGUSR1, requestStop);  // mpirun passes it on and, unlike SIGTERM, does not kill the ranks a second later
  ProgressPrinter printer(simulation.scene(), progressEvery, speaks);
  const RunReport& report = simulation.run(printer, stopSignal);
  printer.clearLine();
  switch (report.outcome) {  // every rank has the same; rank 0 tells it
    case RunOutcome::NumericalTrouble:
      if (speaks) std::fprintf(stderr, "sqdem run: numerical trouble at step %ld (t = %.6g s): %s.\n"
                   "  Likely cause: the time step %.4g s is %.3g x the Rayleigh time of the smallest particle "
                   "(%.4g s); the automatic step is 0.2 x it (lower time_step or time_step_fraction).\n"
                   "  The log is in %s; checkpoints written so far are in %s\n",
                   report.totalSteps, world.time(), report.trouble.c_str(), dt, dt / plan.rayleighTime,
                   plan.rayleighTime, files.log().string().c_str(), output.directory.string().c_str());
      return 3;
    case RunOutcome::Interrupted:
      if (speaks) std::fprintf(stderr, "sqdem run: %s at step %ld (t = %.6g s); log %s, checkpoint %s\n"
                   "  resume with: sqdem run %s --resume %s --out %s\n",
                   stopSignal == SIGINT ? "interrupted" : stopSignal == SIGUSR1 ? "stopped (SIGUSR1)" : "terminated",
                   report.totalSteps, world.time(),
                   files.log().string().c_str(), files.latestCheckpoint().string().c_str(), scenePath.c_str(),
                   files.latestCheckpoint().string().c_str(), output.directory.string().c_str());
      return 130;
    case RunOutcome::Paused:  // no limit was given
    case RunOutcome::Completed:
      break;
  }
  printSummary(world, report, printer.elapsed(), files);
  return 0;
}

}  // namespace

int runCommand(const Arguments& args) {
  const char* usage =
      "usage: sqdem run scene.yaml [--threads N] [--simd PATH] [--out DIR] [--overwrite] [--resume CHECKPOINT] [--progress-every S]\n";
  std::string scene;
  fs::path outDir;
  std::string resume;
  int threads = 0;
  std::optional<SimdPath> simd;
  double progressEvery = 60.0;
  bool overwrite = false;
  std::vector<std::string> given;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) == 0) {
      if (std::find(given.begin(), given.end(), a) != given.end()) {
        std::fprintf(stderr, "sqdem run: '%s' is given twice\n%s", a.c_str(), usage);
        return 2;
      }
      given.push_back(a);
    }
    if ((a == "--threads" || a == "--simd" || a == "--out" || a == "--resume" || a == "--progress-every") && i + 1 == args.size()) {
      std::fprintf(stderr, "sqdem run: '%s' needs a value\n%s", a.c_str(), usage);
      return 2;
    }
    if (a == "--threads") {
      const std::string v = args[++i];
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || n < 1 || n > mostThreads) {
        std::fprintf(stderr, "sqdem run: --threads = '%s': expected an integer in [1, %d]\n", v.c_str(), mostThreads);
        return 2;
      }
      threads = static_cast<int>(n);
    } else if (a == "--simd") {
      const std::string v = args[++i];
      try {
        simd = runnableSimdPath(v);
      } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "sqdem run: --simd = %s\n", e.what());
        return 2;
      }
    } else if (a == "--progress-every") {
      const std::string v = args[++i];
      char* end = nullptr;
      progressEvery = std::strtod(v.c_str(), &end);
      if (v.empty() || *end != '\0' || !(progressEvery >= 0.0 && progressEvery <= 1e6)) {
        std::fprintf(stderr, "sqdem run: --progress-every = '%s': expected seconds in [0, 1e6] (0: no records)\n", v.c_str());
        return 2;
      }
    } else if (a == "--out") {
      outDir = args[++i];
    } else if (a == "--resume") {
      resume = args[++i];
    } else if (a == "--overwrite") {
      overwrite = true;
    } else if (scene.empty() && a.rfind("--", 0) != 0) {
      scene = a;
    } else {
      std::fprintf(stderr, "sqdem run: unexpected argument '%s'\n%s", a.c_str(), usage);
      return 2;
    }
  }
  if (scene.empty()) {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  const std::shared_ptr<const Communicator> ranks = launchedRanks();
  if (ranks->rank() != 0 && !std::freopen("/dev/null", "w", stdout)) return 1;  // rank 0 prints for the run
  try {
    return runScene(ranks, scene, outDir, threads, simd, resume, overwrite, progressEvery);
  } catch (const SceneError& e) {  // found alike on every rank (distributed/agreed.hpp), before the run
    if (ranks->rank() == 0) std::fprintf(stderr, "sqdem run: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {  // while running (output that cannot be written): maybe on this rank alone
    std::fprintf(stderr, "sqdem run: %s\n", e.what());
    if (ranks->size() > 1) ranks->abort(1);
    return 1;
  }
}

}  // namespace sqdem::cli
