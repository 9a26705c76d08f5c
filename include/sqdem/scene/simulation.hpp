#pragma once
// A scene set up to run (the CLI's `sqdem run` and the Python module's Simulation): its World
// built, the run planned (planRun), a checkpoint restored, the output directory prepared, the
// sink and the stage runner made. Under MPI every rank constructs it alike; a failure of the
// set-up on some ranks (a file one cannot read, the output directory rank 0 prepares) throws the
// same SceneError on every rank (the lowest failing rank's message: distributed/agreed.hpp).

#include <csignal>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "sqdem/distributed/communicator.hpp"
#include "sqdem/interaction/simd_path.hpp"
#include "sqdem/scene/file_sink.hpp"
#include "sqdem/scene/stage_runner.hpp"

namespace sqdem {

/// The run's default name (its files' prefix): the scene file's name less a .yaml, .yml or .json
/// extension; a scene from text, its name as given.
std::string defaultRunName(const std::string& scenePath);

/// How a scene runs.
struct RunOptions {
  int threads = 0;                ///< a step's threads (0: OpenMP's default, OMP_NUM_THREADS or every core)
  std::optional<SimdPath> simd;   ///< the kernels' code path (default: the widest this CPU runs)
  /// The output directory; none: no files at all (no frames, log, checkpoints or particle file).
  std::optional<std::filesystem::path> out;
  std::string name;               ///< the files' prefix (default: defaultRunName of Scene::path)
  bool overwrite = false;         ///< replace sqdem's files of that name in `out`
  std::optional<std::filesystem::path> resume;  ///< a checkpoint to continue from (its files: <name>_from_step<N>_*)
};

class Simulation {
 public:
  /// Throws SceneError for a scene that cannot run (planRun), a checkpoint it cannot resume, a
  /// name that cannot name files, or an output directory it cannot prepare.
  Simulation(Scene scene, const RunOptions& options,
             std::shared_ptr<const Communicator> ranks = std::make_shared<SerialCommunicator>());
  /// Its runner and sink refer to its scene, world and plan: it stays where it was made.
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Runs on from where it stands (StageRunner::run).
  const RunReport& run(RunObserver& observer, const volatile std::sig_atomic_t& stop, const RunLimit& limit = {}) {
    return runner_->run(observer, stop, limit);
  }

  /// Sets particle state between steps (the Python module's setters): `change` edits the owned
  /// particles; the world then drops what assumed they moved by their velocities alone and
  /// books the kinetic energy given in its energy ledger (World::particlesEdited), and the run's
  /// health checks take the energy given into their budget (StageRunner::stateEdited), so that
  /// speed given to a particle, or an overlap made by moving it, is not taken for an
  /// instability. Collective across ranks.
  void editParticles(const std::function<void(ParticleStore&)>& change);

  const Scene& scene() const { return scene_; }
  World& world() { return world_; }
  const World& world() const { return world_; }
  const RunPlan& plan() const { return plan_; }
  /// Where the run started (a fresh run's zero, or the checkpoint's place).
  const RunProgress& start() const { return start_; }
  const StageRunner& runner() const { return *runner_; }
  /// The run's files; null without an output directory.
  const FileSink* files() const { return files_.get(); }

 private:
  Scene scene_;
  World world_;
  RunPlan plan_;
  RunProgress start_;
  std::unique_ptr<FileSink> files_;
  RunSink noFiles_;
  std::unique_ptr<StageRunner> runner_;
};

}  // namespace sqdem
