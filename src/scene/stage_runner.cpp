#include "sqdem/scene/stage_runner.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include "sqdem/scene/build_world.hpp"
#include "sqdem/world/packing_measures.hpp"

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
  char text[512];
  if (scene.timeStep && dt > stable) {
    std::snprintf(text, sizeof text, "'time_step': %.4g s is %.3g x the stable estimate %.4g s (the automatic step: "
                  "0.2 x the Rayleigh time of the smallest particle, at most 0.2 / omega of the stiffest bond and a declared impact's collision time over "
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
  // A bond stretched beyond the skin leaves the neighbour list intact and is lost (counted); in
  // pure tension it breaks at the stretch sigma_c / k_n (parallel_bond.hpp).
  for (std::size_t k = 0; k < scene.interactions.size(); ++k) {
    const std::optional<ParallelBond>& bond = scene.interactions[k].bond;
    const double stretch = bond ? bond->tensileStrength / bond->normalStiffness : 0.0;
    if (stretch <= world.neighbourList().skin()) continue;
    std::snprintf(text, sizeof text, "%s: interactions[%zu].bond breaks in tension at a stretch sigma_c / k_n = %.3g m, beyond "
                  "the skin %.3g m: a bond stretched further leaves the neighbour list intact and is lost (the summary counts "
                  "them); raise 'skin' to %.3g m to keep every bond", scene.path.c_str(), k, stretch, world.neighbourList().skin(),
                  stretch);
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

StageRunner::StageRunner(const Scene& scene, World& world, const RunPlan& plan, const RunProgress& start, RunSink& sink)
    : scene_(scene), world_(world), plan_(plan), sink_(sink), start_(start), stage_(start.stage) {
  report_.totalSteps = start.totalSteps;
}

void StageRunner::start() {
  started_ = true;
  const bool fresh = start_.totalSteps == 0 && start_.stage == 0 && start_.stepInStage == 0;
  if (fresh) world_.computeForces();  // a checkpoint carries its forces; recomputing would advance the springs
  sink_.frame(world_);
  if (fresh) sink_.row(world_, 0, "initial");
  health_.emplace(world_);
  lastCheckpoint_ = Clock::now();
}

void StageRunner::enterStage() {
  const StageSpec& stage = scene_.stages[stage_];
  for (std::size_t w = 0; w < world_.walls().size(); ++w) world_.walls()[w].velocity = scene_.walls[w].wall.velocity;
  if (stage.wall) world_.walls()[*stage.wall].velocity = stage.wallVelocity;
  for (Wall& w : world_.walls()) w.servo.reset();
  if (stage.servoWall) world_.walls()[*stage.servoWall].servo = stage.servo;
  world_.setViscousDamping(stage.viscousDamping);
  const bool continuing = stage_ == start_.stage && start_.stepInStage > 0 && report_.stepsThisRun == 0;
  if (stage.bondGap && !continuing) world_.formBonds(*stage.bondGap);
  step_ = continuing ? start_.stepInStage : 0;
  stageStart_ = continuing ? start_.stageStart : world_.time();
  inStage_ = true;
}

std::string StageRunner::stepStage(RunObserver& observer, const volatile std::sig_atomic_t& stop) {
  const StageSpec& stage = scene_.stages[stage_];
  const long steps = plan_.stageSteps[stage_];
  const long frameEvery = scene_.output.frames ? std::max(1L, steps / static_cast<long>(scene_.output.frames)) : 0;
  const long logEvery = scene_.output.logEvery ? static_cast<long>(scene_.output.logEvery) : std::max(1L, steps / 200);
  const double dt = world_.timeStep();
  const long s = ++step_;
  if (!stage.wallPath.points.empty()) {  // the velocity that lands the wall on its path at the step's end
    Wall& w = world_.walls()[*stage.wall];
    const double t = world_.time() - stageStart_;
    w.velocity = (stage.wallPath.offset(t + dt) - stage.wallPath.offset(t)) / dt * w.get<PlaneWall>().plane.normal;
  }
  world_.step();
  ++report_.totalSteps;
  ++report_.stepsThisRun;
  report_.trouble = health_->afterStep(world_);
  if (!report_.trouble.empty()) {
    sink_.row(world_, report_.totalSteps, stage.name);
    report_.outcome = RunOutcome::NumericalTrouble;
    return "numerical trouble";
  }
  if (s % logEvery == 0) sink_.row(world_, report_.totalSteps, stage.name);
  if (frameEvery && s % frameEvery == 0) sink_.frame(world_);
  // A stop criterion ends the stage at this step; the observer is still updated at it.
  std::string ending;
  if (s % 10 == 0 && world_.time() - stageStart_ >= stage.minimumDuration) {
    if (stage.kineticEnergyRatio > 0.0 && s % 100 == 0 &&
        kineticEnergyRatio(world_, scene_.gravity, stage.velocityScale) < stage.kineticEnergyRatio) {
      ending = "kinetic energy ratio below " + std::to_string(stage.kineticEnergyRatio);
    } else {
      const double p = stage.wallPressure > 0.0 ? world_.wallPressure(stage.pressureWall) : 0.0;
      const double phi = stage.porosity > 0.0 ? measurePlate(world_, stage.pressureWall).porosity : 1.0;
      if (stage.wallPressure > 0.0 && p >= stage.wallPressure) {
        ending = measuredStop("pressure reached", p, stage.wallPressure, stage.pressureWall, " Pa");
      } else if (phi <= stage.porosity) {
        ending = measuredStop("pressed the bed to porosity", phi, stage.porosity, stage.pressureWall, "");
      }
    }
    if (!ending.empty() && (!frameEvery || s % frameEvery != 0)) sink_.frame(world_);
  }
  const bool criterion = !ending.empty();
  if (!criterion && s == steps) ending = "duration reached";
  // What each process's own state asks for, agreed over the ranks: stop, a checkpoint by the
  // clock, an update of the observer.
  const auto now = Clock::now();
  std::array<double, 3> asked{
      stop ? 1.0 : 0.0,
      sink_.keepsCheckpoints() && scene_.output.checkpointMinutes > 0.0 &&
              std::chrono::duration<double>(now - lastCheckpoint_).count() > 60.0 * scene_.output.checkpointMinutes
          ? 1.0 : 0.0,
      observer.wantsUpdate() ? 1.0 : 0.0};
  world_.communicator().max(asked);
  if (asked[2] > 0.0) {  // first: the observer may ask to stop at this step (a callback)
    observer.update(stage, s, steps, report_.stepsThisRun, world_);
    if (asked[0] == 0.0) {
      std::array<double, 1> stopped{stop ? 1.0 : 0.0};
      world_.communicator().max(stopped);
      asked[0] = stopped[0];
    }
  }
  if (asked[0] > 0.0) {
    if (!ending.empty()) {  // the stage ends at this step all the same; the run stops after it ended
      stopAfterStage_ = true;
      return ending;
    }
    sink_.row(world_, report_.totalSteps, stage.name);
    sink_.checkpoint(world_, progress(), "");
    report_.outcome = RunOutcome::Interrupted;
    return "stopped";
  }
  if (criterion) return ending;
  if ((scene_.output.checkpointSteps && report_.totalSteps % static_cast<long>(scene_.output.checkpointSteps) == 0) ||
      asked[1] > 0.0) {
    sink_.checkpoint(world_, progress(), "");
    lastCheckpoint_ = now;
  }
  return ending;
}

void StageRunner::endStage(const std::string& reason, RunObserver& observer) {
  const StageSpec& stage = scene_.stages[stage_];
  sink_.row(world_, report_.totalSteps, stage.name);
  sink_.stageEnded(world_, stage);
  observer.stageEnded(stage, reason, world_);
  ++stage_;
  step_ = 0;
  inStage_ = false;
  stageStart_ = world_.time();
  sink_.checkpoint(world_, progress(), stage.name);
}

const RunReport& StageRunner::run(RunObserver& observer, const volatile std::sig_atomic_t& stop, const RunLimit& limit) {
  if (limit.stage && *limit.stage < stage_) {
    throw std::invalid_argument("stage '" + scene_.stages[*limit.stage].name + "' has ended already (the run " +
                                (stage_ < scene_.stages.size() ? "is in stage '" + scene_.stages[stage_].name + "'"
                                                               : std::string("has done every stage")) + ")");
  }
  if (finished()) return report_;
  if (!started_) start();
  report_.outcome = RunOutcome::Paused;
  const long most = std::numeric_limits<long>::max();
  const long until = limit.steps && *limit.steps < most - report_.stepsThisRun ? report_.stepsThisRun + *limit.steps : most;
  while (stage_ < scene_.stages.size()) {
    if (!inStage_) enterStage();
    std::string reason;
    while (reason.empty()) {
      // A stage whose steps are all done (a run stopped, or a checkpoint written, at its last
      // step) ends without another step.
      if (step_ >= plan_.stageSteps[stage_]) {
        reason = "duration reached";
        break;
      }
      if (report_.stepsThisRun >= until) return report_;
      reason = stepStage(observer, stop);
    }
    if (report_.outcome != RunOutcome::Paused) return report_;  // trouble or a stop
    const std::size_t ended = stage_;
    endStage(reason, observer);
    if (std::exchange(stopAfterStage_, false) && stage_ < scene_.stages.size()) {
      sink_.checkpoint(world_, progress(), "");
      report_.outcome = RunOutcome::Interrupted;
      return report_;
    }
    if (limit.stage && *limit.stage == ended && stage_ < scene_.stages.size()) return report_;
  }
  sink_.completed(world_);
  report_.outcome = RunOutcome::Completed;
  return report_;
}

}  // namespace sqdem
