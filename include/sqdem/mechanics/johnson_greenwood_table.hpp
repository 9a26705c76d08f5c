#pragma once
// The dimensionless Johnson-Greenwood curves (004 Eqs. 19-28, jkr_elliptic.hpp) tabulated once,
// so that an elliptic JKR contact costs a table look-up instead of two Brent minimisations and a
// root solve per contact and step (docs/contact_laws.md, "Elliptic JKR from a table").
//
// With the scales of jkr_elliptic.hpp (F_bar = F / (3 pi R_c1 W), delta_bar, A_bar), a curve
// depends on lambda = sqrt(Ri/Rj) alone. Its stable branch runs from the detachment overlap
// delta_bar_d (where F_bar has a square-root singularity in delta_bar) to the Hertz limit
// (F_bar -> gamma_inf delta_bar^3/2, A_bar -> beta_inf delta_bar). The table's coordinates make
// every tabulated quantity smooth, bounded and finite at both ends:
//   u = ln lambda in [ln minLambda, 0],
//   w = sqrt(delta_bar - delta_bar_d),  t = (1 + w)^-1/2 in (0, 1]   (t = 1 at detachment,
//       t -> 0 in the Hertz limit; the JKR correction is a power series in t there),
//   tabulated: F_bar t^6, A_bar t^4 and the axis ratio g, with delta_bar_d and the pull-off
//   F_bar_min per lambda;
// each interpolated by 4-point Lagrange polynomials (bicubic). The nodes are the exact curve
// (EllipticJkr with JkrCurve::Exact). Error against the exact curve, measured over 2e4 random
// points (tests/jkr_test.cpp): stated in docs/contact_laws.md.

#include <vector>

#include "sqdem/math/cubic_stencil.hpp"

namespace sqdem::detail {

/// One point of a dimensionless curve.
struct JohnsonGreenwoodValue {
  double force = 0.0;      ///< F_bar
  double area = 0.0;       ///< A_bar
  double axisRatio = 1.0;  ///< g = b_c / a_c
};

class JohnsonGreenwoodTable {
 public:
  static constexpr double minLambda = 1e-2;  ///< Ri/Rj >= 1e-4; below, the exact curve
  static constexpr int lambdaIntervals = 64, overlapIntervals = 384;

  /// The table, built on first use (thread-safe).
  static const JohnsonGreenwoodTable& instance();

  /// The curve of lambda (minLambda <= lambda <= 1): where it sits in the table, its
  /// detachment overlap delta_bar_d and its pull-off F_bar_min (< 0).
  struct Curve {
    CubicStencil stencil;
    double detachment = 0.0, pullOff = 0.0;
  };
  Curve curve(double lambda) const;
  /// The curve at overlapBar >= curve.detachment.
  JohnsonGreenwoodValue at(const Curve& curve, double overlapBar) const;

 private:
  JohnsonGreenwoodTable();

  struct Node {
    double force, area, axisRatio;  // F_bar t^6, A_bar t^4, g
  };
  std::vector<Node> nodes_;              // (lambdaIntervals + 1) x (overlapIntervals + 1), t fastest
  std::vector<double> detachment_, pullOff_;  // lambdaIntervals + 1
};

}  // namespace sqdem::detail
