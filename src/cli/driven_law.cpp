#include "driven_law.hpp"

#include <cmath>
#include <numbers>

#include "sqdem/mechanics/becker_kamlah.hpp"
#include "sqdem/mechanics/jkr_elliptic.hpp"
#include "sqdem/mechanics/nan_adhesive.hpp"

namespace sqdem::cli {
namespace {

using std::numbers::pi;

double positive(const json& object, const std::string& key, const std::string& where, const char* unit) {
  const double v = number(object, key, where);
  if (!(v > 0.0)) throw InputError(where + ": '" + key + "' must be > 0 (" + unit + ")");
  return v;
}

/// 004 Eqs. 1-2 with the factors of Eqs. 11-14.
class HertzLaw final : public DrivenLaw {
 public:
  HertzLaw(double Estar, const RelativeRadii& radii, EccentricityMethod method)
      : Estar_(Estar), Rc_(radii.Rc), factors_(hertzFactors(radii.ratio(), method)) {}
  LawSample at(double overlap) override {
    if (overlap <= 0.0) return {};
    return {ellipticHertzForce(Estar_, Rc_, overlap, factors_.gamma),
            ellipticHertzArea(Rc_, overlap, factors_.beta), "elastic"};
  }
  json constants() const override { return {{"e2", factors_.e2}, {"gamma", factors_.gamma}, {"beta", factors_.beta}}; }

 private:
  double Estar_, Rc_;
  HertzFactors factors_;
};

/// 002, becker_kamlah.hpp.
class BeckerKamlahLaw final : public DrivenLaw {
 public:
  BeckerKamlahLaw(const BeckerFactors& factors, const BeckerKamlahParameters& p) : law_(factors, p), p_(p) {}
  LawSample at(double overlap) override {
    const BeckerKamlahState s = law_.evaluate(overlap, history_);
    return {s.force, pi * s.contactRadius * s.contactRadius, describe(s.regime)};
  }
  std::optional<YieldPoint> yield() const override { return YieldPoint{law_.yieldOverlap(), law_.yieldForce()}; }
  json constants() const override {
    return {{"delta_Y", law_.yieldOverlap()},     {"F_pY", law_.yieldForce()},
            {"delta_max", law_.plasticLimitOverlap()}, {"lambda_max", p_.lambdaMax},
            {"epsilon_max", p_.epsilonMax},       {"transition", p_.transition}};
  }

 private:
  BeckerKamlah law_;
  BeckerKamlahParameters p_;
  BeckerKamlahHistory history_;
};

/// 004 Eqs. 19-28 with snap-in at overlap 0 and detachment below the detachment overlap.
class JkrLaw final : public DrivenLaw {
 public:
  JkrLaw(double Estar, double W, const RelativeRadii& radii) : law_(Estar, W, radii) {}
  LawSample at(double overlap) override {
    const EllipticJkrState s = law_.evaluate(overlap, history_);
    if (!s.attached) return {};
    return {s.force, s.area, "attached"};
  }
  json constants() const override {
    return {{"pull_off_force", law_.pullOffForce()}, {"detachment_overlap", law_.detachmentOverlap()}};
  }
  bool adhesive() const override { return true; }

 private:
  EllipticJkr law_;
  JkrHistory history_;
};

/// 000, nan_adhesive.hpp; R* = gamma^2 R_c (the header's rule for non-spherical contacts).
class NanLaw final : public DrivenLaw {
 public:
  explicit NanLaw(const NanParameters& p) : law_(p) {}
  LawSample at(double overlap) override {
    const NanState s = law_.evaluate(overlap, history_);
    return {s.force, std::nullopt, describe(s.branch)};
  }
  std::optional<YieldPoint> yield() const override { return YieldPoint{law_.yieldOverlap(), law_.yieldForce()}; }
  json constants() const override {
    return {{"alpha_y", law_.yieldOverlap()}, {"f_y", law_.yieldForce()},  {"f_ce", law_.pullOffForceElastic()},
            {"k_el", law_.kEl()},             {"k_cl", law_.kCl()},          {"k_p", law_.kP()}};
  }
  bool adhesive() const override { return true; }

 private:
  NanAdhesivePlastic law_;
  NanHistory history_;
};

}  // namespace

double ContactMaterials::effectiveModulus() const {
  return sqdem::effectiveModulus(youngsA, poissonA, youngsB, poissonB);
}

double ContactMaterials::effectiveShearModulus() const {
  return sqdem::effectiveShearModulus(youngsA, poissonA, youngsB, poissonB);
}

std::unique_ptr<DrivenLaw> makeDrivenLaw(const json& law, const std::string& where, const RelativeRadii& radii,
                                         const ContactMaterials& materials, double meanRadiusSum) {
  if (!law.is_object()) throw InputError(where + " must be an object");
  const std::string type = choice(law, "type", where, {"hertz", "becker_kamlah", "jkr", "nan"});
  const double Estar = materials.effectiveModulus();
  if (type == "hertz") {
    rejectUnknownKeys(law, {"type", "eccentricity"}, where);
    const std::string method = choice(law, "eccentricity", where, {"exact", "explicit", "tabulated"}, "exact");
    const EccentricityMethod m = method == "exact"      ? EccentricityMethod::Exact
                                 : method == "explicit" ? EccentricityMethod::Explicit
                                                        : EccentricityMethod::Tabulated;
    return std::make_unique<HertzLaw>(Estar, radii, m);
  }
  if (type == "becker_kamlah") {
    rejectUnknownKeys(law, {"type", "yield_strength", "transition", "lambda_max", "epsilon_max", "exponent"}, where);
    BeckerKamlahParameters p;
    p.effectiveModulus = Estar;
    p.yieldStrength = positive(law, "yield_strength", where, "Pa");
    if (law.contains("transition")) {
      if (!law["transition"].is_boolean()) throw InputError(where + ": 'transition' must be true or false");
      p.transition = law["transition"].get<bool>();
    }
    const BeckerFactors factors = beckerFactors(radii);
    if (law.contains("lambda_max") != law.contains("epsilon_max")) {
      throw InputError(where + ": give both 'lambda_max' and 'epsilon_max', or neither (NMC fits, 002 Eq. 54)");
    }
    if (law.contains("lambda_max")) {
      p.lambdaMax = number(law, "lambda_max", where);
      p.epsilonMax = number(law, "epsilon_max", where);
      if (!(p.lambdaMax >= 1.6)) throw InputError(where + ": 'lambda_max' must be >= 1.6 (p_Y = 1.6 Y)");
      if (!(p.epsilonMax > 1.0)) throw InputError(where + ": 'epsilon_max' must be > 1");
    } else {
      if (!(meanRadiusSum > 0.0)) {
        throw InputError(where + ": the NMC fits (002 Eq. 54) need r_IJ: give the geometry as 'particles', "
                                 "or give 'lambda_max' and 'epsilon_max'");
      }
      const BeckerKamlahFits fits = nmcBeckerKamlahFits(factors.Re, meanRadiusSum);
      p.lambdaMax = fits.lambdaMax;
      p.epsilonMax = fits.epsilonMax;
    }
    p.exponent = number(law, "exponent", where, p.exponent);
    if (!(p.exponent > 0.0)) throw InputError(where + ": 'exponent' must be > 0");
    return std::make_unique<BeckerKamlahLaw>(factors, p);
  }
  if (type == "jkr") {
    rejectUnknownKeys(law, {"type", "work_of_adhesion"}, where);
    return std::make_unique<JkrLaw>(Estar, positive(law, "work_of_adhesion", where, "J/m^2"), radii);
  }
  rejectUnknownKeys(law, {"type", "work_of_adhesion", "yield_pressure", "elastic_stiffness", "plastic_stiffness"},
                    where);
  const HertzFactors f = hertzFactors(radii.ratio(), EccentricityMethod::Exact);
  NanParameters p;
  p.effectiveModulus = Estar;
  p.effectiveRadius = f.gamma * f.gamma * radii.Rc;
  p.workOfAdhesion = positive(law, "work_of_adhesion", where, "J/m^2");
  p.yieldPressure = positive(law, "yield_pressure", where, "Pa");
  p.elasticStiffness = number(law, "elastic_stiffness", where, 0.0);
  p.plasticStiffness = number(law, "plastic_stiffness", where, 0.0);
  if (p.elasticStiffness < 0.0 || p.plasticStiffness < 0.0) {
    throw InputError(where + ": stiffnesses must be >= 0 (N/m; 0 selects the default of 000 Eq. 52)");
  }
  try {
    return std::make_unique<NanLaw>(p);
  } catch (const std::invalid_argument& e) {
    throw InputError(where + ": " + e.what());
  }
}

}  // namespace sqdem::cli
