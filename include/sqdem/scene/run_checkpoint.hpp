#pragma once
// A run's checkpoint: where the run stands (RunProgress) followed by the World's state, in a
// self-checking checkpoint file (archive/checkpoint_file.hpp) stamped with the scene's fingerprint
// (scene_fingerprint.hpp: its parts but the stages), the parts and the stages' own fingerprint
// first in the payload.

#include <cstdint>
#include <filesystem>

#include "sqdem/scene/scene.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

/// Where a run stands: the first record of a checkpoint's payload.
struct RunProgress {
  std::uint64_t stage = 0;       ///< the stage under way, or the next to start
  std::int64_t stepInStage = 0;  ///< its steps already done
  double stageStart = 0.0;       ///< simulated time at which it began (s)
  std::int64_t totalSteps = 0;   ///< steps since the run began (the CSV's step column)
  /// Read under a scene with other stages: the state continues under the new ones, from the
  /// first (not written: a checkpoint's progress is its own scene's).
  bool newStages = false;
};

/// Collective: the world's state gathered, rank 0 writes the file; read by every rank, which
/// keeps its share (World::readState), at any rank count.
void writeRunCheckpoint(const std::filesystem::path& path, const Scene& scene, const RunProgress& progress,
                        const World& world);

/// Restores `world` (built from `scene`) and returns the progress; SceneError("<path>: ...") for
/// a corrupted, truncated or finished checkpoint, or one written for a scene whose parts other
/// than its `stages` and `output` differ (naming them). Under a scene whose stages up to the
/// checkpoint's place are unchanged (stages appended or later ones changed) the run continues
/// there; under other stages the state, every contact history kept, runs them from the first (a
/// new protocol; the step count goes on), which a checkpoint written mid-stage refuses. Every
/// rank reads the file (collective); the world is unchanged on error.
RunProgress readRunCheckpoint(const std::filesystem::path& path, const Scene& scene, World& world);

}  // namespace sqdem
