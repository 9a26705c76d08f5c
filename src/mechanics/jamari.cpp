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
  if (!(p.effectiveModulus > 0) || !(p.hardness > 0) || !(p.maxPressureFactor > 0) || !(delta2_ > delta1_)) {
    throw std::invalid_argument("Jamari law: need E*, H, K_v > 0 and c_A large enough that delta_2 > delta_1");
  }
}

double JamariElasticPlastic::loadingForce(double d) const {
  if (d <= 0.0) return 0.0;
  if (d <= delta1_) return ellipticHertzForce(p_.effectiveModulus, r_.Rc, d, h_.gamma);
  const double plasticArea = 2.0 * pi * std::sqrt(r_.Ri * r_.Rj) * d;
  if (d >= delta2_) return plasticArea * p_.meanPressureFactor * p_.hardness;  // Eq. 43
  const double x = (d - delta1_) / (delta2_ - delta1_);
  const double elasticArea = pi * r_.Rc * d * h_.beta;
  const double area = elasticArea + (plasticArea - elasticArea) * (3.0 * x * x - 2.0 * x * x * x);  // Eq. 46
  const double H = p_.hardness, ch = p_.meanPressureFactor;
  const double weight = (std::log(delta2_) - std::log(d)) / (std::log(delta2_) - std::log(delta1_));
  return area * (ch * H - H * (ch - 2.0 / 3.0 * p_.maxPressureFactor) * weight);  // Eq. 45
}

}  // namespace sqdem
