#pragma once
// A run's checkpoint: where the run stands (RunProgress) followed by the World's state, in a
// self-checking checkpoint file (world/checkpoint_file.hpp) stamped with the scene's fingerprint.

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
};

void writeRunCheckpoint(const std::filesystem::path& path, const Scene& scene, const RunProgress& progress,
                        const World& world);

/// Restores `world` (built from `scene`) and returns the progress; SceneError("<path>: ...") for
/// a corrupted, truncated, foreign or finished checkpoint. The world is unchanged on error.
RunProgress readRunCheckpoint(const std::filesystem::path& path, const Scene& scene, World& world);

}  // namespace sqdem
