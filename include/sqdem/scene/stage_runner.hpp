#pragma once
// Runs a scene's stages on its World (library code: the CLI's `sqdem run` and later bindings).
//
// planRun checks, before anything is written, what a run will do: each stage's step count (at
// least one, at most 1e12) and an explicit time step against the stable estimate (0.2 x the
// Rayleigh time of the smallest particle): above it a warning, above 5 x it an error.
//
// runStages then runs the stages from a RunProgress (the start, or a checkpoint): per stage it
// sets the walls' motion (each wall back to its declared velocity, then the stage's move_wall
// velocity or path and servo_wall), the background drag, and
// steps until the duration or a stop criterion (kinetic-energy ratio, wall pressure, porosity under a plate, checked
// every 10 steps after `stop.after`); it writes VTK frames, CSV rows (io/run_log.hpp), the
// checkpoint `<name>_after_<stage>.checkpoint` after each stage and `<name>_latest.checkpoint`
// every output.checkpoint_every_steps steps / checkpoint_every_minutes minutes and when `stop`
// becomes non-zero (then it returns Interrupted after the current step). A completed run ends
// with the particle file of its final state, `<name>_final_particles.csv` (particle_file.hpp), and
// a scene with a pressing plate with `<name>_compression.csv/.gp/.png` (compression_report.hpp). Numerical trouble
// (run_health.hpp) ends it with NumericalTrouble after the log row is written. A run resumed
// mid-stage continues bit for bit.
//
// Across MPI ranks every rank calls runStages alike (the world's communicator): rank 0 writes the
// log, the plots, the checkpoints and the particle file (gathered in id order), every rank its
// piece of each VTK frame. The decisions that read a process's own state — a stop signal, the
// checkpoint clock, the observer's — are agreed over the ranks at every step (one reduction), so
// every rank takes the same step into the same branch.

#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include "sqdem/scene/compression_report.hpp"
#include "sqdem/scene/run_checkpoint.hpp"
#include "sqdem/scene/scene.hpp"
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
  /// runner calls update() on every rank when any rank wants one.
  virtual bool wantsUpdate() { return false; }
  virtual void update(const StageSpec& /*stage*/, long /*step*/, long /*steps*/, long /*stepsThisRun*/,
                      const World& /*world*/) {}
  virtual void stageEnded(const StageSpec& /*stage*/, const std::string& /*reason*/, const World& /*world*/) {}
};

struct RunOutput {
  std::filesystem::path directory;
  std::string name;  ///< prefix of every file of the run
};

enum class RunOutcome { Completed, Interrupted, NumericalTrouble };

struct RunReport {
  RunOutcome outcome = RunOutcome::Completed;
  std::string trouble;                  ///< what went wrong (NumericalTrouble)
  long totalSteps = 0, stepsThisRun = 0;
  std::filesystem::path log, latestCheckpoint;
  std::filesystem::path finalParticles;  ///< the particle file of the final state (Completed)
  /// With a pressing plate (output.compression), Completed: what the press did (of this run's
  /// rows: a resumed run's from its checkpoint on) and its plot, when gnuplot made one.
  std::optional<CompressionSummary> compression;
  std::optional<std::filesystem::path> compressionPlot;
};

RunReport runStages(const Scene& scene, World& world, const RunPlan& plan, const RunProgress& start,
                    const RunOutput& output, RunObserver& observer, const volatile std::sig_atomic_t& stop);

}  // namespace sqdem
