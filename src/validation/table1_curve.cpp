#include "sqdem/validation/table1_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sqdem/truegap/pair_contact.hpp"
#include "sqdem/truegap/true_gap_curve.hpp"
#include "sqdem/validation/table1.hpp"

namespace sqdem {

void requireTable1CurveLaw(std::string_view law) {
  if (std::find(table1CurveLaws.begin(), table1CurveLaws.end(), law) != table1CurveLaws.end()) return;
  std::string names;
  for (const std::string_view name : table1CurveLaws) names += (names.empty() ? "" : ", ") + std::string(name);
  throw std::invalid_argument("unknown law '" + std::string(law) + "' (allowed: " + names + ")");
}

std::vector<Table1CurvePoint> table1Curve(std::string_view law) {
  requireTable1CurveLaw(law);
  const Superquadric shape = table1Shape();
  const double Rvol = shape.volumeEquivalentRadius();
  std::vector<Table1CurvePoint> curve;
  for (const Table1Case& c : table1Cases) {
    // The laws of the true gap take the touching pose's gap (an overlap of 1e-9 R_vol) and press
    // it by each overlap; the Hertz models read the curvatures at each overlap's pose.
    const Table1Result touching = runTable1Case(c, 1e-9);
    const PairBody A{shape, Pose{}}, B{shape, touching.second};
    TrueGapCurve trueGap(A, B, touching.contact, touching.radii, 1.0, 16);
    for (const double f : table1Overlaps) {
      const double delta = f * Rvol, scale = 4.0 / 3.0 * std::sqrt(Rvol) * std::pow(delta, 1.5);
      double force = 0.0;
      if (law == "boundary_element") {
        force = boundaryElementContact(A, B, touching.contact, delta, 1.0).force / scale;
      } else if (law == "true_gap") {
        force = trueGap.at(delta).force / scale;
      } else {
        const Table1Result r = runTable1Case(c, f);
        force = law == "review" ? r.normalisedForce : r.normalisedForceExact;
      }
      curve.push_back({c.id, f, force, c.fem});
    }
  }
  return curve;
}

}  // namespace sqdem
