#include "sqdem/mechanics/jamari.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sqdem/mechanics/elliptic_integrals.hpp"

namespace sqdem {

using std::numbers::pi;

JamariElasticPlastic::JamariElasticPlastic(const RelativeRadii& radii, const HertzFactors& factors,
                                           const JamariParameters& p)
    : r_(radii), h_(factors), p_(p) {
  const double ratio = p.maxPressureFactor * p.hardness / p.effectiveModulus;
  delta1_ = pi * pi / 4.0 * r_.Rc * std::pow(h_.beta / h_.gamma, 2) * ratio * ratio;  // Eq. 41
  const double lambda = std::sqrt(r_.ratio());
  const EllipticIntegrals I = ellipticIntegrals(h_.e2);
  delta2_ = p.plasticOverlapFactor * lambda / (1.0 + lambda * lambda) / std::sqrt(1.0 - h_.e2) * I.E / I.K *
            delta1_;  // Eq. 44
  if (!(p.effectiveModulus > 0) || !(p.hardness > 0) || !(p.maxPressureFactor > 0)) {
    throw std::invalid_argument("Jamari law: need E*, H, K_v > 0");
  }
  // A contact so elongated that Eq. 44 gives delta_2 <= delta_1 has no elastic-plastic range.
  delta2_ = std::max(delta2_, delta1_);
}

double JamariElasticPlastic::loadingArea(double d) const {
  if (d <= 0.0) return 0.0;
  const double elasticArea = pi * r_.Rc * d * h_.beta;  // Eq. 2
  if (d <= delta1_) return elasticArea;
  const double plasticArea = 2.0 * pi * std::sqrt(r_.Ri * r_.Rj) * d;  // Eq. 43
  if (d >= delta2_) return plasticArea;
  const double x = (d - delta1_) / (delta2_ - delta1_);
  return elasticArea + (plasticArea - elasticArea) * (3.0 * x * x - 2.0 * x * x * x);  // Eq. 46
}

double JamariElasticPlastic::loadingForce(double d) const {
  if (d <= 0.0) return 0.0;
  if (d <= delta1_) return ellipticHertzForce(p_.effectiveModulus, r_.Rc, d, h_.gamma);
  const double H = p_.hardness, ch = p_.meanPressureFactor;
  if (d >= delta2_) return loadingArea(d) * ch * H;  // Eq. 43
  const double weight = (std::log(delta2_) - std::log(d)) / (std::log(delta2_) - std::log(delta1_));
  return loadingArea(d) * (ch * H - H * (ch - 2.0 / 3.0 * p_.maxPressureFactor) * weight);  // Eq. 45
}

JamariElasticPlastic::Point JamariElasticPlastic::at(double d, double maxOverlap) const {
  if (d >= maxOverlap) return {loadingForce(d), loadingArea(d)};
  const double Fm = loadingForce(maxOverlap), Am = loadingArea(maxOverlap);
  const double elastic = 3.0 * Fm / (4.0 * p_.effectiveModulus * h_.gamma * std::sqrt(Am / (pi * h_.beta)));
  const double x = (d - (maxOverlap - elastic)) / elastic;
  if (x <= 0.0) return {0.0, 0.0};
  return {Fm * x * std::sqrt(x), Am * x};
}

JamariLaw JamariLaw::read(const LawInput& in, const PairElasticity& pair) {
  if (pair.stiffnessScale != 1.0) in.fail("", "jamari takes no reduced_stiffness (no published rule for plastic contacts)");
  JamariParameters p;
  p.hardness = in.positive("hardness", "Pa, H");
  p.maxPressureFactor = in.positive("max_pressure_factor", "-, K_v", 0.454 + 0.41 * pair.poissonRatio);
  p.meanPressureFactor = in.positive("mean_pressure_factor", "-, c_h", 1.0);
  p.plasticOverlapFactor = in.positive("plastic_overlap_factor", "-, c_A", 220.0);
  if (!(p.plasticOverlapFactor > 2.0)) in.fail("plastic_overlap_factor", "must be > 2 (delta_2 > delta_1 for a circle, 004 Eq. 44)");
  return {p};
}

NormalResponse JamariLaw::force(const NormalContact& c, double overlap, History& h) const {
  if (!(overlap > 0.0)) return {.acting = false};
  const JamariElasticPlastic law = at(c);
  const bool loading = overlap >= h.maxOverlap;
  const JamariElasticPlastic::Point point = law.at(overlap, h.maxOverlap);
  if (loading) h.maxOverlap = overlap;
  const char* regime = !loading ? "unloading" : overlap <= law.yieldOverlap() ? "elastic"
                       : overlap < law.fullyPlasticOverlap() ? "elastic-plastic" : "fully plastic";
  return {.force = point.force, .stiffness = 2.0 * c.effectiveModulus * std::sqrt(point.area / pi), .area = point.area,
          .yielded = h.maxOverlap > law.yieldOverlap(), .regime = regime};
}

}  // namespace sqdem
