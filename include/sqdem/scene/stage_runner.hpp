#pragma once
// Runs a scene's stages on its World (library code: the CLI's `sqdem run` and the Python module).
//
// planRun checks, before anything is written, what a run will do: each stage's step count (at
// least one, at most 1e12) and an explicit time step against the stable estimate (0.2 x the
// Rayleigh time of the smallest particle): above it a warning, above 5 x it an error.
//
// A StageRunner then runs the stages from a RunProgress (the start, or a checkpoint): per stage it
// sets the walls' motion (each wall back to its declared velocity, then the stage's move_wall
// velocity or path and servo_wall), the background drag, and steps until the duration or a stop
// criterion (kinetic-energy ratio, wall pressure, porosity under a plate, checked every 10 steps
// after `stop.after`). It writes through its sink (run_sink.hpp; file_sink.hpp for the CLI's
// files): a frame at the start and output.frames per stage, a log row every output.log_every
// steps and at each stage's end, a checkpoint after each stage and the latest every
// output.checkpoint_every_steps steps / checkpoint_every_minutes minutes and when `stop` becomes
// non-zero (then it returns Interrupted after the current step, or, at a step that ends its
// stage, after the stage's end is written), the final state when the stages are done. Numerical trouble (run_health.hpp) ends it with NumericalTrouble after the log row
// is written. A run may be paused (RunLimit: after so many steps, or at a stage's end) and run on
// with the same bits as without the pause; a run resumed mid-stage continues bit for bit.
//
// Across MPI ranks every rank runs alike (the world's communicator): the decisions that read a
// process's own state — a stop signal, the checkpoint clock, the observer's — are agreed over the
// ranks at every step (one reduction), so every rank takes the same step into the same branch.

#include <chrono>
#include <csignal>
#include <optional>
#include <string>
#include <vector>

#include "sqdem/scene/run_checkpoint.hpp"
#include "sqdem/scene/run_sink.hpp"
#include "sqdem/scene/scene.hpp"
#include "sqdem/world/run_health.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

struct RunPlan {
  std::vector<long> stageSteps;       ///< steps of each stage at the world's time step
  double rayleighTime = 0.0;          ///< of the smallest particle, with reduced stiffness (s)
  std::vector<std::string> warnings;  ///< for the user, before the run
  int surfaceResolution = 0;          ///< of the particles' surfaces in the output (0: none)
};

/// Particles' surfaces are drawn by default up to this many particles (6 N^2 quads each per
/// frame: at 10^5 particles and N = 3 a frame takes 10 s and 91 MB, docs/performance.md).
inline constexpr std::size_t surfacesByDefaultUpTo = 20000;
inline constexpr int defaultSurfaceResolution = 8;

/// Throws SceneError naming the file and key when a stage or the time step is impossible.
RunPlan planRun(const Scene& scene, const World& world);

/// The kinetic_energy_ratio stop criterion: E_kin / sum(m v_s^2 / 2) with the stage's velocity
/// scale v_s, else E_kin / sum(m |g| R_vol), the energy of lifting every particle by its own
/// radius.
double kineticEnergyRatio(const World& world, const Vec3& gravity, double velocityScale);

/// What the runner tells its caller as it goes (printing is the caller's). Across ranks every
/// rank's observer is called at the same steps (what it reads of the world is reduced there).
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  /// Whether this process wants an update after the current step (its own clock, say); the
  /// runner calls update() on every rank when any rank wants one. An update may raise the run's
  /// `stop` flag: the run then ends at this step (Interrupted).
  virtual bool wantsUpdate() { return false; }
  virtual void update(const StageSpec& /*stage*/, long /*step*/, long /*steps*/, long /*stepsThisRun*/,
                      const World& /*world*/) {}
  virtual void stageEnded(const StageSpec& /*stage*/, const std::string& /*reason*/, const World& /*world*/) {}
};

enum class RunOutcome {
  Completed,        ///< every stage is done
  Paused,           ///< the RunLimit was reached: run() goes on from here
  Interrupted,      ///< `stop` was raised: the latest checkpoint is written
  NumericalTrouble  ///< RunReport::trouble says what
};

struct RunReport {
  RunOutcome outcome = RunOutcome::Completed;
  std::string trouble;  ///< what went wrong (NumericalTrouble)
  long totalSteps = 0;  ///< steps since the run began (the log's step column)
  long stepsThisRun = 0;  ///< steps taken by this runner
};

/// Where run() pauses, besides the end of the stages: after `steps` more steps, or at the end of
/// the stage `stage` (an index into Scene::stages).
struct RunLimit {
  std::optional<long> steps;
  std::optional<std::size_t> stage;
};

class StageRunner {
 public:
  /// The runner keeps references to all four; `start` is where the run stands.
  StageRunner(const Scene& scene, World& world, const RunPlan& plan, const RunProgress& start, RunSink& sink);

  /// Runs from where it stands up to the limit, the end of the stages, a stop or trouble. The
  /// first call starts the run: a fresh run computes its first forces (a checkpoint carries its
  /// own), writes its first frame and log row.
  /// std::invalid_argument for a limit at a stage that has ended.
  const RunReport& run(RunObserver& observer, const volatile std::sig_atomic_t& stop, const RunLimit& limit = {});
  /// Particle state was set between steps, giving them kineticGiven (J): the health checks'
  /// energy budget grows with it (RunHealth::stateEdited; before the run starts, the budget is
  /// taken from the state as it then is).
  void stateEdited(double kineticGiven) {
    if (health_) health_->stateEdited(kineticGiven);
  }

  const RunReport& report() const { return report_; }
  /// Where the run stands (as a checkpoint would record it).
  RunProgress progress() const { return {stage_, step_, stageStart_, report_.totalSteps}; }
  /// The stages are done (or trouble ended the run): run() does nothing more.
  bool finished() const { return stage_ >= scene_.stages.size() || report_.outcome == RunOutcome::NumericalTrouble; }

 private:
  void start();
  void enterStage();
  /// One step of the current stage and what follows it; returns why the stage ends ("" if it goes on).
  std::string stepStage(RunObserver& observer, const volatile std::sig_atomic_t& stop);
  void endStage(const std::string& reason, RunObserver& observer);

  const Scene& scene_;
  World& world_;
  const RunPlan& plan_;
  RunSink& sink_;
  RunProgress start_;
  std::optional<RunHealth> health_;  ///< from the run's first forces
  RunReport report_;
  bool started_ = false, inStage_ = false;
  bool stopAfterStage_ = false;  ///< `stop` was raised at a step that ends its stage
  std::size_t stage_ = 0;
  long step_ = 0;           ///< steps of the current stage done
  double stageStart_ = 0.0;
  std::chrono::steady_clock::time_point lastCheckpoint_;
};

}  // namespace sqdem
