#include "sqdem/mechanics/becker_kamlah.hpp"

#include <cmath>
#include <limits>
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
  if (history.maxOverlap <= deltaY_) {  // never yielded: Hertz both ways
    s.force = hertz(g_.Re, overlap);
    s.contactRadius = overlap > 0.0 ? std::sqrt(squaredContactRadius(overlap)) : 0.0;
    s.regime = overlap > 0.0 ? PlasticRegime::Unloading : PlasticRegime::Separated;
    return s;
  }
  const BeckerKamlahDent dent = dentAfter(history.maxOverlap);
  s.plasticOverlap = dent.plasticOverlap;
  const double elastic = overlap - s.plasticOverlap;
  if (elastic <= 0.0) return s;
  s.force = hertz(dent.radius, elastic);                                                       // Eq. 49
  s.contactRadius = std::sqrt(dent.radius * elastic * g_.f1 * g_.f1 / g_.f2);
  s.regime = PlasticRegime::Unloading;
  return s;
}

BeckerKamlahDent BeckerKamlah::dentAfter(double deltaStar) const {
  if (deltaStar <= deltaY_) return {g_.Re, 0.0};
  const double fStarPY = pi * pY_ * (squaredContactRadius(deltaStar) - cY_ * cY_) + forceY_;  // Eq. 24
  const double ReP = 4.0 * p_.effectiveModulus / (3.0 * fStarPY) *
                     std::pow((fStarPY + 0.5 * forceY_) / (pi * pY_), 1.5) /
                     (g_.f1 * g_.f1 * g_.f1);                                                  // Eq. 44
  const double beta = loadingForce(deltaStar) / fStarPY;                                      // Eq. 46
  return {beta * beta * ReP, deltaStar * (1.0 - g_.Re / ReP)};                                // Eqs. 48, 34
}

double BeckerKamlah::hertzSphereRadius(double Re) const { return Re / (g_.f2 * g_.f2 * g_.f2); }

BeckerKamlahLaw BeckerKamlahLaw::read(const LawInput& in, const PairElasticity& pair) {
  if (pair.stiffnessScale != 1.0) in.fail("", "becker_kamlah takes no reduced_stiffness (no published rule for plastic contacts)");
  BeckerKamlahParameters p;
  p.yieldStrength = in.positive("yield_strength", "Pa, yield strength in simple tension", pair.yieldStrength);
  if (!(p.yieldStrength > 0.0)) in.fail("", "becker_kamlah needs yield_strength (Pa): give it here or in both materials");
  if (in.has("plastic_transition")) p.transition = in.flag("plastic_transition");
  if (in.has("lambda_max") != in.has("epsilon_max")) {
    in.fail("", "give both lambda_max and epsilon_max, or neither (NMC fits, 002 Eq. 54)");
  }
  if (in.has("lambda_max")) {
    p.lambdaMax = in.number("lambda_max");
    p.epsilonMax = in.number("epsilon_max");
    if (!(p.lambdaMax >= 1.6)) in.fail("lambda_max", "must be >= 1.6 (p_Y = 1.6 Y)");
    if (!(p.epsilonMax > 1.0)) in.fail("epsilon_max", "must be > 1");
  } else {
    p.epsilonMax = 0.0;  // 0: the fits, per contact
  }
  p.exponent = in.positive("exponent", "-, n of 002 Eq. 28", p.exponent);
  return {p, in.positive("surface_energy", "J/m^2, gamma; W = 2 gamma", 0.0)};
}

BeckerKamlahParameters BeckerKamlahLaw::at(const NormalContact& c, const BeckerFactors& geometry) const {
  BeckerKamlahParameters p = parameters;
  p.effectiveModulus = c.effectiveModulus;
  if (p.transition && p.lambdaMax == 0.0) {
    const BeckerKamlahFits fits = nmcBeckerKamlahFits(geometry.Re, c.radiusSum);
    p.lambdaMax = fits.lambdaMax;
    p.epsilonMax = fits.epsilonMax;
  }
  return p;
}

NormalResponse BeckerKamlahLaw::force(const NormalContact& c, double overlap, History& h) const {
  if (surfaceEnergy == 0.0 && !(overlap > 0.0)) return {.acting = false};
  const BeckerFactors geometry = beckerFactors(c.radii);
  const BeckerKamlah law(geometry, at(c, geometry));
  if (surfaceEnergy > 0.0) return attached(law, c, overlap, h);
  const BeckerKamlahState s = law.evaluate(overlap, h.plastic);
  return {.force = s.force,
          .stiffness = 2.0 * c.effectiveModulus * c.factors.gamma * std::sqrt(c.radii.Rc) * std::sqrt(overlap),
          .area = pi * s.contactRadius * s.contactRadius,
          .yielded = h.plastic.maxOverlap > law.yieldOverlap(),
          .regime = describe(s.regime)};
}

double BeckerKamlahLaw::storedEnergy(const NormalContact& c, double overlap, const History& h, double force) const {
  const BeckerFactors geometry = beckerFactors(c.radii);
  const BeckerKamlah law(geometry, at(c, geometry));
  return 0.4 * force * (overlap - law.dentAfter(h.plastic.maxOverlap).plasticOverlap);
}

NormalResponse BeckerKamlahLaw::attached(const BeckerKamlah& law, const NormalContact& c, double overlap, History& h) const {
  if (!h.attached && overlap < 0.0) return {.acting = false};
  const BeckerKamlahState s = law.evaluate(overlap, h.plastic);  // the plastic state
  const BeckerKamlahDent dent = law.dentAfter(h.plastic.maxOverlap);
  const CircularJkr jkr{c.effectiveModulus, 2.0 * surfaceEnergy, law.hertzSphereRadius(dent.radius)};
  const double elastic = overlap - dent.plasticOverlap;
  h.attached = h.attached ? elastic >= jkr.overlapAt(jkr.minimumContactRadius()) : elastic >= 0.0;
  if (!h.attached) return {.acting = false};
  const double a = jkr.contactRadius(elastic);
  return {.force = jkr.forceAt(a),
          .stiffness = 2.0 * c.effectiveModulus * a,
          .area = pi * a * a,
          .pullOff = jkr.pullOffForce(),
          .yielded = h.plastic.maxOverlap > law.yieldOverlap(),
          .regime = elastic >= 0.0 ? describe(s.regime) : "attached"};
}

double BeckerKamlahLaw::range(const History& h) const {
  return h.attached ? std::numeric_limits<double>::infinity() : 0.0;
}

double BeckerKamlahLaw::reach(double effectiveModulus, double R) const {
  if (surfaceEnergy == 0.0) return 0.0;
  const CircularJkr jkr{effectiveModulus, 2.0 * surfaceEnergy, R};
  return -4.0 * jkr.overlapAt(jkr.minimumContactRadius());
}

void BeckerKamlahLaw::check(const NormalContact& c) const {
  if (parameters.transition && parameters.lambdaMax == 0.0 && !(c.radiusSum > 0.0)) {
    throw std::invalid_argument("the NMC fits (002 Eq. 54) need r_IJ, the sum of the pair's volume radii: give the "
                                "geometry as 'particles', or give 'lambda_max' and 'epsilon_max'");
  }
}

YieldPoint BeckerKamlahLaw::yieldPoint(const NormalContact& c) const {
  const BeckerFactors g = beckerFactors(c.radii);
  const BeckerKamlah law(g, at(c, g));
  return {law.yieldOverlap(), law.yieldForce()};
}

std::vector<LawConstant> BeckerKamlahLaw::constants(const NormalContact& c) const {
  const BeckerFactors g = beckerFactors(c.radii);
  const BeckerKamlahParameters p = at(c, g);
  const BeckerKamlah law(g, p);
  return {{"delta_Y", law.yieldOverlap()}, {"F_pY", law.yieldForce()}, {"delta_max", law.plasticLimitOverlap()},
          {"lambda_max", p.lambdaMax},     {"epsilon_max", p.epsilonMax}};
}

}  // namespace sqdem
