#include "sqdem/mechanics/jkr_elliptic.hpp"

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "sqdem/mechanics/elliptic_integrals.hpp"

namespace sqdem {

using std::numbers::pi;

JohnsonGreenwoodPoint johnsonGreenwoodPoint(double lambda, double g) {
  const double g2 = g * g, sg = std::sqrt(g);
  const EllipticIntegrals I = ellipticIntegrals(1.0 - g2, g2);
  const double K = I.K, B = I.B, C = I.C, D = I.D;
  JohnsonGreenwoodPoint p;
  p.g = g;
  p.Pi2 = ((lambda * lambda + 1.0) * C + D) / (lambda * ((D + C) * (B + g2 * C) - g2 * C * C));
  p.Pi1 = (lambda + 1.0 / lambda - B * p.Pi2) / D;
  const double denominator = p.Pi2 * g2 - p.Pi1;                 // 0 at the Hertz axis ratio
  const double X = (p.Pi1 - p.Pi2 * g2 * sg) / (1.0 - sg);
  const double bracket = 2.0 * K * X - p.Pi1 * B - g2 * p.Pi2 * D;  // Eq. 20
  const double Q = g * (1.0 - sg) * (1.0 - sg) / (denominator * denominator);
  const double loadBracket = X - (p.Pi2 * g2 + p.Pi1) / 3.0;        // Eq. 19
  p.force = 8.0 / (3.0 * pi) * Q * loadBracket;
  p.overlap = std::cbrt(std::pow(std::pow(2.0, 3.5) / (9.0 * pi * pi), 2.0) * Q * Q) * bracket;
  p.area = std::pow(4.0 * std::numbers::sqrt2 / (3.0 * pi) * g * std::sqrt(sg) * (1.0 - sg) /
                        std::abs(denominator), 4.0 / 3.0);
  p.gamma = 1.5 * pi * std::numbers::sqrt2 * loadBracket / std::pow(bracket, 1.5);
  p.beta = 2.0 * g / bracket;
  return p;
}

EllipticJkr::EllipticJkr(double effectiveModulus, double workOfAdhesion, const RelativeRadii& radii, JkrCurve method)
    : circle_{effectiveModulus, workOfAdhesion, std::sqrt(radii.Ri * radii.Rj)},
      lambda_(std::sqrt(radii.ratio())) {
  if (!(effectiveModulus > 0.0) || !(workOfAdhesion > 0.0) || !(radii.Ri > 0.0) || !(radii.Rj >= radii.Ri)) {
    throw std::invalid_argument("elliptic JKR: need E* > 0, W > 0 and 0 < Ri <= Rj");
  }
  const double E = effectiveModulus, W = workOfAdhesion, Rc1 = circle_.radius;
  forceScale_ = 3.0 * pi * Rc1 * W;
  overlapScale_ = std::pow(9.0 * pi * W * std::sqrt(Rc1) / (4.0 * E), 2.0 / 3.0);
  areaScale_ = std::pow(9.0 * std::pow(pi, 2.5) * W * Rc1 * Rc1 / (4.0 * E), 2.0 / 3.0);
  if (circular()) {
    pullOffForce_ = -circle_.pullOffForce();
    detachmentOverlap_ = circle_.overlapAt(circle_.minimumContactRadius());
    return;
  }
  if (method == JkrCurve::Tabulated && lambda_ >= detail::JohnsonGreenwoodTable::minLambda) {
    tabulated_ = true;
    curve_ = detail::JohnsonGreenwoodTable::instance().curve(lambda_);
    detachmentOverlap_ = curve_.detachment * overlapScale_;
    pullOffForce_ = curve_.pullOff * forceScale_;
    return;
  }
  gHertz_ = std::sqrt(1.0 - eccentricitySquaredExact(radii.ratio()));
  const double lo = gHertz_ + 1e-9 * (1.0 - gHertz_), hi = 1.0 - 1e-9 * (1.0 - gHertz_);
  const int bits = 40;
  const auto overlapMin = boost::math::tools::brent_find_minima(
      [this](double g) { return johnsonGreenwoodPoint(lambda_, g).overlap; }, lo, hi, bits);
  gDetach_ = overlapMin.first;
  detachmentOverlap_ = overlapMin.second * overlapScale_;
  const auto forceMin = boost::math::tools::brent_find_minima(
      [this](double g) { return johnsonGreenwoodPoint(lambda_, g).force; }, lo, hi, bits);
  pullOffForce_ = forceMin.second * forceScale_;
}

EllipticJkrState EllipticJkr::evaluate(double overlap, JkrHistory& history) const {
  if (!history.attached && overlap < 0.0) return EllipticJkrState{.attached = false};
  const EllipticJkrState s = evaluate(overlap);
  history.attached = s.attached;
  return s;
}

EllipticJkrState EllipticJkr::evaluate(double overlap) const {
  EllipticJkrState s;
  if (overlap < detachmentOverlap_) {
    s.attached = false;
    return s;
  }
  if (circular()) {
    const double a = circle_.contactRadius(overlap);
    s.force = circle_.forceAt(a);
    s.area = pi * a * a;
    return s;
  }
  if (tabulated_) {
    const detail::JohnsonGreenwoodValue v = detail::JohnsonGreenwoodTable::instance().at(curve_, overlap / overlapScale_);
    return {.force = v.force * forceScale_, .area = v.area * areaScale_, .axisRatio = v.axisRatio};
  }
  return evaluateExact(overlap);
}

EllipticJkrState EllipticJkr::evaluateExact(double overlap) const {
  EllipticJkrState s;
  // delta_bar(g) falls from +inf at g_H to its minimum at g_d: bracket the root by halving the
  // distance to g_H, then TOMS 748. Beyond the last representable bracket the contact is Hertz.
  const double target = overlap / overlapScale_;
  const auto residual = [&](double g) { return johnsonGreenwoodPoint(lambda_, g).overlap - target; };
  double hi = gDetach_, lo = gDetach_, residualLo = residual(lo);
  for (double s2 = 0.5; residualLo <= 0.0; s2 *= 0.5) {
    hi = lo;
    lo = gHertz_ + s2 * (gDetach_ - gHertz_);
    residualLo = residual(lo);
    if (lo - gHertz_ <= 4.0 * std::numeric_limits<double>::epsilon()) break;
  }
  double g = gHertz_;
  if (residualLo > 0.0) {
    std::uintmax_t iterations = 100;
    const auto root = boost::math::tools::toms748_solve(
        residual, lo, hi, boost::math::tools::eps_tolerance<double>(50), iterations);
    g = 0.5 * (root.first + root.second);
  }
  const JohnsonGreenwoodPoint p = johnsonGreenwoodPoint(lambda_, g);
  s.axisRatio = g;
  if (target > 1.0) {
    // F_bar/delta_bar^3/2 = gamma_JG has no (Pi_2 g^2 - Pi_1) denominator: accurate near g_H,
    // where F_bar and delta_bar blow up; near delta_bar = 0 F_bar itself is the accurate form.
    s.force = p.gamma * target * std::sqrt(target) * forceScale_;
    s.area = p.beta * target * areaScale_;
  } else {
    s.force = p.force * forceScale_;
    s.area = p.area * areaScale_;
  }
  return s;
}

EllipticJkrLaw EllipticJkrLaw::read(const LawInput& in, const PairElasticity& pair) {
  const double gamma = in.positive("surface_energy", "J/m^2, gamma; W = 2 gamma");
  const bool tabulated = !in.has("tabulated") || in.flag("tabulated");
  return {pair.reducedSurfaceEnergy(gamma), tabulated ? JkrCurve::Tabulated : JkrCurve::Exact};
}

NormalResponse EllipticJkrLaw::force(const NormalContact& c, double overlap, History& h) const {
  if (!h.attached && overlap < 0.0) return {.acting = false};
  const EllipticJkr jkr = at(c);
  const EllipticJkrState s = jkr.evaluate(overlap, h);
  if (!s.attached) return {.acting = false};
  return {.force = s.force,
          .stiffness = 2.0 * c.effectiveModulus * std::sqrt(s.area / pi),
          .area = s.area,
          .pullOff = -jkr.pullOffForce(),
          .regime = "attached"};
}

double EllipticJkrLaw::range(const History& h) const {
  return h.attached ? std::numeric_limits<double>::infinity() : 0.0;
}

double EllipticJkrLaw::reach(double effectiveModulus, double R) const {
  return -2.0 * EllipticJkr(effectiveModulus, 2.0 * surfaceEnergy, RelativeRadii{R, R, 1.0, 0.5 * R}).detachmentOverlap();
}

}  // namespace sqdem
