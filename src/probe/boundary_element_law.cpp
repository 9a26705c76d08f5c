#include "sqdem/probe/boundary_element_law.hpp"

#include <cmath>

#include "sqdem/truegap/pair_contact.hpp"

namespace sqdem::probe {

BoundaryElementLaw::BoundaryElementLaw(const json& law, const std::string& where, const Particle& A, const Particle& B,
                                       const ContactGeometry& contact, const ContactMaterials& materials)
    : A_(A), B_(B), contact_(contact), effectiveModulus_(materials.effectiveModulus()) {
  rejectUnknownKeys(law, {"type", "cells"}, where);
  const double cells = number(law, "cells", where, 128.0);
  if (!(cells >= 16.0 && cells <= 512.0) || cells != std::floor(cells)) {
    throw InputError(where + ": 'cells' (per side of the grid) must be an integer in [16, 512]");
  }
  cells_ = static_cast<int>(cells);
}

LawSample BoundaryElementLaw::at(double overlap) {
  if (!(overlap > 0.0)) return {};
  const HalfspaceContact c = boundaryElementContact({A_.shape, A_.pose}, {B_.shape, B_.pose}, contact_, overlap, effectiveModulus_, cells_);
  return {c.force, c.area, "elastic", true};
}

}  // namespace sqdem::probe
