// `sqdem run scene.yaml [--threads N] [--out DIR] [--resume CHECKPOINT]`: loads and validates
// the scene, builds the world, runs its stages and writes the VTK series, a CSV log and, after
// every stage, a checkpoint `<name>_after_<stage>.checkpoint` to DIR (default out/<scene name>). --resume
// restores a checkpoint of the same scene and runs the remaining stages (bit for bit what the
// uninterrupted run computes), writing under the name `<name>_from_stageK`. Progress line on a
// terminal; summary at the end.

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "sqdem/io/atomic_file.hpp"
#include "sqdem/io/scene.hpp"
#include "sqdem/io/vtk_writer.hpp"
#include "sqdem/world/build_world.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

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

bool finiteState(const ParticleStore& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !p.conjugateMomentum[i].allFinite()) return false;
  }
  return true;
}

class CsvLog {
 public:
  CsvLog(fs::path path, std::size_t walls) : path_(std::move(path)) {
    text_.precision(12);
    text_ << "time,step,stage,kinetic_energy,contacts,mean_coordination,solid_fraction,bed_height,detector_failures"
             ",stress_xx,stress_yy,stress_zz,stress_xy,stress_xz,stress_yz";
    for (std::size_t w = 0; w < walls; ++w) text_ << ",wall" << w << "_z,wall" << w << "_fx,wall" << w << "_fy,wall" << w << "_fz";
    text_ << "\n";
  }
  void row(const World& world, long step, const std::string& stage) {
    const PackingMeasures m = measurePacking(world);
    text_ << world.time() << ',' << step << ',' << stage << ',' << world.kineticEnergy() << ',' << world.contacts().size()
          << ',' << m.meanCoordination << ',' << m.solidFraction << ',' << m.bedHeight << ','
          << world.statistics().detectorFailures;
    for (const auto& [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) text_ << ',' << m.stress(i, j);
    for (const Wall& w : world.walls()) {
      text_ << ',' << w.plane.point.z() << ',' << w.force.x() << ',' << w.force.y() << ',' << w.force.z();
    }
    text_ << "\n";
  }
  void flush() const { writeFileAtomically(path_, text_.str()); }

 private:
  fs::path path_;
  std::ostringstream text_;
};

/// Checkpoint file: the number of completed stages, then the world state.
void writeCheckpoint(const fs::path& path, std::uint64_t stagesDone, const World& world) {
  std::ostringstream out(std::ios::binary);
  out.write(reinterpret_cast<const char*>(&stagesDone), sizeof stagesDone);
  world.writeState(out);
  writeFileAtomically(path, out.str());
}

std::uint64_t readCheckpoint(const fs::path& path, World& world, std::size_t stages) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path.string() + ": cannot open the checkpoint");
  std::uint64_t stagesDone = 0;
  in.read(reinterpret_cast<char*>(&stagesDone), sizeof stagesDone);
  try {
    world.readState(in);
  } catch (const std::runtime_error& e) {
    throw SceneError(path.string() + ": " + e.what());
  }
  if (stagesDone >= stages) throw SceneError(path.string() + ": every stage of the scene is already done");
  return stagesDone;
}

int runScene(const std::string& scenePath, fs::path outDir, int threads, const std::string& resume) {
  const Scene scene = loadScene(scenePath);  // everything is validated before anything runs
  World world = buildWorld(scene);
  world.setGravity(scene.gravity);
  const std::uint64_t firstStage = resume.empty() ? 0 : readCheckpoint(resume, world, scene.stages.size());
  if (threads > 0) omp_set_num_threads(threads);
  const std::string name = fs::path(scenePath).stem().string() + (firstStage ? "_from_stage" + std::to_string(firstStage) : "");
  if (outDir.empty()) outDir = fs::path("out") / fs::path(scenePath).stem();
  fs::create_directories(outDir);
  const double dt = world.timeStep();
  std::printf("sqdem run: %s: %zu particles, %zu walls, dt = %.4g s, %d thread(s), output in %s\n", scenePath.c_str(),
              world.particles().size(), world.walls().size(), dt, omp_get_max_threads(), outDir.string().c_str());
  std::fflush(stdout);  // seen at once when stdout is a pipe or a log file

  VtkSeries vtk(outDir, name, scene.output.contacts);
  CsvLog log(outDir / (name + ".csv"), world.walls().size());
  if (!firstStage) world.computeForces();  // a checkpoint carries its forces; recomputing would advance the springs
  vtk.writeFrame(world);
  log.row(world, 0, "initial");

  const bool terminal = isatty(fileno(stderr));
  const auto start = Clock::now();
  auto lastProgress = start;
  long totalSteps = 0;
  for (std::size_t stageIndex = firstStage; stageIndex < scene.stages.size(); ++stageIndex) {
    const StageSpec& stage = scene.stages[stageIndex];
    if (stage.wall) world.walls()[*stage.wall].velocity = stage.wallVelocity;
    for (Wall& w : world.walls()) w.servo.reset();
    if (stage.servoWall) world.walls()[*stage.servoWall].servo = stage.servo;
    world.setViscousDamping(stage.viscousDamping);
    const long steps = std::max(1L, std::lround(stage.duration / dt));
    const long frameEvery = scene.output.frames ? std::max(1L, steps / static_cast<long>(scene.output.frames)) : 0;
    const long logEvery = scene.output.logEvery ? static_cast<long>(scene.output.logEvery) : std::max(1L, steps / 200);
    const double stageStart = world.time();
    std::string reason = "duration reached";
    for (long s = 1; s <= steps; ++s) {
      if (!stage.wallPath.points.empty()) {  // the velocity that lands the wall on its path at the step's end
        Wall& w = world.walls()[*stage.wall];
        const double t = world.time() - stageStart;
        w.velocity = (stage.wallPath.offset(t + dt) - stage.wallPath.offset(t)) / dt * w.plane.normal;
      }
      world.step();
      ++totalSteps;
      if (s % 100 == 0 && !finiteState(world.particles())) {
        log.flush();
        std::fprintf(stderr, "\nsqdem run: numerical trouble: non-finite particle state at t = %.6g s (stage '%s'); "
                             "reduce time_step_fraction. Output up to the last frame is kept in %s\n",
                     world.time(), stage.name.c_str(), outDir.string().c_str());
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
      if (terminal && seconds(now - lastProgress) > 0.5) {
        lastProgress = now;
        const double elapsed = seconds(now - start), rate = totalSteps / elapsed;
        std::fprintf(stderr, "\r[%s] %5.1f %%  t = %.4g s  %.0f steps/s  ETA %.0f s   ", stage.name.c_str(),
                     100.0 * s / steps, world.time(), rate, (steps - s) / rate);
      }
    }
    if (terminal) std::fprintf(stderr, "\r%80s\r", "");
    log.row(world, totalSteps, stage.name);
    log.flush();
    const PackingMeasures m = measurePacking(world);
    std::printf("stage '%s': t = %.4g s, %s; solid fraction %.4f, mean coordination %.3f, E_kin %.3g J",
                stage.name.c_str(), world.time(), reason.c_str(), m.solidFraction, m.meanCoordination,
                world.kineticEnergy());
    if (scene.gravity.norm() > 0.0) std::printf(" (ratio %.3g)", kineticEnergyRatio(world, scene.gravity));
    std::printf("\n");
    if (m.betweenWallsFraction > 0.0) std::printf("  solid fraction between the walls %.4f\n", m.betweenWallsFraction);
    std::fflush(stdout);
    writeCheckpoint(outDir / (name + "_after_" + stage.name + ".checkpoint"), stageIndex + 1, world);
  }
  const double wall = seconds(Clock::now() - start);
  const WorldStatistics& st = world.statistics();
  const PackingMeasures m = measurePacking(world);
  std::printf("summary: %ld steps in %.2f s (%.3g particle-steps/s), %zu contacts, %d neighbour-list builds\n",
              totalSteps, wall, totalSteps * static_cast<double>(world.particles().size()) / wall,
              world.contacts().size(), world.neighbourList().builds());
  std::printf("detector: %lld calls, %.2f iterations per call, %lld unresolved, %lld deep overlaps\n",
              st.detectorCalls, st.detectorCalls ? static_cast<double>(st.detectorIterations) / st.detectorCalls : 0.0,
              st.detectorFailures, st.deepOverlaps);
  std::printf("final: solid fraction %.4f (bulk slab %.3g m), mean coordination %.3f (%.3f without rattlers), bed height %.4g m\n",
              m.solidFraction, m.slabHeight, m.meanCoordination, m.meanCoordinationNonRattlers, m.bedHeight);
  if (m.betweenWallsFraction > 0.0) std::printf("final: solid fraction between the walls %.4f\n", m.betweenWallsFraction);
  std::printf("ParaView: open %s and %s\n", (outDir / (name + "_particles.pvd")).string().c_str(),
              (outDir / (name + "_contacts.pvd")).string().c_str());
  return 0;
}

}  // namespace

int runCommand(const Arguments& args) {
  std::string scene;
  fs::path outDir;
  std::string resume;
  int threads = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if ((a == "--threads" || a == "--out" || a == "--resume") && i + 1 == args.size()) {
      std::fprintf(stderr, "sqdem run: '%s' needs a value\n", a.c_str());
      return 2;
    }
    if (a == "--threads") {
      const std::string v = args[++i];
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || n < 1 || n > 1024) {
        std::fprintf(stderr, "sqdem run: --threads = '%s': expected an integer in [1, 1024]\n", v.c_str());
        return 2;
      }
      threads = static_cast<int>(n);
    } else if (a == "--out") {
      outDir = args[++i];
    } else if (a == "--resume") {
      resume = args[++i];
    } else if (scene.empty() && a.rfind("--", 0) != 0) {
      scene = a;
    } else {
      std::fprintf(stderr, "sqdem run: unexpected argument '%s'\nusage: sqdem run scene.yaml [--threads N] [--out DIR] [--resume CHECKPOINT]\n", a.c_str());
      return 2;
    }
  }
  if (scene.empty()) {
    std::fprintf(stderr, "usage: sqdem run scene.yaml [--threads N] [--out DIR] [--resume CHECKPOINT]\n");
    return 2;
  }
  try {
    return runScene(scene, outDir, threads, resume);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "sqdem run: %s\n", e.what());
    return 1;
  }
}

}  // namespace sqdem::cli
