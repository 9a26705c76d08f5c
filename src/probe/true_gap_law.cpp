#include "sqdem/probe/true_gap_law.hpp"

#include <variant>

#include "sqdem/probe/json_law_input.hpp"
#include "sqdem/truegap/true_gap_curve.hpp"

namespace sqdem::probe {

TrueGapCurveLaw::TrueGapCurveLaw(const json& law, const std::string& where, const Particle& A, const Particle& B, const ContactGeometry& contact,
                       const RelativeRadii& radii, const ContactMaterials& materials) {
  // The registry reads and checks the law's keys (law_registry.hpp), as for the engine's scenes.
  const JsonLawInput input(law, where, {"type"});
  const PairElasticity pair = materials.elasticity();
  cells_ = std::get<TrueGapLaw>(readNormalLaw(normalLaw("true_gap", input, "type"), input, pair)).cells;
  curve_ = std::make_unique<TrueGapCurve>(PairBody{A.shape, A.pose}, PairBody{B.shape, B.pose}, contact, radii,
                                          materials.effectiveModulus(), cells_);
}

TrueGapCurveLaw::~TrueGapCurveLaw() = default;

LawSample TrueGapCurveLaw::at(double overlap) {
  const NormalResponse r = curve_->at(overlap);
  if (!r.acting) return {};
  return {r.force, r.area, "elastic", true};
}

json TrueGapCurveLaw::constants() const { return {{"cells", cells_}, {"true_gap_weight", curve_->weight()}}; }

}  // namespace sqdem::probe
