#include "sqdem/probe/driven_law.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "sqdem/probe/json_law_input.hpp"

namespace sqdem::probe {

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
  // (the driver's boundary-element reference is no law of the registry: contact_drive.cpp)
  static constexpr std::array<std::string_view, 1> alsoDriven{"boundary_element"};
  const NormalLawEntry& entry = normalLaw(law["type"].get<std::string>(), input, "type", alsoDriven);
  if (!entry.curvatures) {
    input.fail("type", "volume_sphere_hertz is Hertz on the volume-equivalent spheres, which the driver does not "
                       "take: it drives a law on the pair's relative radii (given, or the particles' curvatures); for "
                       "the volume spheres use elliptic_hertz with radii [R*, R*], R* = rA rB / (rA + rB)");
  }
  const PairElasticity pair = materials.elasticity();
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
