#pragma once
// Table 1 as a curve (docs/contact_laws.md, "Blocky contacts"): the normalised force
// F / (4/3 E* R_vol^1/2 delta^3/2) of the three Table 1 pairs (table1.hpp) at overlaps
// delta / R_vol from 1e-4 to 3e-2, for a law:
//   review            the review's accurate model (explicit e^2, Eq. 14; radii capped at 10 R_vol),
//                     on the detector's curvatures at each overlap: Table 1's own model;
//   elliptic_hertz    the engine's law: the same with the exact e^2 (Eq. 13);
//   boundary_element  the half-space contact of the pair's true gap (truegap/pair_contact.hpp,
//                     128 x 128 cells): the reference;
//   true_gap          the true-gap law (truegap/true_gap_curve.hpp): the same on 16 x 16 cells at
//                     the rungs of its ladder, power laws between them.
// For a Hertzian pair the normalised force is a constant; for the blocky pairs it is not.

#include <array>
#include <string_view>
#include <vector>

namespace sqdem {

inline constexpr std::array<double, 6> table1Overlaps{1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2};
inline constexpr std::array<std::string_view, 4> table1CurveLaws{"review", "elliptic_hertz", "boundary_element", "true_gap"};

struct Table1CurvePoint {
  int caseId;
  double overlapOverRvol;
  double normalisedForce;
  double fem;  ///< the review's finite-element value of the case (one overlap, not stated)
};

/// Throws std::invalid_argument naming table1CurveLaws unless `law` is one of them.
void requireTable1CurveLaw(std::string_view law);
/// The curves of the three cases, case by case (requireTable1CurveLaw first).
std::vector<Table1CurvePoint> table1Curve(std::string_view law);

}  // namespace sqdem
