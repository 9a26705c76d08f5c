// `sqdem run scene.yaml [--threads N] [--out DIR] [--overwrite] [--resume CHECKPOINT]`: loads and
// validates the scene, builds the world, checks its time step and stage lengths, runs its stages
// and writes the VTK series, a CSV log (one row streamed and flushed at a time) and checkpoints to
// DIR (default out/<scene name>):
//   <name>_after_<stage>.checkpoint  after every stage;
//   <name>_latest.checkpoint         every output.checkpoint_every_steps steps and every
//                                    output.checkpoint_every_minutes wall-clock minutes, and on
//                                    SIGINT/SIGTERM (the run then stops after the current step,
//                                    says how to resume and exits 130).
// --resume restores a checkpoint of the same scene (checkpoint_file.hpp refuses any other) and
// continues where it stopped, mid-stage if need be, bit for bit what the uninterrupted run
// computes; its files are named `<name>_from_step<N>` and its CSV step column continues at N.
// DIR must not hold files of this run's name unless --overwrite (which removes sqdem's own files
// of that name first); stale temporary files of killed runs are removed at start. The run's
// health is watched every few steps (run_health.hpp): numerical trouble stops it with the likely
// cause and exit code 3. Progress line on a terminal; summary at the end.

#include <omp.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "commands.hpp"
#include "sqdem/io/scene.hpp"
#include "sqdem/io/vtk_writer.hpp"
#include "sqdem/world/build_world.hpp"
#include "sqdem/world/checkpoint_file.hpp"
#include "sqdem/world/packing_measures.hpp"
#include "sqdem/world/run_health.hpp"

namespace sqdem::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t stopSignal = 0;
extern "C" void requestStop(int signal) { stopSignal = signal; }

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

/// Longest stage accepted (steps): beyond it a run would not end in any useful time, and the
/// step counter must stay exact.
constexpr double mostStepsPerStage = 1e12;

/// E_kin / sum(m |g| R_vol): kinetic energy relative to the energy of lifting every particle by
/// its own radius (the settle stage's stop criterion).
double kineticEnergyRatio(const World& world, const Vec3& gravity) {
  const ParticleStore& p = world.particles();
  double scale = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    scale += p.mass[i] * gravity.norm() * world.shapes()[p.shape[i]].volumeEquivalentRadius();
  }
  return scale > 0.0 ? world.kineticEnergy() / scale : 0.0;
}

/// The run's CSV log, one row written and flushed at a time (an interrupted run keeps its rows).
class CsvLog {
 public:
  CsvLog(const fs::path& path, std::size_t walls) : path_(path), out_(path, std::ios::trunc) {
    if (!out_) throw SceneError("cannot write '" + path.string() + "'");
    out_.precision(12);
    out_ << "time,step,stage,kinetic_energy,contacts,mean_coordination,solid_fraction,bed_height,detector_failures"
            ",stress_xx,stress_yy,stress_zz,stress_xy,stress_xz,stress_yz";
    for (std::size_t w = 0; w < walls; ++w) out_ << ",wall" << w << "_z,wall" << w << "_fx,wall" << w << "_fy,wall" << w << "_fz";
    out_ << std::endl;
  }
  void row(const World& world, long step, const std::string& stage) {
    const PackingMeasures m = measurePacking(world);
    out_ << world.time() << ',' << step << ',' << stage << ',' << world.kineticEnergy() << ',' << world.contacts().size()
         << ',' << m.meanCoordination << ',' << m.solidFraction << ',' << m.bedHeight << ','
         << world.statistics().detectorFailures;
    for (const auto& [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) out_ << ',' << m.stress(i, j);
    for (const Wall& w : world.walls()) {
      out_ << ',' << w.plane.point.z() << ',' << w.force.x() << ',' << w.force.y() << ',' << w.force.z();
    }
    out_ << std::endl;
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
  std::ofstream out_;
};

/// Where a run stands: the first record of a checkpoint's payload.
struct RunProgress {
  std::uint64_t stage = 0;       ///< the stage under way, or the next to start
  std::int64_t stepInStage = 0;  ///< its steps already done
  double stageStart = 0.0;       ///< simulated time at which it began (s)
  std::int64_t totalSteps = 0;   ///< steps since the run began (the CSV's step column)
};

void writeCheckpoint(const fs::path& path, std::uint64_t fingerprint, const RunProgress& progress, const World& world) {
  std::ostringstream out(std::ios::binary);
  out.write(reinterpret_cast<const char*>(&progress.stage), sizeof progress.stage);
  out.write(reinterpret_cast<const char*>(&progress.stepInStage), sizeof progress.stepInStage);
  out.write(reinterpret_cast<const char*>(&progress.stageStart), sizeof progress.stageStart);
  out.write(reinterpret_cast<const char*>(&progress.totalSteps), sizeof progress.totalSteps);
  world.writeState(out);
  writeCheckpointFile(path, fingerprint, out.str());
}

RunProgress readCheckpoint(const fs::path& path, std::uint64_t fingerprint, World& world, std::size_t stages) {
  RunProgress progress;
  try {
    const std::string payload = readCheckpointFile(path, fingerprint);
    CheckpointReader in(payload);
    in.get(progress.stage);
    in.get(progress.stepInStage);
    in.get(progress.stageStart);
    in.get(progress.totalSteps);
    world.readState(in);
    if (progress.stepInStage < 0 || progress.totalSteps < progress.stepInStage || !std::isfinite(progress.stageStart)) {
      throw CheckpointError("checkpoint is corrupt (run progress)");
    }
  } catch (const CheckpointError& e) {
    const std::string what = e.what();
    throw SceneError(what.rfind(path.string(), 0) == 0 ? what : path.string() + ": " + what);
  }
  if (progress.stage >= stages) throw SceneError(path.string() + ": every stage of the scene is already done");
  return progress;
}

/// The steps of a stage; SceneError when it is shorter than one step or absurdly long.
long stageSteps(const Scene& scene, std::size_t k, double dt) {
  const StageSpec& stage = scene.stages[k];
  const double steps = std::round(stage.duration / dt);
  const std::string where = scene.path + ": 'stages[" + std::to_string(k) + "].duration' (stage '" + stage.name + "'): ";
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "%.4g s at time step %.4g s", stage.duration, dt);
  if (!(steps >= 1.0)) {
    throw SceneError(where + numbers + " is shorter than one step: check the time step (the automatic one follows "
                     "youngs_modulus and density: is E in Pa?)");
  }
  if (!(steps <= mostStepsPerStage)) {
    throw SceneError(where + numbers + " would take more than 1e12 steps");
  }
  return static_cast<long>(steps);
}

/// An explicit time step is checked against the automatic estimate (0.2 x the Rayleigh time):
/// above it a warning, above 5 x it (the Rayleigh time itself) an error.
double checkTimeStep(const Scene& scene, const World& world) {
  const double stable = automaticTimeStep(scene, world, 0.2), dt = world.timeStep();
  if (scene.timeStep && dt > stable) {
    char text[256];
    std::snprintf(text, sizeof text, "'time_step': %.4g s is %.3g x the stable estimate %.4g s (0.2 x the Rayleigh "
                  "time of the smallest particle)", dt, dt / stable, stable);
    if (dt > 5.0 * stable) throw SceneError(scene.path + ": " + text + "; at most 5 x is accepted");
    std::fprintf(stderr, "sqdem run: warning: %s; the run may be unstable\n", text);
  }
  return stable;
}

/// A domain the particles fill to less than 1e-6 is most likely a unit slip (domain in m,
/// shapes in um): it runs (the cell grid adapts), but the user is told.
void warnIfSparse(const Scene& scene, const World& world) {
  double volume = 0.0;
  for (const std::uint32_t s : world.particles().shape) volume += world.shapes()[s].volume();
  const double fraction = volume / scene.domain.length().prod();
  if (fraction < 1e-6) {
    std::fprintf(stderr, "sqdem run: warning: %s: the particles fill %.2g of the domain's volume; are 'domain' and "
                 "'shapes' both in m?\n", scene.path.c_str(), fraction);
  }
}

/// Files sqdem writes for the output name `name` (frames, series, log, checkpoints) and their
/// temporaries.
bool ownFile(const std::string& file, const std::string& name) {
  static const std::regex kind(R"(.*\.(vtu|vtp|pvd|csv|checkpoint)(\.tmp[0-9]+)?)");
  return file.rfind(name + "_", 0) == 0 || file.rfind(name + ".", 0) == 0 ? std::regex_match(file, kind) : false;
}

/// Creates DIR; removes temporaries of writers that no longer run (`*.tmp<pid>`, atomic_file);
/// refuses a directory that holds files of this output name (a fresh run: any file) unless
/// `overwrite`, which removes sqdem's own files of that name.
void prepareOutput(const fs::path& dir, const std::string& name, bool fresh, bool overwrite) {
  std::error_code error;
  if (fs::exists(dir, error) && !fs::is_directory(dir, error)) throw SceneError(dir.string() + ": --out is not a directory");
  fs::create_directories(dir, error);
  if (error) throw SceneError(dir.string() + ": cannot create the output directory: " + error.message());
  static const std::regex temporary(R"(.*\.tmp([0-9]+))");
  std::vector<fs::path> clash;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string file = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(file, m, temporary) && entry.is_regular_file()) {
      const long pid = std::strtol(m[1].str().c_str(), nullptr, 10);
      if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
        fs::remove(entry.path(), error);
        continue;
      }
    }
    if (fresh || ownFile(file, name)) clash.push_back(entry.path());
  }
  if (clash.empty()) return;
  if (!overwrite) {
    throw SceneError(dir.string() + ": the output directory already holds " + std::to_string(clash.size()) + " file(s) (" +
                     clash.front().filename().string() + ", ...): choose another --out, or add --overwrite to remove "
                     "sqdem's files named " + name + "_* there first");
  }
  for (const fs::path& file : clash) {
    if (ownFile(file.filename().string(), name)) fs::remove(file, error);
  }
}

int runScene(const std::string& scenePath, fs::path outDir, int threads, const std::string& resume, bool overwrite) {
  const Scene scene = loadScene(scenePath);  // everything is validated before anything runs
  World world = buildWorld(scene);
  world.setGravity(scene.gravity);
  const std::uint64_t fingerprint = sceneFingerprint(scene);
  const double stableStep = checkTimeStep(scene, world);
  warnIfSparse(scene, world);
  const double dt = world.timeStep();
  std::vector<long> steps;
  for (std::size_t k = 0; k < scene.stages.size(); ++k) steps.push_back(stageSteps(scene, k, dt));
  RunProgress progress;
  if (!resume.empty()) progress = readCheckpoint(resume, fingerprint, world, scene.stages.size());
  if (world.timeStep() != dt) throw SceneError(resume + ": checkpoint time step differs from the scene's");

  if (threads > 0) omp_set_num_threads(threads);
  const std::string stem = fs::path(scenePath).stem().string();
  const std::string name = resume.empty() ? stem : stem + "_from_step" + std::to_string(progress.totalSteps);
  if (outDir.empty()) outDir = fs::path("out") / stem;
  prepareOutput(outDir, name, resume.empty(), overwrite);
  std::printf("sqdem run: %s: %zu particles, %zu walls, dt = %.4g s (%.3g x the Rayleigh time), %d thread(s), "
              "output in %s\n", scenePath.c_str(), world.particles().size(), world.walls().size(), dt,
              dt / (5.0 * stableStep), omp_get_max_threads(), outDir.string().c_str());
  if (!resume.empty()) {
    std::printf("resumed from %s at step %lld, stage '%s'\n", resume.c_str(), static_cast<long long>(progress.totalSteps),
                scene.stages[progress.stage].name.c_str());
  }
  std::fflush(stdout);  // seen at once when stdout is a pipe or a log file

  VtkSeries vtk(outDir, name, scene.output.contacts);
  CsvLog log(outDir / (name + ".csv"), world.walls().size());
  if (resume.empty()) world.computeForces();  // a checkpoint carries its forces; recomputing would advance the springs
  vtk.writeFrame(world);
  if (resume.empty()) log.row(world, 0, "initial");
  RunHealth health(world);
  const fs::path latest = outDir / (name + "_latest.checkpoint");
  stopSignal = 0;
  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);

  const bool terminal = isatty(fileno(stderr));
  const auto start = Clock::now();
  auto lastProgress = start, lastCheckpoint = start;
  long totalSteps = progress.totalSteps, stepsThisRun = 0;
  for (std::size_t stageIndex = progress.stage; stageIndex < scene.stages.size(); ++stageIndex) {
    const StageSpec& stage = scene.stages[stageIndex];
    if (stage.wall) world.walls()[*stage.wall].velocity = stage.wallVelocity;
    for (Wall& w : world.walls()) w.servo.reset();
    if (stage.servoWall) world.walls()[*stage.servoWall].servo = stage.servo;
    world.setViscousDamping(stage.viscousDamping);
    const long stageLength = steps[stageIndex];
    const long frameEvery = scene.output.frames ? std::max(1L, stageLength / static_cast<long>(scene.output.frames)) : 0;
    const long logEvery = scene.output.logEvery ? static_cast<long>(scene.output.logEvery) : std::max(1L, stageLength / 200);
    const bool continuing = stageIndex == progress.stage && progress.stepInStage > 0;
    const double stageStart = continuing ? progress.stageStart : world.time();
    std::string reason = "duration reached";
    for (long s = continuing ? progress.stepInStage + 1 : 1; s <= stageLength; ++s) {
      if (!stage.wallPath.points.empty()) {  // the velocity that lands the wall on its path at the step's end
        Wall& w = world.walls()[*stage.wall];
        const double t = world.time() - stageStart;
        w.velocity = (stage.wallPath.offset(t + dt) - stage.wallPath.offset(t)) / dt * w.plane.normal;
      }
      world.step();
      ++totalSteps;
      ++stepsThisRun;
      if (const std::string trouble = health.afterStep(world); !trouble.empty()) {
        log.row(world, totalSteps, stage.name);
        if (terminal) std::fprintf(stderr, "\n");
        std::fprintf(stderr, "sqdem run: numerical trouble at step %ld (t = %.6g s, stage '%s'): %s.\n"
                     "  Likely cause: the time step %.4g s is %.3g x the Rayleigh time of the smallest particle "
                     "(%.4g s); the automatic step is 0.2 x it (lower time_step or time_step_fraction).\n"
                     "  The log is in %s; checkpoints written so far are in %s\n",
                     totalSteps, world.time(), stage.name.c_str(), trouble.c_str(), dt, dt / (5.0 * stableStep),
                     5.0 * stableStep, log.path().string().c_str(), outDir.string().c_str());
        return 3;
      }
      if (s % logEvery == 0) log.row(world, totalSteps, stage.name);
      if (frameEvery && s % frameEvery == 0) vtk.writeFrame(world);
      if (s % 10 == 0 && world.time() - stageStart >= stage.minimumDuration) {
        if (stage.kineticEnergyRatio > 0.0 && s % 100 == 0 &&
            kineticEnergyRatio(world, scene.gravity) < stage.kineticEnergyRatio) {
          reason = "kinetic energy ratio below " + std::to_string(stage.kineticEnergyRatio);
        } else if (stage.wallPressure > 0.0 && world.wallPressure(stage.pressureWall) >= stage.wallPressure) {
          reason = "wall " + std::to_string(stage.pressureWall) + " pressure reached " + std::to_string(stage.wallPressure) + " Pa";
        }
        if (reason != "duration reached") {
          if (!frameEvery || s % frameEvery != 0) vtk.writeFrame(world);
          break;
        }
      }
      const auto now = Clock::now();
      const RunProgress here{stageIndex, s, stageStart, totalSteps};
      if (stopSignal) {
        log.row(world, totalSteps, stage.name);
        writeCheckpoint(latest, fingerprint, here, world);
        if (terminal) std::fprintf(stderr, "\n");
        std::fprintf(stderr, "sqdem run: %s at step %ld (t = %.6g s, stage '%s'); log %s, checkpoint %s\n"
                     "  resume with: sqdem run %s --resume %s --out %s\n",
                     stopSignal == SIGINT ? "interrupted" : "terminated", totalSteps, world.time(), stage.name.c_str(),
                     log.path().string().c_str(), latest.string().c_str(), scenePath.c_str(), latest.string().c_str(),
                     outDir.string().c_str());
        return 130;
      }
      if ((scene.output.checkpointSteps && totalSteps % static_cast<long>(scene.output.checkpointSteps) == 0) ||
          (scene.output.checkpointMinutes > 0.0 && seconds(now - lastCheckpoint) > 60.0 * scene.output.checkpointMinutes)) {
        writeCheckpoint(latest, fingerprint, here, world);
        lastCheckpoint = now;
      }
      if (terminal && seconds(now - lastProgress) > 0.5) {
        lastProgress = now;
        const double elapsed = seconds(now - start), rate = stepsThisRun / elapsed;
        std::fprintf(stderr, "\r[%s] %5.1f %%  t = %.4g s  %.0f steps/s  ETA %.0f s   ", stage.name.c_str(),
                     100.0 * s / stageLength, world.time(), rate, (stageLength - s) / rate);
      }
    }
    if (terminal) std::fprintf(stderr, "\r%80s\r", "");
    log.row(world, totalSteps, stage.name);
    const PackingMeasures m = measurePacking(world);
    std::printf("stage '%s': t = %.4g s, %s; solid fraction %.4f, mean coordination %.3f, E_kin %.3g J",
                stage.name.c_str(), world.time(), reason.c_str(), m.solidFraction, m.meanCoordination,
                world.kineticEnergy());
    if (scene.gravity.norm() > 0.0) std::printf(" (ratio %.3g)", kineticEnergyRatio(world, scene.gravity));
    std::printf("\n");
    if (m.betweenWallsFraction > 0.0) std::printf("  solid fraction between the walls %.4f\n", m.betweenWallsFraction);
    std::fflush(stdout);
    writeCheckpoint(outDir / (name + "_after_" + stage.name + ".checkpoint"), fingerprint,
                    RunProgress{stageIndex + 1, 0, world.time(), totalSteps}, world);
  }
  const double wall = seconds(Clock::now() - start);
  const WorldStatistics& st = world.statistics();
  const PackingMeasures m = measurePacking(world);
  std::printf("summary: %ld steps in %.2f s (%.3g particle-steps/s), %zu contacts, %d neighbour-list builds\n",
              stepsThisRun, wall, stepsThisRun * static_cast<double>(world.particles().size()) / wall,
              world.contacts().size(), world.neighbourList().builds());
  std::printf("detector: %lld calls, %.2f iterations per call, %lld unresolved, %lld deep overlaps\n",
              st.detectorCalls, st.detectorCalls ? static_cast<double>(st.detectorIterations) / st.detectorCalls : 0.0,
              st.detectorFailures, st.deepOverlaps);
  if (st.detectorFailures > 0) {
    std::printf("  unresolved by status:");
    for (int k = 0; k < contactStatusCount; ++k) {
      if (st.failuresByStatus[k]) std::printf(" %lld %s;", st.failuresByStatus[k], describe(static_cast<ContactStatus>(k)));
    }
    std::printf("\n");
  }
  std::printf("final: solid fraction %.4f (bulk slab %.3g m), mean coordination %.3f (%.3f without rattlers), bed height %.4g m\n",
              m.solidFraction, m.slabHeight, m.meanCoordination, m.meanCoordinationNonRattlers, m.bedHeight);
  if (m.betweenWallsFraction > 0.0) std::printf("final: solid fraction between the walls %.4f\n", m.betweenWallsFraction);
  std::printf("ParaView: open %s and %s\n", (outDir / (name + "_particles.pvd")).string().c_str(),
              (outDir / (name + "_contacts.pvd")).string().c_str());
  return 0;
}

}  // namespace

int runCommand(const Arguments& args) {
  const char* usage = "usage: sqdem run scene.yaml [--threads N] [--out DIR] [--overwrite] [--resume CHECKPOINT]\n";
  std::string scene;
  fs::path outDir;
  std::string resume;
  int threads = 0;
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
    if ((a == "--threads" || a == "--out" || a == "--resume") && i + 1 == args.size()) {
      std::fprintf(stderr, "sqdem run: '%s' needs a value\n%s", a.c_str(), usage);
      return 2;
    }
    if (a == "--threads") {
      const std::string v = args[++i];
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || n < 1 || n > 1024) {
        std::fprintf(stderr, "sqdem run: --threads = '%s': expected an integer in [1, 1024]\n", v.c_str());
        return 2;
      }
      threads = static_cast<int>(n);
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
  try {
    return runScene(scene, outDir, threads, resume, overwrite);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "sqdem run: %s\n", e.what());
    return 1;
  }
}

}  // namespace sqdem::cli
