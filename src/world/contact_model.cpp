#include "sqdem/world/contact_model.hpp"

#include "sqdem/mechanics/becker_kamlah.hpp"
#include "sqdem/mechanics/haervig.hpp"
#include "sqdem/mechanics/mindlin_deresiewicz.hpp"

#include <cmath>
#include <numbers>
#include <optional>

namespace sqdem {

ContactForce contactForce(const ContactModel& model, const ContactGeometry& geometry,
                          const ContactKinematics& motion, ContactHistory& history, double dt) {
  const double delta = geometry.overlap;
  const Vec3& n = geometry.normal;
  double Rc, gamma, beta;
  HertzFactors f;
  RelativeRadii radii;
  if (model.usesCurvatures()) {
    const double reference = motion.volumeRadiusB > 0.0 ? std::sqrt(motion.volumeRadiusA * motion.volumeRadiusB)
                                                        : motion.volumeRadiusA;
    radii = relativeRadii(geometry.curvatureA, geometry.curvatureB, model.capFactor * reference);
    f = hertzFactors(radii.ratio(), model.eccentricity);
    Rc = radii.Rc;
    gamma = f.gamma;
    beta = f.beta;
  } else {
    const double Rstar = motion.volumeRadiusB > 0.0 ? motion.volumeRadiusA * motion.volumeRadiusB /
                                                          (motion.volumeRadiusA + motion.volumeRadiusB)
                                                    : motion.volumeRadiusA;
    Rc = 0.5 * Rstar;
    gamma = std::numbers::sqrt2;
    beta = 2.0;
  }
  const double sqrtDelta = std::sqrt(delta);
  // Adhesion: Haervig's simplified JKR on the Hertz-equivalent sphere R* = gamma^2 Rc.
  std::optional<HaervigJkr> jkr;
  if (model.surfaceEnergy > 0.0) jkr.emplace(model.effectiveModulus, model.surfaceEnergy, gamma * gamma * Rc);
  double elastic, area = std::numbers::pi * Rc * beta * delta;
  if (model.normal == NormalLaw::BeckerKamlah) {
    BeckerKamlahParameters p{.effectiveModulus = model.effectiveModulus, .yieldStrength = model.yieldStrength,
                             .lambdaMax = model.lambdaMax, .epsilonMax = model.epsilonMax,
                             .transition = model.plasticTransition};
    const BeckerFactors geometryFactors = beckerFactors(radii);
    if (p.transition && p.lambdaMax == 0.0) {
      const double rIJ = motion.volumeRadiusA + (motion.volumeRadiusB > 0.0 ? motion.volumeRadiusB : motion.volumeRadiusA);
      const BeckerKamlahFits fits = nmcBeckerKamlahFits(geometryFactors.Re, rIJ);
      p.lambdaMax = fits.lambdaMax;
      p.epsilonMax = fits.epsilonMax;
    }
    BeckerKamlahHistory plastic{history.maxOverlap};
    const BeckerKamlahState state = BeckerKamlah(geometryFactors, p).evaluate(delta, plastic);
    history.maxOverlap = plastic.maxOverlap;
    elastic = state.force;
    area = std::numbers::pi * state.contactRadius * state.contactRadius;
  } else {
    elastic = jkr ? jkr->normalForce(delta) : 4.0 / 3.0 * model.effectiveModulus * std::sqrt(Rc) * gamma * delta * sqrtDelta;
  }
  const double Sn = 2.0 * model.effectiveModulus * gamma * std::sqrt(Rc) * sqrtDelta;  // dF/d(delta)
  const double dampingScale = 2.0 * std::sqrt(5.0 / 6.0) * model.dampingRatio;
  const double normalRate = -motion.relativeVelocity.dot(n);  // > 0 approaching
  const double Fn = elastic + dampingScale * std::sqrt(motion.effectiveMass * Sn) * normalRate;

  ContactForce out;
  out.normal = Fn;
  out.area = area;
  out.onB = Fn * n;
  if (model.friction <= 0.0) return out;

  // Tangential spring: keep it in the current tangent plane with its length, then add v_t dt.
  const Vec3 vt = motion.relativeVelocity - motion.relativeVelocity.dot(n) * n;
  Vec3& spring = history.spring;
  const double length = spring.norm();
  spring -= spring.dot(n) * n;
  const double projected = spring.norm();
  if (projected > 0.0) spring *= length / projected;
  spring += vt * dt;
  // Stiffness along the contact ellipse's major axis u and minor axis v (circle: k_u = k_v).
  Vec3 u, v;
  double ku, kv;
  if (model.tangential == TangentialLaw::EllipticMindlin && model.usesCurvatures()) {
    u = contactMajorAxis(geometry.curvatureA, geometry.curvatureB, n);
    const double scale = 8.0 * model.effectiveShear * contactSemiMajorAxis(out.area, f.e2);
    const MindlinPhi phi = mindlinPhi(f.K, f.D, model.poissonRatio);
    ku = scale / phi.major;
    kv = scale / phi.minor;
  } else {
    u = n.unitOrthogonal();
    ku = kv = 8.0 * model.effectiveShear * std::sqrt(out.area / std::numbers::pi);
  }
  v = n.cross(u);
  const double etaU = dampingScale * std::sqrt(motion.effectiveMass * ku);
  const double etaV = dampingScale * std::sqrt(motion.effectiveMass * kv);
  const double xu = spring.dot(u), xv = spring.dot(v), vu = vt.dot(u), vv = vt.dot(v);
  Vec3 Ft = -(ku * xu + etaU * vu) * u - (kv * xv + etaV * vv) * v;  // on B
  const double limit = model.friction * (jkr ? std::abs(Fn + 2.0 * jkr->criticalForce()) : std::max(Fn, 0.0));
  if (Ft.norm() > limit) {
    // Slip: the spring shrinks to what carries the Coulomb force.
    Ft *= limit / Ft.norm();
    spring = ku > 0.0 && kv > 0.0 ? Vec3(-(Ft.dot(u) + etaU * vu) / ku * u - (Ft.dot(v) + etaV * vv) / kv * v) : Vec3::Zero();
  }
  out.onB += Ft;
  return out;
}

}  // namespace sqdem
