#include "sqdem/scene/run_checkpoint.hpp"

#include <cmath>

#include "sqdem/scene/scene_fingerprint.hpp"
#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {

void writeRunCheckpoint(const std::filesystem::path& path, const Scene& scene, const RunProgress& progress,
                        const World& world) {
  const SceneFingerprint fingerprint = sceneFingerprint(scene);
  CheckpointWriter out;
  out.put(fingerprint.parts);
  out.put(fingerprint.stages);
  out.put(progress.stage);
  out.put(progress.stepInStage);
  out.put(progress.stageStart);
  out.put(progress.totalSteps);
  world.writeState(out);  // gathered on rank 0
  if (world.communicator().rank() == 0) writeCheckpointFile(path, {World::stateFingerprint(), fingerprint.state()}, out.bytes());
}

RunProgress readRunCheckpoint(const std::filesystem::path& path, const Scene& scene, World& world) {
  RunProgress progress;
  try {
    const CheckpointContents file = readCheckpointFile(path, World::stateFingerprint());
    CheckpointReader in(file.payload);
    const SceneFingerprint here = sceneFingerprint(scene);
    SceneFingerprint written;
    in.get(written.parts);
    in.get(written.stages);
    if (file.scene != here.state() || written.state() != file.scene) {
      const std::string keys = here.differences(written);
      throw SceneError(path.string() + ": written for another scene (" +
                       (keys.empty() ? std::string("its fingerprint differs") : keys + " differ") +
                       "): a checkpoint resumes under a scene that changes only its 'stages' and 'output'");
    }
    in.get(progress.stage);
    in.get(progress.stepInStage);
    in.get(progress.stageStart);
    in.get(progress.totalSteps);
    if (progress.stepInStage < 0 || progress.totalSteps < progress.stepInStage || !std::isfinite(progress.stageStart)) {
      throw CheckpointError("checkpoint is corrupt (run progress)");
    }
    const bool newStages = written.stages != here.stages;
    if (!newStages && progress.stage >= scene.stages.size()) {
      throw SceneError(path.string() + ": every stage of the scene is already done");
    }
    world.readState(in);
    // Other stages: a new protocol on the checkpointed state, from its first stage.
    if (newStages) progress = {0, 0, world.time(), progress.totalSteps, true};
  } catch (const CheckpointError& e) {
    const std::string what = e.what();
    throw SceneError(what.rfind(path.string(), 0) == 0 ? what : path.string() + ": " + what);
  }
  return progress;
}

}  // namespace sqdem
