// The scene's `materials:` (scene_sections.hpp).

#include <regex>
#include <string>

#include "scene_sections.hpp"

namespace sqdem::detail {
namespace {

Material readMaterial(const Reader& r, const YAML::Node& m, const std::string& where) {
  r.allowOnly(m, where, {"youngs_modulus", "poisson_ratio", "density", "friction", "restitution", "yield_strength",
                        "electronic_conductivity"});
  Material out;
  out.youngsModulus = r.positive(m, "youngs_modulus", where, "Pa");
  out.poissonRatio = r.number(m, "poisson_ratio", where);
  if (!(out.poissonRatio > -1.0 && out.poissonRatio < 0.5)) r.fail(m["poisson_ratio"], where + ".poisson_ratio", "must be in (-1, 0.5)");
  out.density = r.positive(m, "density", where, "kg/m^3");
  out.friction = r.number(m, "friction", where, 0.0);
  if (out.friction < 0.0) r.fail(m["friction"], where + ".friction", "must be >= 0");
  out.restitution = r.number(m, "restitution", where, 1.0);
  if (!(out.restitution > 0.0 && out.restitution <= 1.0)) r.fail(m["restitution"], where + ".restitution", "must be in (0, 1]");
  out.yieldStrength = r.number(m, "yield_strength", where, 0.0);
  if (out.yieldStrength < 0.0) r.fail(m["yield_strength"], where + ".yield_strength", "must be > 0 (Pa)");
  return out;
}

}  // namespace

void readMaterials(const Reader& r, const YAML::Node& root, Scene& scene) {
  const YAML::Node materials = root["materials"];
  if (!materials || !materials.IsMap() || materials.size() == 0) r.fail(materials ? materials : root, "materials", "missing (a mapping name -> properties)");
  r.uniqueKeys(materials, "materials");
  for (const auto& m : materials) {
    const std::string name = m.first.as<std::string>();
    static const std::regex plain("[A-Za-z0-9_.-]+");  // names go into particle files (CSV) and messages
    if (!std::regex_match(name, plain)) r.fail(m.first, "materials." + name, "names are letters, digits, '_', '.', '-'");
    const std::string where = "materials." + name;
    NamedMaterial& material = scene.materials.emplace_back(NamedMaterial{name, readMaterial(r, m.second, where), std::nullopt});
    if (m.second["electronic_conductivity"]) material.electronicConductivity = r.positive(m.second, "electronic_conductivity", where, "S/m");
  }
}

}  // namespace sqdem::detail
