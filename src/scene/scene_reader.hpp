#pragma once
// The scene reader's checks (scene_loader.cpp and the section readers, scene_sections.hpp): a
// number, a vector, a range, a choice, a name looked up, each failing with a SceneError that names
// the document, the line and the key path ("interactions[0].cap_factor").

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/scene/scene.hpp"
#include "sqdem/scene/scene_loader.hpp"

namespace sqdem::detail {

/// "where.key", or "key" at the top level.
inline std::string keyPath(const std::string& where, const std::string& key) { return where.empty() ? key : where + "." + key; }

/// Reads a scene document's values with their checks: every failure names the document (its file,
/// and the line where the document is a file) and the key.
class Reader {
 public:
  /// `origin` names the document in messages; relative paths in it are relative to `directory`.
  Reader(std::string origin, std::filesystem::path directory, bool lines)
      : file_(std::move(origin)), directory_(std::move(directory)), lines_(lines) {}
  /// A reader of the file `path` (a scene or a shape file).
  static Reader ofFile(const std::string& path) { return Reader(path, std::filesystem::path(path).parent_path(), true); }

  /// A file a key names, relative to the document's directory.
  std::filesystem::path relative(const std::string& file) const { return directory_ / file; }

  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& message) const {
    std::ostringstream s;
    s << file_;
    if (lines_ && node.IsDefined() && node.Mark().line >= 0) s << ":" << node.Mark().line + 1;
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
    if (!walls[w].wall.is<PlaneWall>()) {
      fail(map["wall"], keyPath(where, "wall"), "walls[" + std::to_string(w) + "] is " + walls[w].wall.kind() + "; this needs a plane");
    }
    return w;
  }
  /// The required key "wall": a plate pressing the bed onto the floor (porosities between them):
  /// a plane facing -z, in a scene with a plane facing +z.
  std::size_t plate(const YAML::Node& map, const std::string& where, const std::vector<WallSpec>& walls) const {
    const std::size_t w = plane(map, where, walls);
    if (!walls[w].wall.get<PlaneWall>().facesDown()) {
      fail(map["wall"], keyPath(where, "wall"), "the pressing plate must be a plane facing -z (normal [0, 0, -1])");
    }
    if (std::ranges::none_of(walls, [](const WallSpec& s) { return s.wall.is<PlaneWall>() && s.wall.get<PlaneWall>().facesUp(); })) {
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
  std::filesystem::path directory_;
  bool lines_;
};

}  // namespace sqdem::detail
