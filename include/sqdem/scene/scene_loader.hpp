#pragma once
// Scene documents (YAML): every key is checked before anything runs; errors name the document,
// the line (for a file), the key and what is allowed (SceneError). A scene is read from a file or
// from a document built in code (a YAML or JSON text: Python's dictionaries come this way), with
// the same checks and messages.

#include <filesystem>
#include <string>

#include "sqdem/scene/scene.hpp"

namespace sqdem {

/// Reads and validates a scene file; throws SceneError("file:line: 'key': message").
Scene loadScene(const std::string& path);

/// Where a scene document built in code comes from: `name` stands for the file in messages and
/// names the scene (Scene::path), relative paths in it (shape, particle and mesh files) are
/// relative to `directory`.
struct SceneOrigin {
  std::string name = "<scene>";
  std::filesystem::path directory = ".";
};

/// Reads and validates a scene document given as YAML or JSON text; throws
/// SceneError("name: 'key': message"), with no line numbers (the text is generated).
Scene sceneFromText(const std::string& text, const SceneOrigin& origin = {});

/// A number for a scene message: 1e+07 rather than 10000000.000000.
std::string shortNumber(double x);

}  // namespace sqdem
