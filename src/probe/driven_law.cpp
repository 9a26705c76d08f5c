#include "sqdem/probe/driven_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sqdem::probe {
namespace {

/// A law's keys in a JSON object (law_input.hpp); "type" and "eccentricity" are the driver's.
class JsonLawInput final : public LawInput {
 public:
  JsonLawInput(const json& object, std::string where, std::vector<std::string_view> ownKeys)
      : object_(object), where_(std::move(where)), ownKeys_(std::move(ownKeys)) {}

  bool has(std::string_view key) const override { return object_.contains(key); }
  double number(std::string_view key) const override { return probe::number(object_, std::string(key), where_); }
  bool flag(std::string_view key) const override {
    const json& v = object_.at(key);
    if (!v.is_boolean()) fail(key, "must be true or false");
    return v.get<bool>();
  }
  std::unique_ptr<LawInput> child(std::string_view key) const override {
    const json& v = object_.at(key);
    if (!v.is_object()) fail(key, "must be an object");
    return std::make_unique<JsonLawInput>(v, where_ + "." + std::string(key), std::vector<std::string_view>{});
  }
  std::vector<std::string> keys() const override {
    std::vector<std::string> out;
    for (const auto& [key, value] : object_.items()) {
      if (std::find(ownKeys_.begin(), ownKeys_.end(), key) == ownKeys_.end()) out.push_back(key);
    }
    return out;
  }
  std::string ownKeys() const override { return joinKeys(ownKeys_); }
  void raise(std::string_view key, const std::string& message) const override {
    throw InputError(where_ + ": " + (key.empty() ? "" : "'" + std::string(key) + "' ") + message);
  }

 private:
  const json& object_;
  std::string where_;
  std::vector<std::string_view> ownKeys_;
};

}  // namespace

double ContactMaterials::effectiveModulus() const {
  return sqdem::effectiveModulus(youngsA, poissonA, youngsB, poissonB);
}

double ContactMaterials::effectiveShearModulus() const {
  return sqdem::effectiveShearModulus(youngsA, poissonA, youngsB, poissonB);
}

DrivenLaw::DrivenLaw(const json& law, const std::string& where, const RelativeRadii& radii,
                     const ContactMaterials& materials, double meanRadiusSum) {
  if (!law.is_object()) throw InputError(where + " must be an object");
  const JsonLawInput input(law, where, {"type", "eccentricity"});
  const std::string method = choice(law, "eccentricity", where, {"exact", "explicit", "tabulated"}, "exact");
  const EccentricityMethod m = method == "exact"      ? EccentricityMethod::Exact
                               : method == "explicit" ? EccentricityMethod::Explicit
                                                      : EccentricityMethod::Tabulated;
  if (!law.contains("type") || !law["type"].is_string()) input.fail("type", "must name a law");
  const NormalLawEntry& entry = normalLaw(law["type"].get<std::string>(), input, "type");
  if (!entry.curvatures) {
    input.fail("type", "volume_sphere_hertz is Hertz on the volume-equivalent spheres, which the driver does not "
                       "take: it drives a law on the pair's relative radii (given, or the particles' curvatures); for "
                       "the volume spheres use elliptic_hertz with radii [R*, R*], R* = rA rB / (rA + rB)");
  }
  const PairElasticity pair{.effectiveModulus = materials.effectiveModulus(), .poissonRatio = materials.meanPoisson()};
  law_ = readNormalLaw(entry, input, pair);
  adhesive_ = sqdem::adhesive(law_);
  contact_ = {.radii = radii, .factors = hertzFactors(radii.ratio(), m), .effectiveModulus = pair.effectiveModulus,
              .radiusSum = meanRadiusSum};
  try {
    checkContact(law_, contact_);
  } catch (const std::invalid_argument& e) {
    throw InputError(where + ": " + e.what());
  }
}

LawSample DrivenLaw::at(double overlap) {
  // The history stays across separation and detachment: the driver loads one contact spot
  // again and again (002 Tables 3-4 reload a plastic dent, 000 Fig. 2d re-attaches at alpha_c0),
  // where the engine starts a new contact.
  const NormalResponse r = normalResponse(law_, contact_, overlap, history_);
  if (!r.acting) return {};
  return {r.force, r.area > 0.0 ? std::optional(r.area) : std::nullopt, r.regime, true};
}

std::optional<YieldPoint> DrivenLaw::yield() const { return yieldPoint(law_, contact_); }

json DrivenLaw::constants() const {
  json out = json::object();
  for (const LawConstant& c : lawConstants(law_, contact_)) out[c.name] = c.value;
  return out;
}

}  // namespace sqdem::probe
