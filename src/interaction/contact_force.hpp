#pragma once
// contactForce (contact_model.hpp) for one normal law type: the body the engine's kernels
// instantiate per law (no dispatch per contact) and the generic entry point visits.

#include <cmath>
#include <variant>

#include "sqdem/interaction/contact_model.hpp"

namespace sqdem::detail {

/// E* and r_IJ of the contact (radii and factors left to the caller).
inline NormalContact sizedContact(const ContactModel& model, const ContactKinematics& motion) {
  NormalContact c;
  c.effectiveModulus = model.effectiveModulus;
  c.radiusSum = motion.volumeRadiusA + (motion.volumeRadiusB > 0.0 ? motion.volumeRadiusB : motion.volumeRadiusA);
  return c;
}

/// The contact of the volume-equivalent spheres: a circle, Ri = Rj = R*, Rc = R*/2.
inline NormalContact circularContact(const ContactModel& model, const ContactKinematics& motion) {
  NormalContact c = sizedContact(model, motion);
  const double Rstar = motion.volumeRadiusB > 0.0
                           ? motion.volumeRadiusA * motion.volumeRadiusB / (motion.volumeRadiusA + motion.volumeRadiusB)
                           : motion.volumeRadiusA;
  c.radii = {.Ri = Rstar, .Rj = Rstar, .cosOmega = 1.0, .Rc = 0.5 * Rstar};
  c.factors = circularHertzFactors();
  return c;
}

/// What the normal law sees of the contact: relative radii and factors from the curvatures, or
/// the volume-equivalent spheres' circle.
inline NormalContact normalContact(const ContactModel& model, const ContactGeometry& geometry,
                                   const ContactKinematics& motion) {
  if (!model.usesCurvatures()) return circularContact(model, motion);
  NormalContact c = sizedContact(model, motion);
  const double reference = motion.volumeRadiusB > 0.0 ? std::sqrt(motion.volumeRadiusA * motion.volumeRadiusB)
                                                      : motion.volumeRadiusA;
  c.radii = relativeRadii(geometry.curvatureA, geometry.curvatureB, model.capFactor * reference);
  c.factors = hertzFactors(c.radii.ratio(), model.eccentricity);
  return c;
}

/// The law's view of a solved contact: its radii and factors, and the major axis when the
/// tangential spring works on the ellipse.
inline LawGeometry lawGeometry(const ContactModel& model, const ContactGeometry& geometry,
                               const ContactKinematics& motion) {
  LawGeometry g{geometry.overlap, geometry.normal, normalContact(model, geometry, motion), Vec3::Zero()};
  if (model.tangential.elliptic && model.tangential.friction > 0.0) {
    g.majorAxis = contactMajorAxis(geometry.curvatureA, geometry.curvatureB, geometry.normal);
  }
  return g;
}

template <NormalLawComponent Law>
[[gnu::always_inline]] inline ContactForce contactForce(const ContactModel& model, const Law& law, const LawGeometry& geometry,
                          const ContactKinematics& motion, ContactHistory& history, double dt) {
  const double delta = geometry.overlap;
  const Vec3& n = geometry.normal;
  const NormalContact& c = geometry.contact;
  const NormalResponse r = normalResponse(law, c, delta, history.normal);
  if (!r.acting) {  // the law keeps its own record; the tangential and rolling springs end
    history.spring.setZero();
    history.rolling.setZero();
    return {.acting = false, .valid = r.valid};
  }
  const double normalRate = -motion.relativeVelocity.dot(n);  // > 0 approaching
  const double damping = model.damping.coefficient(motion.effectiveMass, r.stiffness) * normalRate;
  const double Fn = r.force + damping;

  ContactForce out;
  out.normal = Fn;
  out.normalDamping = damping;
  out.normalStiffness = r.stiffness;
  out.area = r.area;
  out.yielded = r.yielded;
  out.onB = Fn * n;
  const Vec3 vt = motion.relativeVelocity - motion.relativeVelocity.dot(n) * n;
  const MindlinSpring& tangential = model.tangential;
  if (tangential.friction > 0.0) {
    const double limit = tangential.friction * (r.pullOff > 0.0 ? std::abs(Fn + 2.0 * r.pullOff) : std::max(Fn, 0.0));
    out.onB += tangential.force(c, geometry.majorAxis, n, r.area, vt, limit, model.damping, motion.effectiveMass,
                                history.spring, dt);
  }
  if constexpr (std::is_same_v<Law, HaervigJkrLaw>) {
    if (model.rolling) {
      out.momentOnB = model.rolling->moment(law, c, delta, n, vt, motion.volumeRadiusA, motion.volumeRadiusB,
                                            motion.angularVelocityA, motion.angularVelocityB, history.rolling, dt);
    }
  }
  return out;
}

}  // namespace sqdem::detail
