#pragma once
// What a checkpoint must share with the scene that resumes it (docs/running.md, "Checkpoints").

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sqdem/scene/scene.hpp"

namespace sqdem {

/// Hashes of a validated scene's parts, each of the values of its keys (not the path, nor the
/// `output` keys but the energy ledger, part of the world's state), and of each stage. A
/// checkpoint resumes under a scene whose parts are all the same as its writer's; the stages may
/// differ (a new protocol on the checkpointed state, run_checkpoint.hpp).
struct SceneFingerprint {
  /// The parts, by the scene keys they cover.
  static constexpr std::array<const char*, 11> partKeys = {
      "seed", "domain", "gravity", "time_step, time_step_fraction, impact_velocity, steps_per_collision",
      "skin, broad_phase, reorder_every", "materials", "shapes", "interactions", "walls", "particles, insert",
      "output.energy"};
  std::array<std::uint64_t, partKeys.size()> parts{};
  std::vector<std::uint64_t> stages;  ///< one per stage

  /// One hash of every part (a checkpoint header's scene fingerprint).
  std::uint64_t state() const;
  /// The keys of the parts that differ from `other`'s, comma-separated ("" if none).
  std::string differences(const SceneFingerprint& other) const;
};

SceneFingerprint sceneFingerprint(const Scene& scene);

}  // namespace sqdem
