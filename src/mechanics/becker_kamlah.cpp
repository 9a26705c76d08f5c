#include "sqdem/mechanics/becker_kamlah.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sqdem {

using std::numbers::pi;

BeckerKamlahFits nmcBeckerKamlahFits(double Re, double meanRadiusSum) {
  const double x = Re / meanRadiusSum;
  return {1.05 * std::exp(-4.62 * x) + 2.42, 8.19 * std::exp(-6.14 * x) + 1.14};
}

const char* describe(PlasticRegime regime) {
  switch (regime) {
    case PlasticRegime::Separated: return "separated";
    case PlasticRegime::Elastic: return "elastic";
    case PlasticRegime::ElasticPlastic: return "elastic-plastic";
    case PlasticRegime::FullyPlastic: return "fully-plastic";
    case PlasticRegime::Unloading: return "unloading";
  }
  return "unknown";
}

BeckerKamlah::BeckerKamlah(const BeckerFactors& geometry, const BeckerKamlahParameters& parameters)
    : g_(geometry), p_(parameters) {
  if (!(p_.effectiveModulus > 0.0) || !(p_.yieldStrength > 0.0)) {
    throw std::invalid_argument("Becker-Kamlah law: E* and Y must be positive");
  }
  if (p_.transition && !(p_.lambdaMax >= 1.6 && p_.epsilonMax > 1.0 && p_.exponent > 0.0)) {
    throw std::invalid_argument("Becker-Kamlah law: need lambdaMax >= 1.6, epsilonMax > 1, exponent > 0");
  }
  pY_ = 1.6 * p_.yieldStrength;
  cY_ = pi * pY_ * g_.Re * g_.f1 * g_.f1 * g_.f1 / (2.0 * p_.effectiveModulus);
  deltaY_ = cY_ * cY_ * g_.f2 / (g_.Re * g_.f1 * g_.f1);
  forceY_ = hertz(g_.Re, deltaY_);
  deltaMax_ = p_.transition ? p_.epsilonMax * p_.epsilonMax * deltaY_ : deltaY_;
}

double BeckerKamlah::hertz(double Re, double overlap) const {
  BeckerFactors g = g_;
  g.Re = Re;
  return beckerHertzForce(p_.effectiveModulus, g, overlap);
}

double BeckerKamlah::loadingForce(double overlap) const {
  if (overlap <= deltaY_) return hertz(g_.Re, overlap);
  const double c2 = squaredContactRadius(overlap);
  double lambda = 1.6;
  if (p_.transition) {
    lambda = p_.lambdaMax;
    if (overlap < deltaMax_) {
      const double c = std::sqrt(c2);
      const double s = (p_.epsilonMax * cY_ - c) / ((p_.epsilonMax - 1.0) * cY_);
      lambda -= (p_.lambdaMax - 1.6) * std::pow(s, p_.exponent);
    }
  }
  return pi * lambda * p_.yieldStrength * (c2 - cY_ * cY_) + forceY_;
}

BeckerKamlahState BeckerKamlah::evaluate(double overlap, BeckerKamlahHistory& history) const {
  BeckerKamlahState s;
  if (overlap >= history.maxOverlap) {  // (first) loading
    history.maxOverlap = overlap;
    if (overlap <= 0.0) return s;
    s.force = loadingForce(overlap);
    s.contactRadius = std::sqrt(squaredContactRadius(overlap));
    s.regime = overlap <= deltaY_ ? PlasticRegime::Elastic
               : overlap < deltaMax_ ? PlasticRegime::ElasticPlastic
                                     : PlasticRegime::FullyPlastic;
    return s;
  }
  const double deltaStar = history.maxOverlap;
  if (deltaStar <= deltaY_) {  // never yielded: Hertz both ways
    s.force = hertz(g_.Re, overlap);
    s.contactRadius = overlap > 0.0 ? std::sqrt(squaredContactRadius(overlap)) : 0.0;
    s.regime = overlap > 0.0 ? PlasticRegime::Unloading : PlasticRegime::Separated;
    return s;
  }
  const double fStarPY = pi * pY_ * (squaredContactRadius(deltaStar) - cY_ * cY_) + forceY_;  // Eq. 24
  const double ReP = 4.0 * p_.effectiveModulus / (3.0 * fStarPY) *
                     std::pow((fStarPY + 0.5 * forceY_) / (pi * pY_), 1.5) /
                     (g_.f1 * g_.f1 * g_.f1);                                                  // Eq. 44
  const double beta = loadingForce(deltaStar) / fStarPY;                                      // Eq. 46
  const double RePMax = beta * beta * ReP;                                                     // Eq. 48
  s.plasticOverlap = deltaStar * (1.0 - g_.Re / ReP);                                         // Eq. 34
  const double elastic = overlap - s.plasticOverlap;
  if (elastic <= 0.0) return s;
  s.force = hertz(RePMax, elastic);                                                            // Eq. 49
  s.contactRadius = std::sqrt(RePMax * elastic * g_.f1 * g_.f1 / g_.f2);
  s.regime = PlasticRegime::Unloading;
  return s;
}

}  // namespace sqdem
