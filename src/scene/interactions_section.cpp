// The scene's `interactions:` (scene_sections.hpp).

#include <algorithm>
#include <memory>
#include <string>
#include <variant>

#include "sqdem/mechanics/law_registry.hpp"

#include "scene_sections.hpp"

namespace sqdem::detail {
namespace {

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

/// `bond`: the pair's parallel bond (mechanics/parallel_bond.hpp, docs/bonds.md).
ParallelBond readBond(const Reader& r, const YAML::Node& b, const std::string& where) {
  if (!b.IsMap()) {
    r.fail(b, where,
           "must be a map {radius_multiplier, normal_stiffness, shear_stiffness, tensile_strength, shear_strength, damping_ratio}");
  }
  r.allowOnly(b, where, {"radius_multiplier", "normal_stiffness", "shear_stiffness", "tensile_strength", "shear_strength", "damping_ratio"});
  const double dampingRatio = r.number(b, "damping_ratio", where, 0.0);
  if (!(dampingRatio >= 0.0 && dampingRatio <= 1.0)) {
    r.fail(b["damping_ratio"], where + ".damping_ratio", "must be in [0, 1] (a fraction of each spring's critical damping)");
  }
  return {.radiusMultiplier = b["radius_multiplier"] ? r.positive(b, "radius_multiplier", where, "-") : 1.0,
          .normalStiffness = r.positive(b, "normal_stiffness", where, "Pa/m"),
          .shearStiffness = r.positive(b, "shear_stiffness", where, "Pa/m"),
          .tensileStrength = r.positive(b, "tensile_strength", where, "Pa"),
          .shearStrength = r.positive(b, "shear_strength", where, "Pa"),
          .dampingRatio = dampingRatio};
}

}  // namespace

void readInteractions(const Reader& r, const YAML::Node& root, Scene& scene) {
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
                                                 "restitution",       "rolling_hysteresis",  "friction",
                                                 "bond",              "deep_overlaps"};
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
    if (in["bond"]) spec.bond = readBond(r, in["bond"], where + ".bond");
    spec.deepOverlapsExpected = r.choice(in, "deep_overlaps", where, {{"trouble", false}, {"expected", true}}, false);
    scene.interactions.push_back(spec);
  }
  for (std::size_t a = 0; a < nm; ++a) {
    for (std::size_t b = a; b < nm; ++b) {
      if (!declared[a * nm + b]) {
        r.fail(interactions, "interactions", "no entry for the material pair [" + scene.materials[a].name + ", " + scene.materials[b].name + "]");
      }
    }
  }
}

}  // namespace sqdem::detail
