#include "sqdem/scene/run_checkpoint.hpp"

#include <cmath>

#include "sqdem/scene/scene_fingerprint.hpp"
#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {
void writeRunCheckpoint(const std::filesystem::path& path, const Scene& scene, const RunProgress& progress,
                        const World& world) {
  CheckpointWriter out;
  out.put(progress.stage);
  out.put(progress.stepInStage);
  out.put(progress.stageStart);
  out.put(progress.totalSteps);
  world.writeState(out);
  writeCheckpointFile(path, {World::stateFingerprint(), sceneFingerprint(scene)}, out.bytes());
}

RunProgress readRunCheckpoint(const std::filesystem::path& path, const Scene& scene, World& world) {
  RunProgress progress;
  try {
    const std::string payload = readCheckpointFile(path, {World::stateFingerprint(), sceneFingerprint(scene)});
    CheckpointReader in(payload);
    in.get(progress.stage);
    in.get(progress.stepInStage);
    in.get(progress.stageStart);
    in.get(progress.totalSteps);
    if (progress.stepInStage < 0 || progress.totalSteps < progress.stepInStage || !std::isfinite(progress.stageStart)) {
      throw CheckpointError("checkpoint is corrupt (run progress)");
    }
    if (progress.stage >= scene.stages.size()) {
      throw SceneError(path.string() + ": every stage of the scene is already done");
    }
    world.readState(in);
  } catch (const CheckpointError& e) {
    const std::string what = e.what();
    throw SceneError(what.rfind(path.string(), 0) == 0 ? what : path.string() + ": " + what);
  }
  return progress;
}

}  // namespace sqdem
