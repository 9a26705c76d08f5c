#pragma once
// The single-contact driver (`sqdem contact`, `sqdem.contact` in Python): one contact driven along
// a prescribed normal (and optionally tangential) displacement history, for one or more curves
// (a geometry and a normal law each). The input is the JSON document of README.md, "sqdem contact"; every key is
// checked (InputError naming it).
// The result is every curve's response step by step; writing it (CSV, plots) is the caller's.

#include <optional>
#include <string>
#include <vector>

#include "sqdem/probe/driven_law.hpp"
#include "sqdem/probe/json_input.hpp"

namespace sqdem::probe {

/// One curve's response along the path, one entry per step.
struct DrivenCurve {
  std::string label;
  RelativeRadii radii;           ///< of the contact (from the detector's curvatures, or given)
  double meanRadiusSum = 0.0;    ///< r_IJ (m) of two posed particles; 0 for prescribed radii
  int detectorFailures = 0;      ///< steps whose overlap is the prescribed approach
  json constants{};              ///< the law's constants worth reporting (DrivenLaw::constants)
  std::optional<YieldPoint> yield{};
  std::vector<double> overlap{};     ///< (m)
  std::vector<double> normalForce{}; ///< (N), > 0 repulsive
  std::vector<std::optional<double>> area{};  ///< contact area (m^2), where the law defines one
  std::vector<std::string> regime{}; ///< the law's branch at each step
  std::vector<double> tangentialForce{};  ///< (N), empty without a tangential drive
};

struct ContactDrive {
  std::string name;   ///< names the output files: letters, digits, '_', '.', '-'
  std::string title;  ///< the plot's title (safe inside a gnuplot string)
  std::vector<double> displacement;            ///< the approach at each step (m)
  std::vector<double> tangentialDisplacement;  ///< (m), empty if not driven
  std::vector<DrivenCurve> curves;
  bool plotNormalised = false;  ///< plot.normalise: yield (by the first curve's yield point)
  bool plotTangential = false;  ///< plot.quantity: tangential
};

/// Reads the drive (`defaultName` names it when the input has no "name") and drives every curve.
ContactDrive driveContact(const json& input, const std::string& defaultName);

}  // namespace sqdem::probe
