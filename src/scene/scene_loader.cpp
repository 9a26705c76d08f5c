// Scene files (YAML, yaml-cpp): every key is checked, unknown keys are errors, and every message
// names file:line, the key and what is allowed. Keys and units: README.md "Scene files".

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>
#include <utility>

#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/io/stl_mesh.hpp"
#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/scene/particle_file.hpp"
#include "sqdem/scene/scene_loader.hpp"

#include "sqdem/io/plain_name.hpp"

namespace sqdem {
namespace {

/// "where.key", or "key" at the top level.
std::string keyPath(const std::string& where, const std::string& key) { return where.empty() ? key : where + "." + key; }

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& message) const {
    std::ostringstream s;
    s << file_;
    if (node.IsDefined() && node.Mark().line >= 0) s << ":" << node.Mark().line + 1;
    s << ": " << (key.empty() ? "" : "'" + key + "': ") << message;
    throw SceneError(s.str());
  }

  /// A mapping whose keys are all different (YAML parsers keep the first of two equal keys).
  void uniqueKeys(const YAML::Node& map, const std::string& where) const {
    if (!map.IsMap()) fail(map, where, "must be a mapping");
    std::vector<std::string> seen;
    for (const auto& entry : map) {
      const std::string key = entry.first.IsScalar() ? entry.first.as<std::string>() : "";
      if (std::find(seen.begin(), seen.end(), key) != seen.end()) fail(entry.first, keyPath(where, key), "given twice");
      seen.push_back(key);
    }
  }

  void allowOnly(const YAML::Node& map, const std::string& where, std::initializer_list<const char*> keys) const {
    allowOnly(map, where, std::vector<std::string_view>(keys.begin(), keys.end()));
  }
  void allowOnly(const YAML::Node& map, const std::string& where, const std::vector<std::string_view>& keys) const {
    uniqueKeys(map, where);
    for (const auto& entry : map) {
      const std::string key = entry.first.as<std::string>();
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
        fail(entry.first, keyPath(where, key), "unknown key (allowed: " + joinKeys(keys) + ")");
      }
    }
  }

  double number(const YAML::Node& map, const std::string& key, const std::string& where) const {
    const YAML::Node v = map[key];
    if (!v) fail(map, keyPath(where, key), "missing (a number is required)");
    return asNumber(v, keyPath(where, key));
  }
  double number(const YAML::Node& map, const std::string& key, const std::string& where, double fallback) const {
    return map[key] ? asNumber(map[key], keyPath(where, key)) : fallback;
  }
  double asNumber(const YAML::Node& v, const std::string& key) const {
    double x;
    if (!v.IsScalar() || !YAML::convert<double>::decode(v, x) || !std::isfinite(x)) fail(v, key, "must be a finite number");
    return x;
  }
  double positive(const YAML::Node& map, const std::string& key, const std::string& where, const char* unit) const {
    const double x = number(map, key, where);
    if (!(x > 0.0)) fail(map[key], keyPath(where, key), std::string("must be > 0 (") + unit + ")");
    return x;
  }
  /// An integer-valued number in [lo, hi]; `fallback` when the key is absent (required without).
  double integer(const YAML::Node& map, const std::string& key, const std::string& where, double lo, double hi,
                 std::optional<double> fallback = std::nullopt) const {
    const double x = fallback ? number(map, key, where, *fallback) : number(map, key, where);
    if (!(x >= lo && x <= hi) || x != std::floor(x)) {
      fail(map[key], keyPath(where, key), "must be an integer in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]");
    }
    return x;
  }
  /// The required key "wall": an index into the scene's walls.
  std::size_t wallIndex(const YAML::Node& map, const std::string& where, std::size_t walls) const {
    const double w = number(map, "wall", where);
    if (!(w >= 0 && w < static_cast<double>(walls)) || w != std::floor(w)) {
      fail(map["wall"], keyPath(where, "wall"), "must be a wall index in [0, " + std::to_string(walls) + ")");
    }
    return static_cast<std::size_t>(w);
  }
  /// The required key "wall": the index of a plane (pressures and paths along a normal).
  std::size_t plane(const YAML::Node& map, const std::string& where, const std::vector<WallSpec>& walls) const {
    const std::size_t w = wallIndex(map, where, walls.size());
    if (walls[w].shape != WallShape::Plane) {
      const char* shape = walls[w].shape == WallShape::Cylinder ? "a cylinder" : "a mesh";
      fail(map["wall"], keyPath(where, "wall"), "walls[" + std::to_string(w) + "] is " + shape + "; this needs a plane");
    }
    return w;
  }
  /// The required key "wall": a plate pressing the bed onto the floor (porosities between them):
  /// a plane facing -z, in a scene with a plane facing +z.
  std::size_t plate(const YAML::Node& map, const std::string& where, const std::vector<WallSpec>& walls) const {
    const std::size_t w = plane(map, where, walls);
    if (!(walls[w].normal.z() < -0.999)) {
      fail(map["wall"], keyPath(where, "wall"), "the pressing plate must be a plane facing -z (normal [0, 0, -1])");
    }
    if (std::ranges::none_of(walls, [](const WallSpec& s) { return s.shape == WallShape::Plane && s.normal.z() > 0.999; })) {
      fail(map["wall"], keyPath(where, "wall"), "needs a floor to press against: a plane wall facing +z");
    }
    return w;
  }
  Vec3 vector(const YAML::Node& map, const std::string& key, const std::string& where) const {
    const YAML::Node v = map[key];
    if (!v) fail(map, keyPath(where, key), "missing ([x, y, z] required)");
    if (!v.IsSequence() || v.size() != 3) fail(v, keyPath(where, key), "must be a list of three numbers [x, y, z]");
    return {asNumber(v[0], keyPath(where, key)), asNumber(v[1], keyPath(where, key)), asNumber(v[2], keyPath(where, key))};
  }
  std::array<double, 2> range(const YAML::Node& v, const std::string& key) const {
    if (v.IsScalar()) {
      const double x = asNumber(v, key);
      if (!(x > 0.0)) fail(v, key, "must be > 0");
      return {x, x};
    }
    if (!v.IsSequence() || v.size() != 2) fail(v, key, "must be a number or a range [min, max]");
    const std::array<double, 2> r{asNumber(v[0], key), asNumber(v[1], key)};
    if (!(r[0] > 0.0 && r[0] <= r[1])) fail(v, key, "needs 0 < min <= max");
    return r;
  }
  std::string text(const YAML::Node& map, const std::string& key, const std::string& where) const {
    const YAML::Node v = map[key];
    if (!v || !v.IsScalar()) fail(v ? v : map, keyPath(where, key), "missing or not a string");
    return v.as<std::string>();
  }
  bool flag(const YAML::Node& map, const std::string& key, const std::string& where, bool fallback) const {
    if (!map[key]) return fallback;
    bool b;
    if (!YAML::convert<bool>::decode(map[key], b)) fail(map[key], keyPath(where, key), "must be true or false");
    return b;
  }
  /// A named option: `fallback` when the key is absent, else one of `options` (name, value).
  template <typename E>
  E choice(const YAML::Node& map, const std::string& key, const std::string& where,
           std::initializer_list<std::pair<const char*, E>> options, E fallback) const {
    if (!map[key]) return fallback;
    const std::string name = map[key].IsScalar() ? map[key].as<std::string>() : "";
    std::string list;
    for (const auto& [option, value] : options) {
      if (name == option) return value;
      list += std::string(list.empty() ? "" : ", ") + option;
    }
    fail(map[key], keyPath(where, key), "allowed: " + list);
  }
  template <typename T>
  std::uint32_t lookup(const YAML::Node& node, const std::string& key, const std::vector<T>& items, const char* what) const {
    const std::string name = node.IsScalar() ? node.as<std::string>() : "";
    std::string list;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (items[i].name == name) return static_cast<std::uint32_t>(i);
      list += (i ? ", " : "") + items[i].name;
    }
    fail(node, key, "unknown " + std::string(what) + " '" + name + "' (defined: " + list + ")");
  }

 private:
  std::string file_;
};

/// A law's keys in a scene mapping (law_input.hpp); `pairKeys` are the interaction's own keys,
/// also allowed there. Every number read is recorded for the scene fingerprint.
class SceneLawInput final : public LawInput {
 public:
  SceneLawInput(const Reader& r, YAML::Node map, std::string where, std::vector<std::string_view> pairKeys,
                std::vector<std::pair<std::string, double>>& record)
      : r_(r), map_(std::move(map)), where_(std::move(where)), pairKeys_(std::move(pairKeys)), record_(record) {}

  bool has(std::string_view key) const override { return map_[std::string(key)].IsDefined(); }
  double number(std::string_view key) const override {
    const double x = r_.number(map_, std::string(key), where_);
    record_.emplace_back(keyPath(where_, std::string(key)), x);
    return x;
  }
  bool flag(std::string_view key) const override {
    const bool b = r_.flag(map_, std::string(key), where_, false);
    record_.emplace_back(keyPath(where_, std::string(key)), b ? 1.0 : 0.0);
    return b;
  }
  std::unique_ptr<LawInput> child(std::string_view key) const override {
    const YAML::Node node = map_[std::string(key)];
    const std::string at = keyPath(where_, std::string(key));
    if (!node.IsMap()) r_.fail(node, at, "must be a mapping");
    return std::make_unique<SceneLawInput>(r_, node, at, std::vector<std::string_view>{}, record_);
  }
  std::vector<std::string> keys() const override {
    r_.uniqueKeys(map_, where_);
    std::vector<std::string> out;
    for (const auto& entry : map_) {
      const std::string key = entry.first.as<std::string>();
      if (std::find(pairKeys_.begin(), pairKeys_.end(), key) == pairKeys_.end()) out.push_back(key);
    }
    return out;
  }
  std::string ownKeys() const override { return joinKeys(pairKeys_); }
  void raise(std::string_view key, const std::string& message) const override {
    const YAML::Node node = key.empty() ? map_ : map_[std::string(key)];
    r_.fail(node.IsDefined() ? node : map_, key.empty() ? where_ : keyPath(where_, std::string(key)), message);
  }

 private:
  const Reader& r_;
  YAML::Node map_;
  std::string where_;
  std::vector<std::string_view> pairKeys_;
  std::vector<std::pair<std::string, double>>& record_;
};

/// An entry of `particles:`: a fixed-size shape family, a material and the initial state.
ParticleSpec readParticle(const Reader& r, const YAML::Node& node, const std::string& where, const Scene& scene) {
  r.allowOnly(node, where, {"shape", "material", "centre", "quaternion", "velocity", "angular_velocity", "allow_overlap"});
  ParticleSpec p;
  p.origin = where;
  if (!node["shape"]) r.fail(node, where + ".shape", "missing");
  if (!node["material"]) r.fail(node, where + ".material", "missing");
  p.shape = r.lookup(node["shape"], where + ".shape", scene.shapes, "shape");
  const ShapeFamily& f = scene.shapes[*p.shape];
  if (f.volumeRadius[0] != f.volumeRadius[1] || f.aspectB[0] != f.aspectB[1] || f.aspectC[0] != f.aspectC[1]) {
    r.fail(node["shape"], where + ".shape", "shape '" + f.name + "' is a distribution; an explicit particle needs a shape of fixed size (semi_axes)");
  }
  p.material = r.lookup(node["material"], where + ".material", scene.materials, "material");
  p.centre = r.vector(node, "centre", where);
  if (const YAML::Node q = node["quaternion"]) {
    if (!q.IsSequence() || q.size() != 4) r.fail(q, where + ".quaternion", "must be [w, x, y, z]");
    p.orientation = Quat(r.asNumber(q[0], where + ".quaternion"), r.asNumber(q[1], where + ".quaternion"),
                         r.asNumber(q[2], where + ".quaternion"), r.asNumber(q[3], where + ".quaternion"));
    if (std::abs(p.orientation.norm() - 1.0) > 1e-6) r.fail(q, where + ".quaternion", "must be a unit quaternion [w, x, y, z]");
    p.orientation.normalize();
  }
  if (node["velocity"]) p.velocity = r.vector(node, "velocity", where);
  if (node["angular_velocity"]) p.angularVelocity = r.vector(node, "angular_velocity", where);
  p.allowOverlap = r.flag(node, "allow_overlap", where, false);
  return p;
}

Material readMaterial(const Reader& r, const YAML::Node& m, const std::string& where) {
  r.allowOnly(m, where, {"youngs_modulus", "poisson_ratio", "density", "friction", "restitution", "yield_strength"});
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

/// A box {lo: [x, y, z], hi: [x, y, z]} (m), hi > lo.
std::pair<Vec3, Vec3> readRegion(const Reader& r, const YAML::Node& region, const std::string& where) {
  r.allowOnly(region, where, {"lo", "hi"});
  const Vec3 lo = r.vector(region, "lo", where), hi = r.vector(region, "hi", where);
  if (!((hi - lo).minCoeff() > 0.0)) r.fail(region, where, "needs hi > lo");
  return {lo, hi};
}

/// A mesh wall's STL file (relative to the scene file), read, repaired (io/stl_mesh.hpp) and
/// scaled to m, with its contact features.
MeshFeatures readMeshWall(const Reader& r, const YAML::Node& wall, const std::string& where, const std::string& scenePath) {
  const std::filesystem::path file = std::filesystem::path(scenePath).parent_path() / r.text(wall, "mesh", where);
  if (!std::filesystem::is_regular_file(file)) {
    r.fail(wall["mesh"], where + ".mesh", "cannot open '" + file.string() + "' (paths are relative to the scene file)");
  }
  const double scale = wall["scale"] ? r.positive(wall, "scale", where, "m per STL unit") : 1.0;
  try {
    return MeshFeatures(readStlMesh(file, scale).mesh);
  } catch (const MeshError& e) {
    r.fail(wall["mesh"], where + ".mesh", e.what());
  } catch (const std::invalid_argument& e) {
    r.fail(wall["mesh"], where + ".mesh", file.string() + ": " + e.what());
  }
}

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

Scene parseScene(const std::string& path, const YAML::Node& root) {
  const Reader r(path);
  Scene scene;
  scene.path = path;
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
  scene.broadPhase = r.choice(root, "broad_phase", "", {{"cell_list", BroadPhase::CellList}, {"aabb_tree", BroadPhase::AabbTree}},
                              BroadPhase::CellList);
  scene.reorderEvery = static_cast<int>(r.integer(root, "reorder_every", "", 0.0, 1e6, 20.0));

  const YAML::Node materials = root["materials"];
  if (!materials || !materials.IsMap() || materials.size() == 0) r.fail(materials ? materials : root, "materials", "missing (a mapping name -> properties)");
  r.uniqueKeys(materials, "materials");
  for (const auto& m : materials) {
    const std::string name = m.first.as<std::string>();
    static const std::regex plain("[A-Za-z0-9_.-]+");  // names go into particle files (CSV) and messages
    if (!std::regex_match(name, plain)) r.fail(m.first, "materials." + name, "names are letters, digits, '_', '.', '-'");
    scene.materials.push_back({name, readMaterial(r, m.second, "materials." + name)});
  }
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
    const std::string shapePath = (std::filesystem::path(path).parent_path() / file.as<std::string>()).string();
    YAML::Node shape;
    try {
      shape = YAML::LoadFile(shapePath);
    } catch (const YAML::BadFile&) {
      r.fail(file, "shapes." + name + ".file", "cannot open '" + shapePath + "' (paths are relative to the scene file)");
    } catch (const YAML::ParserException& e) {
      throw SceneError(shapePath + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
    }
    scene.shapes.push_back(readShape(Reader(shapePath), shape, name));
  }

  // Interactions: every material pair must be declared exactly once.
  const std::size_t nm = scene.materials.size();
  std::vector<bool> declared(nm * nm, false);
  const YAML::Node interactions = root["interactions"];
  if (!interactions || !interactions.IsSequence()) r.fail(interactions ? interactions : root, "interactions", "missing (a list, one entry per material pair)");
  for (std::size_t k = 0; k < interactions.size(); ++k) {
    const YAML::Node in = interactions[k];
    const std::string where = "interactions[" + std::to_string(k) + "]";
    const std::vector<std::string_view> pairKeys{"materials",         "normal",      "tangential",         "eccentricity",
                                                 "cap_factor",        "curvature_tolerance", "reduced_stiffness",
                                                 "restitution",       "rolling_hysteresis",  "friction"};
    r.uniqueKeys(in, where);
    const YAML::Node pair = in["materials"];
    if (!pair || !pair.IsSequence() || pair.size() != 2) r.fail(pair ? pair : in, where + ".materials", "must be a pair [material, material]");
    InteractionSpec spec;
    spec.materialA = r.lookup(pair[0], where + ".materials", scene.materials, "material");
    spec.materialB = r.lookup(pair[1], where + ".materials", scene.materials, "material");
    if (declared[spec.materialA * nm + spec.materialB]) r.fail(pair, where + ".materials", "this pair is declared twice");
    declared[spec.materialA * nm + spec.materialB] = declared[spec.materialB * nm + spec.materialA] = true;
    spec.capFactor = r.number(in, "cap_factor", where, 10.0);
    if (!(spec.capFactor > 0.0)) r.fail(in["cap_factor"], where + ".cap_factor", "must be > 0");
    spec.curvatureTolerance = r.number(in, "curvature_tolerance", where, InteractionSpec{}.curvatureTolerance);
    if (!(spec.curvatureTolerance >= 0.0 && spec.curvatureTolerance <= 0.1)) {
      r.fail(in["curvature_tolerance"], where + ".curvature_tolerance", "must be in [0, 0.1] (0: curvatures every step)");
    }
    spec.stiffnessScale = r.number(in, "reduced_stiffness", where, 1.0);
    if (!(spec.stiffnessScale > 0.0 && spec.stiffnessScale <= 1.0)) r.fail(in["reduced_stiffness"], where + ".reduced_stiffness", "must be in (0, 1] (E_mod / E)");
    // The normal law (law_registry.hpp) reads its own keys.
    const Material &A = scene.materials[spec.materialA].material, &B = scene.materials[spec.materialB].material;
    const PairElasticity elasticity{
        .effectiveModulus = effectiveModulus(A.youngsModulus, A.poissonRatio, B.youngsModulus, B.poissonRatio) * spec.stiffnessScale,
        .stiffnessScale = spec.stiffnessScale,
        .poissonRatio = 0.5 * (A.poissonRatio + B.poissonRatio),
        .yieldStrength = std::min(A.yieldStrength, B.yieldStrength)};
    const SceneLawInput lawInput(r, in, where, pairKeys, spec.lawParameters);
    spec.normalName = in["normal"] ? r.text(in, "normal", where) : "elliptic_hertz";
    const NormalLawEntry& entry = normalLaw(spec.normalName, lawInput, "normal");
    spec.normal = readNormalLaw(entry, lawInput, elasticity);
    spec.curvatures = entry.curvatures;
    // The elliptic tangential law needs the contact ellipse, which only the curvature laws have.
    spec.ellipticTangential = r.choice(in, "tangential", where, {{"elliptic_mindlin", true}, {"circular_mindlin", false}},
                                       entry.curvatures);
    if (!entry.curvatures && spec.ellipticTangential) {
      r.fail(in["tangential"], where + ".tangential", "elliptic_mindlin needs a law on the curvatures (allowed here: circular_mindlin)");
    }
    spec.eccentricity = r.choice(in, "eccentricity", where,
                                 {{"tabulated", EccentricityMethod::Tabulated}, {"exact", EccentricityMethod::Exact},
                                  {"explicit", EccentricityMethod::Explicit}},
                                 EccentricityMethod::Tabulated);
    // Pair values of the damping and friction: by default the smaller of the two materials'.
    spec.restitution = r.number(in, "restitution", where, 0.0);
    if (in["restitution"] && !(spec.restitution > 0.0 && spec.restitution <= 1.0)) {
      r.fail(in["restitution"], where + ".restitution", "must be in (0, 1]");
    }
    spec.friction = r.number(in, "friction", where, -1.0);
    if (in["friction"] && spec.friction < 0.0) r.fail(in["friction"], where + ".friction", "must be >= 0");
    spec.rollingHysteresis = r.number(in, "rolling_hysteresis", where, 0.0);
    if (spec.rollingHysteresis < 0.0) r.fail(in["rolling_hysteresis"], where + ".rolling_hysteresis", "must be >= 0 (dgamma/gamma)");
    if (spec.rollingHysteresis > 0.0 && !std::holds_alternative<HaervigJkrLaw>(spec.normal)) {
      r.fail(in["rolling_hysteresis"], where + ".rolling_hysteresis",
             "needs normal: haervig_jkr (001's rolling resistance, Eqs. 18-22, is built on its F_C and a_0)");
    }
    scene.interactions.push_back(spec);
  }
  for (std::size_t a = 0; a < nm; ++a) {
    for (std::size_t b = a; b < nm; ++b) {
      if (!declared[a * nm + b]) {
        r.fail(interactions, "interactions", "no entry for the material pair [" + scene.materials[a].name + ", " + scene.materials[b].name + "]");
      }
    }
  }

  if (const YAML::Node walls = root["walls"]) {
    if (!walls.IsSequence()) r.fail(walls, "walls", "must be a list");
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const std::string where = "walls[" + std::to_string(k) + "]";
      r.allowOnly(walls[k], where, {"point", "normal", "axis", "radius", "length", "ends", "spin", "mesh", "scale", "angular_velocity", "velocity", "material"});
      WallSpec w;
      w.point = r.vector(walls[k], "point", where);
      // A plane has a normal; a cylinder an axis, a radius and optionally a spin; a mesh a file
      // and optionally an angular velocity about its point.
      if (int(walls[k]["normal"].IsDefined()) + int(walls[k]["axis"].IsDefined()) + int(walls[k]["mesh"].IsDefined()) != 1) {
        r.fail(walls[k], where,
               "needs exactly one of normal [nx, ny, nz] (a plane), axis [ux, uy, uz] with radius (m) (a cylinder) or "
               "mesh: file.stl (a triangle mesh)");
      }
      if (walls[k]["mesh"]) {
        w.shape = WallShape::Mesh;
        w.mesh = std::make_shared<const MeshFeatures>(readMeshWall(r, walls[k], where, path));
      } else if (walls[k]["scale"]) {
        r.fail(walls[k]["scale"], where + ".scale", "belongs to a mesh wall (mesh: file.stl)");
      }
      const char* direction = walls[k]["normal"] ? "normal" : "axis";
      const Vec3 unit = w.mesh ? Vec3::UnitZ() : r.vector(walls[k], direction, where);
      if (!(unit.norm() > 0.0)) r.fail(walls[k][direction], where + "." + direction, "must be non-zero");
      if (w.mesh) {
        for (const char* key : {"radius", "length", "ends", "spin"}) {
          if (walls[k][key]) r.fail(walls[k][key], where + "." + key, "belongs to a cylinder (axis), not a mesh");
        }
        if (walls[k]["angular_velocity"]) w.angularVelocity = r.vector(walls[k], "angular_velocity", where);
      } else if (walls[k]["normal"]) {
        w.normal = unit.normalized();
        for (const char* key : {"radius", "length", "ends", "spin"}) {
          if (walls[k][key]) r.fail(walls[k][key], where + "." + key, "belongs to a cylinder (axis), not a plane (normal)");
        }
        if (walls[k]["angular_velocity"]) r.fail(walls[k]["angular_velocity"], where + ".angular_velocity", "belongs to a mesh; a plane does not rotate");
      } else {
        if (walls[k]["angular_velocity"]) {
          r.fail(walls[k]["angular_velocity"], where + ".angular_velocity", "belongs to a mesh; a cylinder turns about its axis by spin (rad/s)");
        }
        w.shape = WallShape::Cylinder;
        w.axis = unit.normalized();
        w.radius = r.positive(walls[k], "radius", where, "m");
        w.angularVelocity = r.number(walls[k], "spin", where, 0.0) * w.axis;
        if (walls[k]["length"]) w.length = r.positive(walls[k], "length", where, "m");
        if (const YAML::Node ends = walls[k]["ends"]) {
          const std::string kind = r.text(walls[k], "ends", where);
          if (kind != "flat" && kind != "rounded") r.fail(ends, where + ".ends", "must be flat or rounded");
          if (w.length == 0.0) r.fail(ends, where + ".ends", "belongs to a finite cylinder: give its length (m)");
          w.flatEnds = kind == "flat";
        }
      }
      if (walls[k]["velocity"]) w.velocity = r.vector(walls[k], "velocity", where);
      if (!walls[k]["material"]) r.fail(walls[k], where + ".material", "missing");
      w.material = r.lookup(walls[k]["material"], where + ".material", scene.materials, "material");
      scene.walls.push_back(w);
    }
  }

  // Explicit particles: the list, then the files of `insert`; random insertions avoid them.
  if (const YAML::Node list = root["particles"]) {
    if (!list.IsSequence() || list.size() == 0) r.fail(list, "particles", "must be a non-empty list of {shape, material, centre, ...}");
    for (std::size_t k = 0; k < list.size(); ++k) scene.particles.push_back(readParticle(r, list[k], "particles[" + std::to_string(k) + "]", scene));
  }
  const YAML::Node insert = root["insert"];
  if (insert && (!insert.IsSequence() || insert.size() == 0)) r.fail(insert, "insert", "must be a non-empty list");
  if (!insert && scene.particles.empty()) r.fail(root, "insert", "missing: give particles by 'insert' (a list of {count, shape, material, region} or {file}) or 'particles'");
  for (std::size_t k = 0; insert && k < insert.size(); ++k) {
    const std::string where = "insert[" + std::to_string(k) + "]";
    const YAML::Node in = insert[k];
    if (in.IsMap() && in["file"]) {
      r.allowOnly(in, where, {"file", "allow_overlap", "offset", "region"});
      const std::filesystem::path file = std::filesystem::path(path).parent_path() / r.text(in, "file", where);
      if (!std::filesystem::is_regular_file(file)) {
        r.fail(in["file"], where + ".file", "cannot open '" + file.string() + "' (paths are relative to the scene file)");
      }
      const bool allowOverlap = r.flag(in, "allow_overlap", where, false);
      const Vec3 offset = in["offset"] ? r.vector(in, "offset", where) : Vec3::Zero();  // e.g. tiling a periodic bed
      std::vector<ParticleSpec> particles;
      try {
        particles = readParticleFile(file, scene.materials);
      } catch (const SceneError& e) {
        r.fail(in["file"], where + ".file", e.what());
      }
      // region: only the particles whose bounding spheres lie within it (cutting a strip out of
      // a periodic bed, whose particles cross its faces).
      Vec3 keepLo = Vec3::Constant(-std::numeric_limits<double>::infinity()), keepHi = -keepLo;
      if (in["region"]) std::tie(keepLo, keepHi) = readRegion(r, in["region"], where + ".region");
      for (ParticleSpec& p : particles) {
        p.allowOverlap = allowOverlap;
        p.centre += offset;
        const double reach = Superquadric(p.semiAxes.x(), p.semiAxes.y(), p.semiAxes.z(), p.n1, p.n2).boundingRadius();
        if (((p.centre.array() - reach) < keepLo.array()).any() || ((p.centre.array() + reach) > keepHi.array()).any()) continue;
        scene.particles.push_back(std::move(p));
      }
      continue;
    }
    r.allowOnly(in, where, {"count", "solid_fraction", "shape", "material", "region", "random_orientation"});
    InsertionSpec spec;
    if (in["count"].IsDefined() == in["solid_fraction"].IsDefined()) {
      r.fail(in, where, "needs exactly one of count (particles) or solid_fraction (of the region's volume)");
    }
    if (in["count"]) spec.count = static_cast<std::size_t>(r.integer(in, "count", where, 1.0, 1e7));
    if (in["solid_fraction"]) {
      spec.solidFraction = r.number(in, "solid_fraction", where);
      if (!(spec.solidFraction > 0.0 && spec.solidFraction <= 0.4)) {
        r.fail(in["solid_fraction"], where + ".solid_fraction", "must be in (0, 0.4] (random sequential addition jams near 0.38)");
      }
    }
    if (!in["shape"]) r.fail(in, where + ".shape", "missing");
    if (!in["material"]) r.fail(in, where + ".material", "missing");
    spec.shape = r.lookup(in["shape"], where + ".shape", scene.shapes, "shape");
    spec.material = r.lookup(in["material"], where + ".material", scene.materials, "material");
    const YAML::Node region = in["region"];
    if (!region) r.fail(in, where + ".region", "missing ({lo: [x,y,z], hi: [x,y,z]})");
    std::tie(spec.lo, spec.hi) = readRegion(r, region, where + ".region");
    for (int d = 0; d < 3; ++d) {
      if (!scene.domain.periodic[d] && (spec.lo(d) < scene.domain.lo(d) || spec.hi(d) > scene.domain.hi(d))) {
        r.fail(region, where + ".region", std::string("reaches outside the domain along ") + "xyz"[d] +
                                              " (the region holds particle centres and must lie within domain.lo, domain.hi)");
      }
    }
    spec.randomOrientation = r.flag(in, "random_orientation", where, true);
    scene.insertions.push_back(spec);
  }

  const YAML::Node stages = root["stages"];
  if (!stages || !stages.IsSequence() || stages.size() == 0) r.fail(stages ? stages : root, "stages", "missing (a list of {name, duration, stop})");
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const std::string where = "stages[" + std::to_string(k) + "]";
    const YAML::Node st = stages[k];
    r.allowOnly(st, where, {"name", "duration", "stop", "move_wall", "servo_wall", "viscous_damping"});
    StageSpec spec;
    spec.name = st["name"] ? r.text(st, "name", where) : "stage" + std::to_string(k);
    // Stage names go into CSV rows and file names.
    if (!isPlainName(spec.name, 64)) {
      r.fail(st["name"], where + ".name", "must be 1-64 letters, digits, '_', '.', '-', not starting with '.' or '-'");
    }
    for (const StageSpec& other : scene.stages) {
      if (other.name == spec.name) r.fail(st["name"], where + ".name", "'" + spec.name + "' names an earlier stage too");
    }
    spec.duration = r.positive(st, "duration", where, "s");
    spec.viscousDamping = r.number(st, "viscous_damping", where, 0.0);
    if (spec.viscousDamping < 0.0) r.fail(st["viscous_damping"], where + ".viscous_damping", "must be >= 0 (1/s)");
    if (const YAML::Node stop = st["stop"]) {
      r.allowOnly(stop, where + ".stop", {"kinetic_energy_ratio", "velocity_scale", "wall_pressure", "porosity", "wall", "after"});
      if (!stop["kinetic_energy_ratio"] && !stop["wall_pressure"] && !stop["porosity"]) {
        r.fail(stop, where + ".stop", "needs kinetic_energy_ratio, wall_pressure or porosity (the last two with wall)");
      }
      if (stop["kinetic_energy_ratio"]) {
        spec.kineticEnergyRatio = r.positive(stop, "kinetic_energy_ratio", where + ".stop", "-");
        if (stop["velocity_scale"]) {
          spec.velocityScale = r.positive(stop, "velocity_scale", where + ".stop", "m/s");
        } else if (scene.gravity.norm() == 0.0) {
          r.fail(stop, where + ".stop.kinetic_energy_ratio",
                 "without gravity needs velocity_scale (m/s): the ratio is then E_kin / sum m v_s^2 / 2");
        }
      } else if (stop["velocity_scale"]) {
        r.fail(stop["velocity_scale"], where + ".stop.velocity_scale", "belongs to kinetic_energy_ratio");
      }
      if (stop["wall_pressure"]) {
        spec.wallPressure = r.positive(stop, "wall_pressure", where + ".stop", "Pa");
        spec.pressureWall = r.plane(stop, where + ".stop", scene.walls);
      }
      if (stop["porosity"]) {
        spec.porosity = r.number(stop, "porosity", where + ".stop");
        if (!(spec.porosity > 0.0 && spec.porosity < 1.0)) r.fail(stop["porosity"], where + ".stop.porosity", "must be in (0, 1)");
        spec.pressureWall = r.plate(stop, where + ".stop", scene.walls);
      }
      spec.minimumDuration = r.number(stop, "after", where + ".stop", 0.0);
    }
    if (const YAML::Node move = st["move_wall"]) {
      const std::string at = where + ".move_wall";
      r.allowOnly(move, at, {"wall", "velocity", "path"});
      spec.wall = r.wallIndex(move, at, scene.walls.size());
      if (move["velocity"].IsDefined() == move["path"].IsDefined()) {
        r.fail(move, at, "needs exactly one of velocity [vx, vy, vz] (m/s) or path [[t (s), offset (m)], ...]");
      }
      if (move["velocity"]) spec.wallVelocity = r.vector(move, "velocity", at);
      if (const YAML::Node path = move["path"]) {
        const std::string key = at + ".path";
        r.plane(move, at, scene.walls);  // the path runs along the plane's normal
        if (!path.IsSequence() || path.size() == 0) r.fail(path, key, "must be a list of [t (s), offset along the wall normal (m)] points");
        double last = 0.0;
        for (const auto& point : path) {
          if (!point.IsSequence() || point.size() != 2) r.fail(point, key, "each point is [t (s), offset (m)]");
          const double t = r.asNumber(point[0], key), x = r.asNumber(point[1], key);
          if (!(t > last)) r.fail(point, key, "times must be > 0 and increasing (s)");
          last = t;
          spec.wallPath.points.push_back({t, x});
        }
      }
    }
    if (const YAML::Node servo = st["servo_wall"]) {
      r.allowOnly(servo, where + ".servo_wall", {"wall", "pressure", "max_speed"});
      spec.servoWall = r.plane(servo, where + ".servo_wall", scene.walls);
      if (spec.wall == spec.servoWall) r.fail(servo, where + ".servo_wall", "the same wall cannot also be in move_wall");
      spec.servo.pressure = r.positive(servo, "pressure", where + ".servo_wall", "Pa");
      spec.servo.maxSpeed = r.positive(servo, "max_speed", where + ".servo_wall", "m/s");
    }
    scene.stages.push_back(spec);
  }

  if (const YAML::Node out = root["output"]) {
    r.allowOnly(out, "output",
                {"frames", "log_every", "contacts", "surface_resolution", "checkpoint_every_steps", "checkpoint_every_minutes", "energy", "compression",
                 "sphere_orientation", "vtk_compression"});
    scene.output.frames = static_cast<std::size_t>(r.integer(out, "frames", "output", 0.0, 1e5, 20.0));
    scene.output.logEvery = static_cast<std::size_t>(r.integer(out, "log_every", "output", 0.0, 1e12, 0.0));
    scene.output.contacts = r.flag(out, "contacts", "output", true);
    if (out["surface_resolution"]) {
      scene.output.surfaceResolution = static_cast<int>(r.integer(out, "surface_resolution", "output", 0.0, 64.0, 8.0));
    }
    scene.output.checkpointSteps = static_cast<std::uint64_t>(r.integer(out, "checkpoint_every_steps", "output", 0.0, 1e12, 0.0));
    scene.output.checkpointMinutes = r.number(out, "checkpoint_every_minutes", "output", scene.output.checkpointMinutes);
    if (!(scene.output.checkpointMinutes >= 0.0)) {
      r.fail(out["checkpoint_every_minutes"], "output.checkpoint_every_minutes", "must be >= 0 (wall-clock minutes, 0: off)");
    }
    if (const YAML::Node press = out["compression"]) {
      r.allowOnly(press, "output.compression", {"wall"});
      scene.output.compressionWall = r.plate(press, "output.compression", scene.walls);
    }
    scene.output.energy = r.flag(out, "energy", "output", false);
    scene.output.sphereOrientation = r.flag(out, "sphere_orientation", "output", false);
    scene.output.vtkCompression = r.choice(out, "vtk_compression", "output",
                                           {{"zlib", VtkCompression::ZLib}, {"lz4", VtkCompression::LZ4}, {"none", VtkCompression::None}},
                                           VtkCompression::ZLib);
    for (std::size_t k = 0; scene.output.energy && k < scene.interactions.size(); ++k) {
      if (!storesEnergy(scene.interactions[k].normal)) {
        r.fail(out["energy"], "output.energy",
               "the energy ledger needs every interaction's normal law to state its stored elastic energy "
               "(elliptic_hertz, volume_sphere_hertz, becker_kamlah without surface_energy); interactions[" +
                   std::to_string(k) + "] uses " + scene.interactions[k].normalName);
      }
    }
  }
  return scene;
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
  try {
    return parseScene(path, root);
  } catch (const YAML::Exception& e) {  // a wrong node type where a string was expected
    throw SceneError(path + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

}  // namespace sqdem
