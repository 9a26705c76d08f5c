#pragma once
// Scene files (YAML): every key is checked before anything runs; errors name the file, line, key
// and what is allowed (SceneError).

#include <string>

#include "sqdem/scene/scene.hpp"

namespace sqdem {

/// Reads and validates a scene file; throws SceneError("file:line: 'key': message").
Scene loadScene(const std::string& path);

/// A number for a scene message: 1e+07 rather than 10000000.000000.
std::string shortNumber(double x);

}  // namespace sqdem
