#include "sqdem/probe/true_gap_law.hpp"

#include <cmath>

#include "sqdem/truegap/true_gap_curve.hpp"

namespace sqdem::probe {

TrueGapCurveLaw::TrueGapCurveLaw(const json& law, const std::string& where, const Particle& A, const Particle& B, const ContactGeometry& contact,
                       const RelativeRadii& radii, const ContactMaterials& materials) {
  rejectUnknownKeys(law, {"type", "cells"}, where);
  const double cells = number(law, "cells", where, TrueGapLaw{}.cells);
  if (!(cells >= TrueGapLaw::fewestCells && cells <= TrueGapLaw::mostCells) || cells != std::floor(cells)) {
    throw InputError(where + ": 'cells' (per side of the coarse grid) must be an integer in [" + std::to_string(TrueGapLaw::fewestCells) +
                     ", " + std::to_string(TrueGapLaw::mostCells) + "]");
  }
  cells_ = static_cast<int>(cells);
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
