#pragma once
// The true-gap law as a curve of the single-contact driver (`sqdem contact`, law type
// "true_gap"; docs/contact_laws.md, "The true-gap law"): the law at the two posed particles'
// pose (truegap/true_gap_curve.hpp), its coarse grid `cells` x `cells`. Elastic, frictionless,
// normal only.

#include <memory>

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/probe/driven_law.hpp"
#include "sqdem/probe/json_input.hpp"

namespace sqdem {
class TrueGapCurve;
}

namespace sqdem::probe {

class TrueGapCurveLaw final : public CurveLaw {
 public:
  /// `law` {"type": "true_gap", "cells": 8-64 (default 16), "gap_tolerance" (no effect at one
  /// pose)}, read and checked by the law registry (TrueGapLaw::read, as in a scene's
  /// interactions); the particles, the detector's contact
  /// at their given poses and its relative radii (capped as the curve's geometry says: the
  /// elliptic Hertz blended in near ellipsoids).
  TrueGapCurveLaw(const json& law, const std::string& where, const Particle& A, const Particle& B, const ContactGeometry& contact,
             const RelativeRadii& radii, const ContactMaterials& materials);
  ~TrueGapCurveLaw() override;

  LawSample at(double overlap) override;
  json constants() const override;
  bool normalOnly() const override { return true; }

 private:
  std::unique_ptr<TrueGapCurve> curve_;
  int cells_;
};

}  // namespace sqdem::probe
