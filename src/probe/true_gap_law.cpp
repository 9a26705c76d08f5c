#include "sqdem/probe/true_gap_law.hpp"

#include <cmath>

#include "sqdem/truegap/true_gap_curve.hpp"

namespace sqdem::probe {

TrueGapLaw::TrueGapLaw(const json& law, const std::string& where, const Particle& A, const Particle& B, const ContactGeometry& contact,
                       const RelativeRadii& radii, const ContactMaterials& materials) {
  rejectUnknownKeys(law, {"type", "cells"}, where);
  const double cells = number(law, "cells", where, 16.0);
  if (!(cells >= 8.0 && cells <= 64.0) || cells != std::floor(cells)) {
    throw InputError(where + ": 'cells' (per side of the coarse grid) must be an integer in [8, 64]");
  }
  cells_ = static_cast<int>(cells);
  curve_ = std::make_unique<TrueGapCurve>(PairBody{A.shape, A.pose}, PairBody{B.shape, B.pose}, contact, radii,
                                          materials.effectiveModulus(), cells_);
}

TrueGapLaw::~TrueGapLaw() = default;

LawSample TrueGapLaw::at(double overlap) {
  const NormalResponse r = curve_->at(overlap);
  if (!r.acting) return {};
  return {r.force, r.area, "elastic", true};
}

json TrueGapLaw::constants() const { return {{"cells", cells_}, {"true_gap_weight", curve_->weight()}}; }

}  // namespace sqdem::probe
