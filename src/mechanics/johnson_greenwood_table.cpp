#include "sqdem/mechanics/johnson_greenwood_table.hpp"

#include <cmath>
#include <numbers>

#include "sqdem/mechanics/jkr_elliptic.hpp"

namespace sqdem::detail {
namespace {

using std::numbers::pi;

const double lambdaStep = -std::log(JohnsonGreenwoodTable::minLambda) / JohnsonGreenwoodTable::lambdaIntervals;

/// The overlap of the Hertz-limit node (t = 0), where F_bar / delta_bar^3/2 and A_bar / delta_bar
/// are within ~delta_bar^-3/4 = 1e-9 of their limits.
constexpr double hertzLimitOverlap = 1e12;

}  // namespace

const JohnsonGreenwoodTable& JohnsonGreenwoodTable::instance() {
  static const JohnsonGreenwoodTable table;
  return table;
}

JohnsonGreenwoodTable::JohnsonGreenwoodTable()
    : nodes_((lambdaIntervals + 1) * (overlapIntervals + 1)), detachment_(lambdaIntervals + 1), pullOff_(lambdaIntervals + 1) {
  // E* = 9 pi / 4, W = 1 and R_c1 = 1 make the scales of jkr_elliptic.hpp 1 (overlap), 3 pi
  // (force) and pi (area).
  for (int i = 0; i <= lambdaIntervals; ++i) {
    const double lambda = i == lambdaIntervals ? 1.0 : std::exp((i - lambdaIntervals) * lambdaStep);
    const RelativeRadii radii{.Ri = lambda, .Rj = 1.0 / lambda, .cosOmega = 1.0, .Rc = 1.0 / (lambda + 1.0 / lambda)};
    const EllipticJkr exact(9.0 * pi / 4.0, 1.0, radii, JkrCurve::Exact);
    detachment_[i] = exact.detachmentOverlap();
    pullOff_[i] = exact.pullOffForce() / (3.0 * pi);
    for (int j = 0; j <= overlapIntervals; ++j) {
      Node& node = nodes_[i * (overlapIntervals + 1) + j];
      if (j == 0) {
        const EllipticJkrState s = exact.evaluate(hertzLimitOverlap);
        node = {s.force / (3.0 * pi) / std::pow(hertzLimitOverlap, 1.5), s.area / pi / hertzLimitOverlap, s.axisRatio};
        continue;
      }
      const double t = static_cast<double>(j) / overlapIntervals, w = 1.0 / (t * t) - 1.0;
      const EllipticJkrState s = exact.evaluate(detachment_[i] + w * w);
      const double t2 = t * t;
      node = {s.force / (3.0 * pi) * t2 * t2 * t2, s.area / pi * t2 * t2, s.axisRatio};
    }
  }
}

JohnsonGreenwoodTable::Curve JohnsonGreenwoodTable::curve(double lambda) const {
  Curve c{.stencil = cubicStencil(std::log(lambda) / lambdaStep + lambdaIntervals, lambdaIntervals)};
  for (int i = 0; i < 4; ++i) {
    c.detachment += c.stencil.weight[i] * detachment_[c.stencil.first + i];
    c.pullOff += c.stencil.weight[i] * pullOff_[c.stencil.first + i];
  }
  return c;
}

JohnsonGreenwoodValue JohnsonGreenwoodTable::at(const Curve& curve, double overlapBar) const {
  const double w = std::sqrt(std::max(overlapBar - curve.detachment, 0.0)), t = 1.0 / std::sqrt(1.0 + w);
  const CubicStencil across = cubicStencil(t * overlapIntervals, overlapIntervals);
  Node sum{0.0, 0.0, 0.0};
  for (int i = 0; i < 4; ++i) {
    const Node* row = &nodes_[(curve.stencil.first + i) * (overlapIntervals + 1) + across.first];
    Node r{0.0, 0.0, 0.0};
    for (int j = 0; j < 4; ++j) {
      r.force += across.weight[j] * row[j].force;
      r.area += across.weight[j] * row[j].area;
      r.axisRatio += across.weight[j] * row[j].axisRatio;
    }
    sum.force += curve.stencil.weight[i] * r.force;
    sum.area += curve.stencil.weight[i] * r.area;
    sum.axisRatio += curve.stencil.weight[i] * r.axisRatio;
  }
  const double t2 = t * t;
  return {.force = sum.force / (t2 * t2 * t2), .area = sum.area / (t2 * t2), .axisRatio = sum.axisRatio};
}

}  // namespace sqdem::detail
