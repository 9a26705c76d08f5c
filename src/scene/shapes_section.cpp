// The scene's `shapes:` (scene_sections.hpp).

#include <string>

#include "sqdem/geometry/superquadric.hpp"

#include "scene_sections.hpp"

namespace sqdem::detail {
namespace {

ShapeFamily readShape(const Reader& r, const YAML::Node& s, const std::string& name) {
  const std::string where = "shapes." + name;
  r.allowOnly(s, where, {"semi_axes", "volume_radius", "aspect_b", "aspect_c", "n1", "n2"});
  ShapeFamily f;
  f.name = name;
  f.n1 = r.number(s, "n1", where, 2.0);
  f.n2 = r.number(s, "n2", where, 2.0);
  if (!(f.n1 >= 2.0 && f.n1 <= 50.0) || !(f.n2 >= 2.0 && f.n2 <= 50.0)) {
    r.fail(s, where, "exponents n1, n2 must be in [2, 50] (convex superquadrics)");
  }
  if (s["semi_axes"]) {
    if (s["volume_radius"] || s["aspect_b"] || s["aspect_c"]) r.fail(s, where, "give either semi_axes or volume_radius + aspect_b/aspect_c");
    const Vec3 a = r.vector(s, "semi_axes", where);
    if (!(a.minCoeff() > 0.0)) r.fail(s["semi_axes"], where + ".semi_axes", "must be > 0 (m)");
    f.semiAxes = a;
    const double rv = Superquadric(a.x(), a.y(), a.z(), f.n1, f.n2).volumeEquivalentRadius();
    f.volumeRadius = {rv, rv};
    f.aspectB = {a.y() / a.x(), a.y() / a.x()};
    f.aspectC = {a.z() / a.x(), a.z() / a.x()};
    return f;
  }
  if (!s["volume_radius"]) r.fail(s, where, "needs semi_axes [a, b, c] or volume_radius (m, number or [min, max])");
  f.volumeRadius = r.range(s["volume_radius"], where + ".volume_radius");
  if (s["aspect_b"]) f.aspectB = r.range(s["aspect_b"], where + ".aspect_b");
  if (s["aspect_c"]) f.aspectC = r.range(s["aspect_c"], where + ".aspect_c");
  return f;
}

}  // namespace

void readShapes(const Reader& r, const YAML::Node& root, Scene& scene) {
  // Shapes: optional when every particle comes with its own semi-axes (particle files, explicit
  // particles); a name used elsewhere must be here.
  const YAML::Node shapes = root["shapes"];
  if (shapes && (!shapes.IsMap() || shapes.size() == 0)) r.fail(shapes, "shapes", "must be a mapping name -> shape");
  if (shapes) r.uniqueKeys(shapes, "shapes");
  for (const auto& s : shapes ? shapes : YAML::Node(YAML::NodeType::Map)) {
    const std::string name = s.first.as<std::string>();
    const YAML::Node file = s.second["file"];
    if (!file) {
      scene.shapes.push_back(readShape(r, s.second, name));
      continue;
    }
    // A shape file (e.g. shapes/*.yaml): the same keys, its path relative to the scene file.
    if (s.second.size() != 1 || !file.IsScalar()) r.fail(s.second, "shapes." + name, "give either 'file: path' alone or the shape's keys");
    const std::filesystem::path shapeFile = r.relative(file.as<std::string>());
    const std::string shapePath = shapeFile.string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(shapeFile, error)) {
      r.fail(file, "shapes." + name + ".file", "cannot open '" + shapePath + "'" +
                                                   (std::filesystem::is_directory(shapeFile, error) ? ": it is a directory" : "") +
                                                   " (paths are relative to the scene file)");
    }
    YAML::Node shape;
    try {
      shape = YAML::LoadFile(shapePath);
    } catch (const YAML::BadFile&) {
      r.fail(file, "shapes." + name + ".file", "cannot open '" + shapePath + "' (paths are relative to the scene file)");
    } catch (const YAML::ParserException& e) {
      throw SceneError(shapePath + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
    }
    scene.shapes.push_back(readShape(Reader::ofFile(shapePath), shape, name));
  }
}

}  // namespace sqdem::detail
