#include "sqdem/scene/run_checkpoint.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "sqdem/scene/scene_fingerprint.hpp"
#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {

void writeRunCheckpoint(const std::filesystem::path& path, const Scene& scene, const RunProgress& progress,
                        const World& world) {
  const SceneFingerprint fingerprint = sceneFingerprint(scene);
  CheckpointWriter out;
  out.put(fingerprint.parts);
  out.putVector(fingerprint.stages);
  out.put(progress.stage);
  out.put(progress.stepInStage);
  out.put(progress.stageStart);
  out.put(progress.totalSteps);
  world.writeState(out);  // gathered on rank 0
  if (world.communicator().rank() == 0) writeCheckpointFile(path, {World::stateFingerprint(), fingerprint.state()}, out.bytes());
}

RunProgress readRunCheckpoint(const std::filesystem::path& path, const Scene& scene, World& world) {
  const auto refuse = [&](const std::string& what) { return SceneError(path.string() + ": " + what); };
  // Every rank reads the file; they agree before the world's collective restore.
  std::optional<CheckpointContents> file;
  std::string unreadable;
  try {
    file = readCheckpointFile(path, World::stateFingerprint());
  } catch (const CheckpointError& e) {
    unreadable = e.what();
  }
  if (world.communicator().any(!unreadable.empty())) {
    throw SceneError(unreadable.empty() ? path.string() + ": not readable by every rank" : unreadable);
  }
  RunProgress progress;
  try {
    CheckpointReader in(file->payload);
    const SceneFingerprint here = sceneFingerprint(scene);
    SceneFingerprint written;
    in.get(written.parts);
    in.getVector(written.stages, ~std::uint64_t{0});
    if (file->scene != here.state() || written.state() != file->scene) {
      const std::string keys = here.differences(written);
      throw refuse("written for another scene (" + (keys.empty() ? std::string("its fingerprint differs") : keys + " differ") +
                   "): a checkpoint resumes under a scene that changes only its 'stages' and 'output'");
    }
    in.get(progress.stage);
    in.get(progress.stepInStage);
    in.get(progress.stageStart);
    in.get(progress.totalSteps);
    if (progress.stepInStage < 0 || progress.totalSteps < progress.stepInStage || !std::isfinite(progress.stageStart) ||
        progress.stage > written.stages.size()) {
      throw CheckpointError("checkpoint is corrupt (run progress)");
    }
    // The stages up to where the checkpoint stands (the one under way included): unchanged, the
    // run continues there; changed, the scene's stages are a new protocol, from the first.
    const std::size_t done = progress.stage + (progress.stepInStage > 0 ? 1 : 0);
    const bool continues = here.stages.size() >= done &&
                           std::equal(written.stages.begin(), written.stages.begin() + done, here.stages.begin());
    if (!continues && progress.stepInStage > 0) {
      throw refuse("written in the middle of stage " + std::to_string(progress.stage + 1) + ", which this scene changes: "
                   "a scene with other stages resumes a checkpoint written between stages (<name>_after_<stage>.checkpoint)");
    }
    if (continues && progress.stage >= scene.stages.size()) throw refuse("every stage of the scene is already done");
    world.readState(in);
    if (!continues) progress = {0, 0, world.time(), progress.totalSteps, true};
  } catch (const CheckpointError& e) {
    const std::string what = e.what();
    throw SceneError(what.rfind(path.string(), 0) == 0 ? what : path.string() + ": " + what);
  }
  return progress;
}

}  // namespace sqdem
