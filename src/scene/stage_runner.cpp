#include "sqdem/scene/stage_runner.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "sqdem/io/run_log.hpp"
#include "sqdem/io/vtk_writer.hpp"
#include "sqdem/scene/compression_report.hpp"
#include "sqdem/scene/particle_file.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/world/packing_measures.hpp"
#include "sqdem/world/run_health.hpp"

namespace sqdem {
namespace {

using Clock = std::chrono::steady_clock;

/// Longest stage accepted (steps): beyond it a run would not end in any useful time, and the
/// step counter must stay exact.
constexpr double mostStepsPerStage = 1e12;

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
  if (!(steps <= mostStepsPerStage)) throw SceneError(where + numbers + " would take more than 1e12 steps");
  return static_cast<long>(steps);
}

/// "wall W <what> <measured><unit> (target <target><unit>)".
std::string measuredStop(const char* what, double measured, double target, std::size_t wall, const char* unit) {
  char text[160];
  std::snprintf(text, sizeof text, "wall %zu %s %.6g%s (target %.6g%s)", wall, what, measured, unit, target, unit);
  return text;
}

}  // namespace

RunPlan planRun(const Scene& scene, const World& world) {
  RunPlan plan;
  const double stable = automaticTimeStep(scene, world, 0.2), dt = world.timeStep();
  plan.rayleighTime = rayleighTime(scene, world);
  char text[320];
  if (scene.timeStep && dt > stable) {
    std::snprintf(text, sizeof text, "'time_step': %.4g s is %.3g x the stable estimate %.4g s (the automatic step: "
                  "0.2 x the Rayleigh time of the smallest particle, at most a declared impact's collision time over "
                  "steps_per_collision)", dt, dt / stable, stable);
    if (dt > 5.0 * stable) throw SceneError(scene.path + ": " + text + "; at most 5 x is accepted");
    plan.warnings.push_back(std::string(text) + "; the run may be unstable");
  }
  for (std::size_t k = 0; k < scene.stages.size(); ++k) plan.stageSteps.push_back(stageSteps(scene, k, dt));
  const auto n = static_cast<std::size_t>(world.communicator().sum(static_cast<long long>(world.particles().size())));
  plan.surfaceResolution = scene.output.surfaceResolution.value_or(n <= surfacesByDefaultUpTo ? defaultSurfaceResolution : 0);
  if (!scene.output.surfaceResolution && plan.surfaceResolution == 0) {
    std::snprintf(text, sizeof text, "%zu particles: their surfaces are not drawn by default above %zu (set "
                  "output.surface_resolution N to draw them, 6 N^2 quads each per frame); the centres are written as always", n,
                  surfacesByDefaultUpTo);
    plan.warnings.emplace_back(text);
  }
  // A domain the particles fill to less than 1e-6 is most likely a unit slip (domain in m,
  // shapes in um): it runs (the cell grid adapts), but the user is told.
  const double fraction = solidVolume(world) / scene.domain.length().prod();
  if (fraction < 1e-6) {
    std::snprintf(text, sizeof text, "%s: the particles fill %.2g of the domain's volume; are 'domain' and 'shapes' "
                  "both in m?", scene.path.c_str(), fraction);
    plan.warnings.emplace_back(text);
  }
  return plan;
}

double kineticEnergyRatio(const World& world, const Vec3& gravity, double velocityScale) {
  const ParticleStore& p = world.particles();
  ExactSum share;
  for (std::size_t i = 0; i < p.size(); ++i) {
    share.add(velocityScale > 0.0 ? 0.5 * p.mass[i] * velocityScale * velocityScale
                                  : p.mass[i] * gravity.norm() * world.shapes()[p.shape[i]].volumeEquivalentRadius());
  }
  const double scale = world.communicator().sum(share);
  return scale > 0.0 ? world.kineticEnergy() / scale : 0.0;
}

RunReport runStages(const Scene& scene, World& world, const RunPlan& plan, const RunProgress& start,
                    const RunOutput& output, RunObserver& observer, const volatile std::sig_atomic_t& stop) {
  const bool fresh = start.totalSteps == 0 && start.stage == 0 && start.stepInStage == 0;
  VtkSeries vtk(output.directory, output.name, {scene.output.contacts, plan.surfaceResolution, scene.output.vtkCompression});
  RunLog log(output.directory / (output.name + ".csv"), world, scene.output.compressionWall);
  std::optional<CompressionRecord> compression;
  if (scene.output.compressionWall) compression.emplace();
  const auto logRow = [&](long step, const std::string& stage) {
    const std::optional<PlateMeasures> plate = log.row(world, step, stage);
    if (compression) compression->add(world.time(), *plate);
  };
  RunReport report;
  report.log = log.path();
  report.latestCheckpoint = output.directory / (output.name + "_latest.checkpoint");
  if (fresh) world.computeForces();  // a checkpoint carries its forces; recomputing would advance the springs
  vtk.writeFrame(world);
  if (fresh) logRow(0, "initial");
  RunHealth health(world);

  const double dt = world.timeStep();
  auto lastCheckpoint = Clock::now();
  long& totalSteps = report.totalSteps;
  totalSteps = start.totalSteps;
  for (std::size_t stageIndex = start.stage; stageIndex < scene.stages.size(); ++stageIndex) {
    const StageSpec& stage = scene.stages[stageIndex];
    for (std::size_t w = 0; w < world.walls().size(); ++w) world.walls()[w].velocity = scene.walls[w].velocity;
    if (stage.wall) world.walls()[*stage.wall].velocity = stage.wallVelocity;
    for (Wall& w : world.walls()) w.servo.reset();
    if (stage.servoWall) world.walls()[*stage.servoWall].servo = stage.servo;
    world.setViscousDamping(stage.viscousDamping);
    const long steps = plan.stageSteps[stageIndex];
    const long frameEvery = scene.output.frames ? std::max(1L, steps / static_cast<long>(scene.output.frames)) : 0;
    const long logEvery = scene.output.logEvery ? static_cast<long>(scene.output.logEvery) : std::max(1L, steps / 200);
    const bool continuing = stageIndex == start.stage && start.stepInStage > 0;
    const double stageStart = continuing ? start.stageStart : world.time();
    std::string reason = "duration reached";
    for (long s = continuing ? start.stepInStage + 1 : 1; s <= steps; ++s) {
      if (!stage.wallPath.points.empty()) {  // the velocity that lands the wall on its path at the step's end
        Wall& w = world.walls()[*stage.wall];
        const double t = world.time() - stageStart;
        w.velocity = (stage.wallPath.offset(t + dt) - stage.wallPath.offset(t)) / dt * w.plane.normal;
      }
      world.step();
      ++totalSteps;
      ++report.stepsThisRun;
      report.trouble = health.afterStep(world);
      if (!report.trouble.empty()) {
        logRow(totalSteps, stage.name);
        report.outcome = RunOutcome::NumericalTrouble;
        return report;
      }
      if (s % logEvery == 0) logRow(totalSteps, stage.name);
      if (frameEvery && s % frameEvery == 0) vtk.writeFrame(world);
      if (s % 10 == 0 && world.time() - stageStart >= stage.minimumDuration) {
        if (stage.kineticEnergyRatio > 0.0 && s % 100 == 0 &&
            kineticEnergyRatio(world, scene.gravity, stage.velocityScale) < stage.kineticEnergyRatio) {
          reason = "kinetic energy ratio below " + std::to_string(stage.kineticEnergyRatio);
        } else {
          const double p = stage.wallPressure > 0.0 ? world.wallPressure(stage.pressureWall) : 0.0;
          const double phi = stage.porosity > 0.0 ? measurePlate(world, stage.pressureWall).porosity : 1.0;
          if (stage.wallPressure > 0.0 && p >= stage.wallPressure) {
            reason = measuredStop("pressure reached", p, stage.wallPressure, stage.pressureWall, " Pa");
          } else if (phi <= stage.porosity) {
            reason = measuredStop("pressed the bed to porosity", phi, stage.porosity, stage.pressureWall, "");
          }
        }
        if (reason != "duration reached") {
          if (!frameEvery || s % frameEvery != 0) vtk.writeFrame(world);
          break;
        }
      }
      const RunProgress here{stageIndex, s, stageStart, totalSteps};
      // What each process's own state asks for, agreed over the ranks: stop, a checkpoint by the
      // clock, an update of the observer.
      const auto now = Clock::now();
      std::array<double, 3> asked{
          stop ? 1.0 : 0.0,
          scene.output.checkpointMinutes > 0.0 &&
                  std::chrono::duration<double>(now - lastCheckpoint).count() > 60.0 * scene.output.checkpointMinutes
              ? 1.0 : 0.0,
          observer.wantsUpdate() ? 1.0 : 0.0};
      world.communicator().max(asked);
      if (asked[0] > 0.0) {
        logRow(totalSteps, stage.name);
        writeRunCheckpoint(report.latestCheckpoint, scene, here, world);
        report.outcome = RunOutcome::Interrupted;
        return report;
      }
      if ((scene.output.checkpointSteps && totalSteps % static_cast<long>(scene.output.checkpointSteps) == 0) ||
          asked[1] > 0.0) {
        writeRunCheckpoint(report.latestCheckpoint, scene, here, world);
        lastCheckpoint = now;
      }
      if (asked[2] > 0.0) observer.update(stage, s, steps, report.stepsThisRun, world);
    }
    logRow(totalSteps, stage.name);
    observer.stageEnded(stage, reason, world);
    writeRunCheckpoint(output.directory / (output.name + "_after_" + stage.name + ".checkpoint"), scene,
                       RunProgress{stageIndex + 1, 0, world.time(), totalSteps}, world);
  }
  report.finalParticles = output.directory / (output.name + "_final_particles.csv");
  writeParticleFile(report.finalParticles, world, scene.materials);
  if (compression) {
    report.compression = compression->summary();
    if (world.communicator().rank() == 0) report.compressionPlot = compression->write(output.directory, output.name);
  }
  return report;
}

}  // namespace sqdem
