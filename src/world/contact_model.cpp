#include "sqdem/world/contact_model.hpp"

#include "sqdem/mechanics/becker_kamlah.hpp"
#include "sqdem/mechanics/haervig.hpp"
#include "sqdem/mechanics/mindlin_deresiewicz.hpp"
#include "sqdem/mechanics/roughness_gw.hpp"

#include <cmath>
#include <numbers>
#include <optional>

namespace sqdem {
namespace {

/// The contact's Hertz description: effective radius Rc, factors gamma/beta (and e^2, K, D) and,
/// for curvature laws, the relative radii.
struct HertzContact {
  RelativeRadii radii;
  HertzFactors factors;
  double Rc = 0.0;
};

HertzContact hertzContact(const ContactModel& model, const ContactGeometry& geometry, const ContactKinematics& motion) {
  HertzContact h;
  if (model.usesCurvatures()) {
    const double reference = motion.volumeRadiusB > 0.0 ? std::sqrt(motion.volumeRadiusA * motion.volumeRadiusB)
                                                        : motion.volumeRadiusA;
    h.radii = relativeRadii(geometry.curvatureA, geometry.curvatureB, model.capFactor * reference);
    h.factors = hertzFactors(h.radii.ratio(), model.eccentricity);
    h.Rc = h.radii.Rc;
  } else {  // volume-equivalent spheres: a circle, Rc = R*/2
    const double Rstar = motion.volumeRadiusB > 0.0 ? motion.volumeRadiusA * motion.volumeRadiusB /
                                                          (motion.volumeRadiusA + motion.volumeRadiusB)
                                                    : motion.volumeRadiusA;
    h.Rc = 0.5 * Rstar;
    h.factors = circularHertzFactors();
  }
  return h;
}

/// Becker-Kamlah force and area at the overlap; updates the largest overlap.
BeckerKamlahState beckerKamlahForce(const ContactModel& model, const HertzContact& h, const ContactKinematics& motion,
                                    double overlap, double& maxOverlap) {
  BeckerKamlahParameters p{.effectiveModulus = model.effectiveModulus, .yieldStrength = model.yieldStrength,
                           .lambdaMax = model.lambdaMax, .epsilonMax = model.epsilonMax,
                           .transition = model.plasticTransition};
  const BeckerFactors geometry = beckerFactors(h.radii);
  if (p.transition && p.lambdaMax == 0.0) {
    const double rIJ = motion.volumeRadiusA + (motion.volumeRadiusB > 0.0 ? motion.volumeRadiusB : motion.volumeRadiusA);
    const BeckerKamlahFits fits = nmcBeckerKamlahFits(geometry.Re, rIJ);
    p.lambdaMax = fits.lambdaMax;
    p.epsilonMax = fits.epsilonMax;
  }
  BeckerKamlahHistory plastic{maxOverlap};
  const BeckerKamlahState state = BeckerKamlah(geometry, p).evaluate(overlap, plastic);
  maxOverlap = plastic.maxOverlap;
  return state;
}

/// Keeps a history vector in the current tangent plane with its length (the contact rotates).
void keepInTangentPlane(Vec3& x, const Vec3& n) {
  const double length = x.norm();
  x -= x.dot(n) * n;
  const double projected = x.norm();
  if (projected > 0.0) x *= length / projected;
}

/// Tangential force on B (Coulomb-capped spring with damping); updates the spring.
Vec3 tangentialForce(const ContactModel& model, const ContactGeometry& geometry, const HertzContact& h,
                     const ContactKinematics& motion, const Vec3& vt, double area, double limit, double dampingScale,
                     Vec3& spring, double dt) {
  const Vec3& n = geometry.normal;
  keepInTangentPlane(spring, n);
  spring += vt * dt;
  // Stiffness along the contact ellipse's major axis u and minor axis v (circle: k_u = k_v).
  Vec3 u;
  double ku, kv;
  if (model.tangential == TangentialLaw::EllipticMindlin && model.usesCurvatures()) {
    u = contactMajorAxis(geometry.curvatureA, geometry.curvatureB, n);
    const double scale = 8.0 * model.effectiveShear * contactSemiMajorAxis(area, h.factors.e2);
    const MindlinPhi phi = mindlinPhi(h.factors.K, h.factors.D, model.poissonRatio);
    ku = scale / phi.major;
    kv = scale / phi.minor;
  } else {
    u = n.unitOrthogonal();
    ku = kv = 8.0 * model.effectiveShear * std::sqrt(area / std::numbers::pi);
  }
  const Vec3 v = n.cross(u);
  const double etaU = dampingScale * std::sqrt(motion.effectiveMass * ku);
  const double etaV = dampingScale * std::sqrt(motion.effectiveMass * kv);
  const double vu = vt.dot(u), vv = vt.dot(v);
  Vec3 Ft = -(ku * spring.dot(u) + etaU * vu) * u - (kv * spring.dot(v) + etaV * vv) * v;
  if (Ft.norm() > limit) {
    // Slip: the spring shrinks to what carries the Coulomb force.
    Ft *= limit / Ft.norm();
    spring = ku > 0.0 && kv > 0.0 ? Vec3(-(Ft.dot(u) + etaU * vu) / ku * u - (Ft.dot(v) + etaV * vv) / kv * v) : Vec3::Zero();
  }
  return Ft;
}

/// Rolling resistance moment on B (001 Eqs. 18-22); updates the rolling displacement.
Vec3 rollingMoment(const ContactModel& model, const HaervigJkr& modified, double R, double overlap, const Vec3& n,
                   const ContactKinematics& motion, const Vec3& vt, Vec3& xi, double dt) {
  const HaervigJkr real(model.realModulus, model.realSurfaceEnergy, R);
  const HaervigRolling rolling{real.criticalForce(), real.equilibriumContactRadius() / 12.0 * model.rollingHysteresis};
  // Eq. 20; the radius ratio term tends to -1/2 for a wall (r_B -> infinity).
  const double ratio = motion.volumeRadiusB > 0.0 ? (motion.volumeRadiusA - motion.volumeRadiusB) /
                                                        (motion.volumeRadiusA + motion.volumeRadiusB)
                                                  : -1.0;
  const Vec3 slidingAB = -vt;  // A relative to B at the contact
  const Vec3 vL = R * (motion.angularVelocityA - motion.angularVelocityB).cross(n) + 0.5 * ratio * slidingAB;
  keepInTangentPlane(xi, n);
  xi += vL * dt;
  double length = xi.norm();
  const double magnitude = rolling.torque(length, modified.contactRadius(overlap) / modified.equilibriumContactRadius());
  if (length < xi.norm()) xi *= length / xi.norm();  // Eq. 22: truncated at xi_crit
  return xi.norm() > 0.0 ? Vec3(magnitude * n.cross(xi.normalized())) : Vec3::Zero();
}

}  // namespace

ContactForce contactForce(const ContactModel& model, const ContactGeometry& geometry,
                          const ContactKinematics& motion, ContactHistory& history, double dt) {
  const double delta = geometry.overlap;
  const Vec3& n = geometry.normal;
  const HertzContact h = hertzContact(model, geometry, motion);
  const double gamma = h.factors.gamma, sqrtRc = std::sqrt(h.Rc), sqrtDelta = std::sqrt(std::max(delta, 0.0));
  // Adhesion: Haervig's simplified JKR on the Hertz-equivalent sphere R* = gamma^2 Rc.
  const double Rhertz = gamma * gamma * h.Rc;
  std::optional<HaervigJkr> jkr;
  if (model.surfaceEnergy > 0.0) jkr.emplace(model.effectiveModulus, model.surfaceEnergy, Rhertz);

  double elastic, area = std::numbers::pi * h.Rc * h.factors.beta * delta;
  double Sn = 2.0 * model.effectiveModulus * gamma * sqrtRc * sqrtDelta;  // dF/d(delta) of elliptic Hertz
  if (model.normal == NormalLaw::BeckerKamlah) {
    const BeckerKamlahState state = beckerKamlahForce(model, h, motion, delta, history.maxOverlap);
    elastic = state.force;
    area = std::numbers::pi * state.contactRadius * state.contactRadius;
  } else if (model.roughnessSigma > 0.0) {
    const RoughContact rough{model.asperityCount, model.roughnessSigma};
    const double hs = -delta / model.roughnessSigma, step = 1e-4;
    elastic = rough.force(model.effectiveModulus, h.Rc, gamma, hs);
    area = rough.area(h.Rc, h.factors.beta, hs);
    Sn = (rough.force(model.effectiveModulus, h.Rc, gamma, hs - step) -
          rough.force(model.effectiveModulus, h.Rc, gamma, hs + step)) / (2.0 * step * model.roughnessSigma);
  } else {
    elastic = jkr ? jkr->normalForce(delta) : 4.0 / 3.0 * model.effectiveModulus * sqrtRc * gamma * delta * sqrtDelta;
  }
  const double dampingScale = 2.0 * std::sqrt(5.0 / 6.0) * model.dampingRatio;
  const double normalRate = -motion.relativeVelocity.dot(n);  // > 0 approaching
  const double damping = dampingScale * std::sqrt(motion.effectiveMass * Sn) * normalRate;
  const double Fn = elastic + damping;

  ContactForce out;
  out.normal = Fn;
  out.normalDamping = damping;
  out.normalStiffness = Sn;
  out.area = area;
  out.onB = Fn * n;
  const Vec3 vt = motion.relativeVelocity - motion.relativeVelocity.dot(n) * n;
  if (model.friction > 0.0) {
    const double limit = model.friction * (jkr ? std::abs(Fn + 2.0 * jkr->criticalForce()) : std::max(Fn, 0.0));
    out.onB += tangentialForce(model, geometry, h, motion, vt, area, limit, dampingScale, history.spring, dt);
  }
  if (jkr && model.rollingHysteresis > 0.0) {
    out.momentOnB = rollingMoment(model, *jkr, Rhertz, delta, n, motion, vt, history.rolling, dt);
  }
  return out;
}

}  // namespace sqdem
