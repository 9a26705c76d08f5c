#pragma once

#include <cstdint>

#include "sqdem/scene/scene.hpp"

namespace sqdem {

/// A hash of everything the scene declares except its path and its `output` keys: a
/// checkpoint written by one scene is refused by another (world/checkpoint_file.hpp).
std::uint64_t sceneFingerprint(const Scene& scene);

}  // namespace sqdem
