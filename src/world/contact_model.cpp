#include "sqdem/world/contact_model.hpp"

#include "sqdem/mechanics/mindlin_deresiewicz.hpp"

#include <cmath>
#include <numbers>

namespace sqdem {
namespace {

/// What the normal law sees of the contact: relative radii and factors from the curvatures, or
/// the volume-equivalent spheres' circle (Ri = Rj = R*, Rc = R*/2).
NormalContact normalContact(const ContactModel& model, const ContactGeometry& geometry, const ContactKinematics& motion) {
  NormalContact c;
  c.effectiveModulus = model.effectiveModulus;
  c.radiusSum = motion.volumeRadiusA + (motion.volumeRadiusB > 0.0 ? motion.volumeRadiusB : motion.volumeRadiusA);
  if (model.usesCurvatures()) {
    const double reference = motion.volumeRadiusB > 0.0 ? std::sqrt(motion.volumeRadiusA * motion.volumeRadiusB)
                                                        : motion.volumeRadiusA;
    c.radii = relativeRadii(geometry.curvatureA, geometry.curvatureB, model.capFactor * reference);
    c.factors = hertzFactors(c.radii.ratio(), model.eccentricity);
  } else {
    const double Rstar = motion.volumeRadiusB > 0.0 ? motion.volumeRadiusA * motion.volumeRadiusB /
                                                          (motion.volumeRadiusA + motion.volumeRadiusB)
                                                    : motion.volumeRadiusA;
    c.radii = {.Ri = Rstar, .Rj = Rstar, .cosOmega = 1.0, .Rc = 0.5 * Rstar};
    c.factors = circularHertzFactors();
  }
  return c;
}

/// Keeps a history vector in the current tangent plane with its length (the contact rotates).
void keepInTangentPlane(Vec3& x, const Vec3& n) {
  const double length = x.norm();
  x -= x.dot(n) * n;
  const double projected = x.norm();
  if (projected > 0.0) x *= length / projected;
}

/// Tangential force on B (Coulomb-capped spring with damping); updates the spring.
Vec3 tangentialForce(const ContactModel& model, const ContactGeometry& geometry, const NormalContact& c,
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
    const double scale = 8.0 * model.effectiveShear * contactSemiMajorAxis(area, c.factors.e2);
    const MindlinPhi phi = mindlinPhi(c.factors.K, c.factors.D, model.poissonRatio);
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
Vec3 rollingMoment(const ContactModel& model, const NormalContact& c, double overlap, const Vec3& n,
                   const ContactKinematics& motion, const Vec3& vt, Vec3& xi, double dt) {
  const HaervigJkrLaw& law = std::get<HaervigJkrLaw>(model.normal);
  const HaervigJkr modified = law.at(c);
  const double R = c.factors.gamma * c.factors.gamma * c.radii.Rc;  // the Hertz-equivalent sphere
  const HaervigJkr real(model.realModulus, law.realSurfaceEnergy, R);
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

ContactForce contactForce(const ContactModel& model, const ContactGeometry& geometry, const ContactKinematics& motion,
                          ContactHistory& history, double dt) {
  const double delta = geometry.overlap;
  const Vec3& n = geometry.normal;
  const NormalContact c = normalContact(model, geometry, motion);
  const NormalResponse r = normalResponse(model.normal, c, delta, history.normal);
  if (!r.acting) {  // the law keeps its own record; the tangential and rolling springs end
    history.spring.setZero();
    history.rolling.setZero();
    return {.acting = false, .valid = r.valid};
  }
  const double dampingScale = 2.0 * std::sqrt(5.0 / 6.0) * model.dampingRatio;
  const double normalRate = -motion.relativeVelocity.dot(n);  // > 0 approaching
  const double damping = dampingScale * std::sqrt(motion.effectiveMass * r.stiffness) * normalRate;
  const double Fn = r.force + damping;

  ContactForce out;
  out.normal = Fn;
  out.normalDamping = damping;
  out.normalStiffness = r.stiffness;
  out.area = r.area;
  out.onB = Fn * n;
  const Vec3 vt = motion.relativeVelocity - motion.relativeVelocity.dot(n) * n;
  if (model.friction > 0.0) {
    const double limit = model.friction * (r.pullOff > 0.0 ? std::abs(Fn + 2.0 * r.pullOff) : std::max(Fn, 0.0));
    out.onB += tangentialForce(model, geometry, c, motion, vt, r.area, limit, dampingScale, history.spring, dt);
  }
  if (model.rollingHysteresis > 0.0) {
    out.momentOnB = rollingMoment(model, c, delta, n, motion, vt, history.rolling, dt);
  }
  return out;
}

}  // namespace sqdem
