#pragma once
// The boundary-element reference as a curve of the single-contact driver (`sqdem contact`, law
// type "boundary_element"; docs/contact_laws.md, "The boundary-element reference"): at each
// step's overlap, the half-space contact of the two posed particles' true gap
// (truegap/pair_contact.hpp) on `cells` x `cells` cells over the region the gap
// interpenetrates at that overlap. Elastic, frictionless, normal only; slow (~0.5 s a step at
// 128 x 128 cells).

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/probe/driven_law.hpp"
#include "sqdem/probe/json_input.hpp"

namespace sqdem::probe {

class BoundaryElementLaw final : public CurveLaw {
 public:
  /// `law` {"type": "boundary_element", "cells": 16-512 (default 128)}; the particles and the
  /// detector's contact at their given poses (kept by reference: the curve's geometry owns them).
  BoundaryElementLaw(const json& law, const std::string& where, const Particle& A, const Particle& B, const ContactGeometry& contact,
                     const ContactMaterials& materials);

  LawSample at(double overlap) override;
  json constants() const override { return {{"cells", cells_}}; }
  bool normalOnly() const override { return true; }

 private:
  const Particle &A_, &B_;
  const ContactGeometry& contact_;
  double effectiveModulus_;
  int cells_;
};

}  // namespace sqdem::probe
