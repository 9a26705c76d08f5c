#include "sqdem/mechanics/nan_adhesive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace sqdem {

using std::numbers::pi;

const char* describe(NanBranch branch) {
  switch (branch) {
    case NanBranch::Detached: return "detached";
    case NanBranch::Elastic: return "elastic";
    case NanBranch::Plastic: return "plastic";
    case NanBranch::Adhesive: return "adhesive";
  }
  return "unknown";
}

NanAdhesivePlastic::NanAdhesivePlastic(const NanParameters& p) {
  const double E = p.effectiveModulus, R = p.effectiveRadius, W = p.workOfAdhesion, py = p.yieldPressure;
  if (!(E > 0) || !(R > 0) || !(W > 0) || !(py > 0)) {
    throw std::invalid_argument("Nan law: E*, R*, work of adhesion and yield pressure must be positive");
  }
  kEl_ = p.elasticStiffness > 0 ? p.elasticStiffness : pi * R * py;  // Eq. 52
  kP_ = p.plasticStiffness > 0 ? p.plasticStiffness : kEl_;
  fCe_ = 1.5 * pi * W * R;                                           // Eq. 5
  wJkr_ = 7.09 * std::cbrt(std::pow(W, 5) * std::pow(R, 4) / (E * E));  // Eq. 37
  const double x = fCe_ * fCe_ / (kEl_ * wJkr_);
  const double kElOverKCl = 162.0 / (56.0 * x) - 17.0 / 56.0;           // Eqs. 36-38
  if (!(kElOverKCl > 0)) {
    throw std::invalid_argument("Nan law: k_el is too large for the JKR separation work (Eq. 36 gives k_cl < 0)");
  }
  kCl_ = kEl_ / kElOverKCl;
  wY_ = std::pow(pi * R * py, 5) / (60.0 * std::pow(E, 4) * R * R);     // Eq. 27
  fY_ = std::sqrt(2.0 * kEl_ * wY_);                                    // Eq. 28
  alpha0_ = 8.0 / 9.0 * fCe_ / kEl_;                                     // Eq. 6
  alphaY_ = alpha0_ + fY_ / kEl_;                                        // Eq. 29
}

NanUnloading NanAdhesivePlastic::unloadingFrom(double maxOverlap) const {
  NanUnloading u;
  const double aMax = std::max(maxOverlap, alphaY_);
  u.kE = kEl_ * std::sqrt(aMax / alphaY_);                                 // Eq. 46
  u.kC = u.kE * kCl_ / kEl_;
  u.fMax = fY_ + kP_ * (aMax - alphaY_);                                   // Eq. 10
  u.alphaP = (1.0 - kP_ / u.kE) * aMax + (kP_ * alphaY_ - fY_) / u.kE;     // Eq. 16
  const double A = 96.0 / (56.0 * u.kE / u.kC + 17.0);                     // Eq. 56
  const double ratio = u.kE / kEl_;
  u.fCp = fCe_ * 0.5 * (-A + std::sqrt(A * A + 4.0 * ratio * (A * u.alphaP / alpha0_ + 1.0)));  // Eq. 59
  u.alphaC0 = u.alphaP - 8.0 / 9.0 * u.fCp / u.kE;                         // Eq. 12
  u.alphaCp = u.alphaP - u.fCp / u.kE;                                     // Eq. 13
  u.alphaJp = u.alphaCp - 4.0 / 9.0 * u.fCp / u.kC;                        // Eq. 14
  return u;
}

NanState NanAdhesivePlastic::evaluate(double overlap, NanHistory& history) const {
  const NanUnloading u = unloadingFrom(history.maxOverlap);
  NanState s;
  if (!history.attached) {
    if (overlap < u.alphaC0) return s;  // first approach (alpha_c0 = 0) or reloading (Fig. 2d)
    history.attached = true;
  }
  if (overlap < u.alphaJp) {
    history.attached = false;
    return s;
  }
  if (overlap <= u.alphaCp) {
    s.force = -u.fCp + u.kC * (u.alphaCp - overlap);
    s.stiffness = u.kC;
    s.branch = NanBranch::Adhesive;
    return s;
  }
  const double fe = u.kE * (overlap - u.alphaP);
  const double fp = fY_ + kP_ * (overlap - alphaY_);
  s.force = std::min(fe, fp);
  // On the plastic line only at a new maximum past yield; with k_p = k_el the two lines coincide
  // below alpha_y, so comparing fe and fp would pick the label by round-off.
  s.branch = overlap > alphaY_ && overlap >= history.maxOverlap ? NanBranch::Plastic : NanBranch::Elastic;
  s.stiffness = s.branch == NanBranch::Plastic ? kP_ : u.kE;
  if (overlap > alphaY_ && overlap > history.maxOverlap) history.maxOverlap = overlap;
  return s;
}

double nanCriticalTimeStep(double mass, double stiffness) { return 2.0 * std::sqrt(mass / stiffness); }

NanAdhesiveLaw NanAdhesiveLaw::read(const LawInput& in, const PairElasticity& pair) {
  if (pair.stiffnessScale != 1.0) in.fail("", "nan_adhesive takes no reduced_stiffness (000 gives no rule for it)");
  NanAdhesiveLaw law;
  law.surfaceEnergy = in.positive("surface_energy", "J/m^2, gamma; W = 2 gamma");
  law.yieldPressure = in.positive("yield_pressure", "Pa, p_y");
  law.elasticStiffness = in.positive("elastic_stiffness", "N/m, k_el; default pi R* p_y, 000 Eq. 52", 0.0);
  law.plasticStiffness = in.positive("plastic_stiffness", "N/m, k_p; default k_el", 0.0);
  return law;
}

NanAdhesivePlastic NanAdhesiveLaw::at(const NormalContact& c) const {
  return NanAdhesivePlastic({.effectiveModulus = c.effectiveModulus,
                             .effectiveRadius = c.factors.gamma * c.factors.gamma * c.radii.Rc,
                             .workOfAdhesion = 2.0 * surfaceEnergy,
                             .yieldPressure = yieldPressure,
                             .elasticStiffness = elasticStiffness,
                             .plasticStiffness = plasticStiffness});
}

NormalResponse NanAdhesiveLaw::force(const NormalContact& c, double overlap, History& h) const {
  if (!h.attached && overlap < 0.0) return {.acting = false};
  std::optional<NanAdhesivePlastic> valid;
  try {
    valid.emplace(at(c));
  } catch (const std::invalid_argument&) {
    return {.acting = false, .valid = false};
  }
  const NanAdhesivePlastic& law = *valid;
  const NanState s = law.evaluate(overlap, h);
  if (s.branch == NanBranch::Detached) return {.acting = false};
  return {.force = s.force, .stiffness = s.stiffness, .pullOff = law.pullOffForceElastic(), .regime = describe(s.branch)};
}

double NanAdhesiveLaw::range(const History& h) const {
  return h.attached ? std::numeric_limits<double>::infinity() : 0.0;
}

double NanAdhesiveLaw::reach(double effectiveModulus, double R) const {
  const NormalContact sphere{.radii = {R, R, 1.0, 0.5 * R}, .factors = circularHertzFactors(), .effectiveModulus = effectiveModulus};
  return -2.0 * at(sphere).unloadingFrom(0.0).alphaJp;
}

}  // namespace sqdem
