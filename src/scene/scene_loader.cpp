// Scene documents (YAML, yaml-cpp): every key is checked, unknown keys are errors, and every
// message names the document (file:line for a file), the key and what is allowed. The top-level
// keys are read here, each section by its reader (scene_sections.hpp). Keys and units:
// docs/scene_reference.md.

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "scene_reader.hpp"
#include "scene_sections.hpp"
#include "sqdem/scene/scene_loader.hpp"

namespace sqdem {
namespace {

using detail::Reader;

Scene parseScene(const Reader& r, const std::string& name, const YAML::Node& root) {
  Scene scene;
  scene.path = name;
  r.allowOnly(root, "", {"seed", "domain", "gravity", "time_step", "time_step_fraction", "impact_velocity", "steps_per_collision", "skin", "detector_tolerance", "broad_phase", "reorder_every", "materials",
                         "shapes", "interactions", "walls", "particles", "insert", "stages", "output"});
  scene.seed = static_cast<std::uint64_t>(r.integer(root, "seed", "", 0.0, 1e18, 1.0));

  const YAML::Node domain = root["domain"];
  if (!domain) r.fail(root, "domain", "missing ({lo: [x,y,z], hi: [x,y,z], periodic: [x, y]})");
  r.allowOnly(domain, "domain", {"lo", "hi", "periodic"});
  scene.domain.lo = r.vector(domain, "lo", "domain");
  scene.domain.hi = r.vector(domain, "hi", "domain");
  if (!((scene.domain.hi - scene.domain.lo).minCoeff() > 0.0)) r.fail(domain, "domain", "needs hi > lo in x, y and z");
  if (const YAML::Node p = domain["periodic"]) {
    if (!p.IsSequence()) r.fail(p, "domain.periodic", "must be a list of directions from x, y, z");
    for (const auto& d : p) {
      const std::string axis = d.as<std::string>();
      if (axis != "x" && axis != "y" && axis != "z") r.fail(d, "domain.periodic", "directions are x, y, z (got '" + axis + "')");
      scene.domain.periodic[axis[0] - 'x'] = true;
    }
  }
  if (root["gravity"]) scene.gravity = r.vector(root, "gravity", "");

  if (const YAML::Node dt = root["time_step"]) {
    if (!(dt.IsScalar() && dt.as<std::string>() == "auto")) {
      scene.timeStep = r.asNumber(dt, "time_step");
      if (!(*scene.timeStep > 0.0)) r.fail(dt, "time_step", "must be > 0 (s) or 'auto'");
    }
  }
  scene.timeStepFraction = r.number(root, "time_step_fraction", "", 0.2);
  if (!(scene.timeStepFraction > 0.0 && scene.timeStepFraction <= 1.0)) r.fail(root["time_step_fraction"], "time_step_fraction", "must be in (0, 1]");
  scene.impactVelocity = r.number(root, "impact_velocity", "", 0.0);
  if (scene.impactVelocity < 0.0) r.fail(root["impact_velocity"], "impact_velocity", "must be >= 0 (m/s)");
  scene.stepsPerCollision = r.number(root, "steps_per_collision", "", 50.0);
  if (!(scene.stepsPerCollision >= 10.0)) r.fail(root["steps_per_collision"], "steps_per_collision", "must be >= 10");
  scene.skin = r.number(root, "skin", "", 0.0);
  if (scene.skin < 0.0) r.fail(root["skin"], "skin", "must be >= 0 (m)");
  if (root["detector_tolerance"]) {
    scene.detectorTolerance = r.number(root, "detector_tolerance", "", 0.0);
    if (!(scene.detectorTolerance >= 1e-14 && scene.detectorTolerance <= 1e-3)) {
      r.fail(root["detector_tolerance"], "detector_tolerance", "must be in [1e-14, 1e-3] (relative to sqrt(R_vol,A R_vol,B))");
    }
  }
  scene.broadPhase = r.choice(root, "broad_phase", "",
                              {{"auto", std::optional<BroadPhase>()}, {"cell_list", std::optional(BroadPhase::CellList)},
                               {"aabb_tree", std::optional(BroadPhase::AabbTree)}},
                              std::optional<BroadPhase>());
  scene.reorderEvery = static_cast<int>(r.integer(root, "reorder_every", "", 0.0, 1e6, 20.0));

  detail::readMaterials(r, root, scene);
  detail::readShapes(r, root, scene);
  detail::readInteractions(r, root, scene);
  detail::readWalls(r, root, scene);
  detail::readParticles(r, root, scene);
  detail::readStages(r, root, scene);
  detail::readOutput(r, root, scene);
  return scene;
}

/// yaml-cpp's exceptions of a wrong node type (a string expected) as the document's SceneError.
Scene parseChecked(const Reader& r, const std::string& name, const YAML::Node& root, bool lines) {
  try {
    return parseScene(r, name, root);
  } catch (const YAML::Exception& e) {
    throw SceneError(name + (lines ? ":" + std::to_string(e.mark.line + 1) : std::string()) + ": " + e.msg);
  }
}

}  // namespace

std::string shortNumber(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

Scene loadScene(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw SceneError(path + (std::filesystem::is_directory(path, error) ? ": is a directory, not a scene file"
                                                                        : ": cannot open the scene file"));
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw SceneError(path + ": cannot open the scene file");
  } catch (const YAML::ParserException& e) {
    throw SceneError(path + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
  }
  return parseChecked(Reader::ofFile(path), path, root, true);
}

Scene sceneFromText(const std::string& text, const SceneOrigin& origin) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError(origin.name + ": not valid YAML: " + e.msg);
  }
  return parseChecked(Reader(origin.name, origin.directory, false), origin.name, root, false);
}

}  // namespace sqdem
