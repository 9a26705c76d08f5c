#pragma once
// contactForce (contact_model.hpp) for one normal law type: the body the engine's kernels
// instantiate per law (no dispatch per contact) and the generic entry point visits.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include "sqdem/interaction/contact_model.hpp"

namespace sqdem::detail {

/// x y / (x + y): the reduced mass, radius or moment of inertia of two bodies.
inline double reduced(double x, double y) { return x * y / (x + y); }

/// E* and r_IJ of the contact (radii and factors left to the caller).
inline NormalContact sizedContact(const ContactModel& model, const ContactKinematics& motion) {
  NormalContact c;
  c.effectiveModulus = model.effectiveModulus;
  c.radiusSum = motion.volumeRadiusA + (motion.volumeRadiusB > 0.0 ? motion.volumeRadiusB : motion.volumeRadiusA);
  return c;
}

/// R* = rA rB / (rA + rB) of the volume-equivalent spheres (m; a wall: rA).
inline double reducedRadius(const ContactKinematics& motion) {
  return motion.volumeRadiusB > 0.0 ? reduced(motion.volumeRadiusA, motion.volumeRadiusB) : motion.volumeRadiusA;
}

/// A deep overlap (ContactStatistics::deepOverlaps): deeper than half the smaller volume radius
/// of the two bodies; radiusB 0 for a wall, which has none.
inline bool deepOverlap(double overlap, double radiusA, double radiusB) {
  return overlap > 0.5 * (radiusB > 0.0 ? std::min(radiusA, radiusB) : radiusA);
}

/// The contact of the volume-equivalent spheres: a circle, Ri = Rj = R*, Rc = R*/2.
inline NormalContact circularContact(const ContactModel& model, const ContactKinematics& motion) {
  NormalContact c = sizedContact(model, motion);
  const double Rstar = reducedRadius(motion);
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
/// tangential spring works on the ellipse or the true-gap law lays its plane's axes on it.
inline LawGeometry lawGeometry(const ContactModel& model, const ContactGeometry& geometry,
                               const ContactKinematics& motion) {
  LawGeometry g{geometry.overlap, geometry.normal, normalContact(model, geometry, motion), Vec3::Zero()};
  if ((model.tangential.elliptic && model.tangential.friction > 0.0) || std::holds_alternative<TrueGapLaw>(model.normal)) {
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

/// contactForce for HertzLaw on a round contact (pair_kind.hpp: the circle of R*, no curvatures):
/// with gamma = sqrt 2, beta = 2, Rc = R*/2 (004 Eqs. 1-2), a = sqrt(R* delta) is the contact
/// radius and F = 4/3 E* a delta, S_n = 2 E* a, A = pi a^2, Mindlin's circle K_t = 8 G* a; both
/// damping coefficients come from one sqrt(m* a) (ViscousDamping: scale sqrt(m k)). The same
/// forces as contactForce to round-off, with three square roots instead of six.
struct RoundHertz {
  explicit RoundHertz(const ContactModel& model)
      : rootNormal(std::sqrt(2.0 * model.effectiveModulus)), rootTangential(std::sqrt(8.0 * model.tangential.effectiveShear)) {}
  double rootNormal, rootTangential;  ///< sqrt(2 E*), sqrt(8 G*): the model's, once per group
};
[[gnu::always_inline]] inline ContactForce roundHertzForce(const ContactModel& model, const RoundHertz& roots, const ContactKinematics& motion,
                                                           double overlap, const Vec3& n, ContactHistory& history, double dt) {
  if (!(overlap > 0.0)) {  // HertzLaw does not act; the tangential spring ends
    history.spring.setZero();
    return {.acting = false};
  }
  const double a = std::sqrt(reducedRadius(motion) * overlap), E = model.effectiveModulus;
  const double rootMassRadius = model.damping.scale() * std::sqrt(motion.effectiveMass * a);
  ContactForce out;
  out.normalStiffness = 2.0 * E * a;
  out.normalDamping = rootMassRadius * roots.rootNormal * -motion.relativeVelocity.dot(n);
  out.normal = 4.0 / 3.0 * E * a * overlap + out.normalDamping;
  out.area = std::numbers::pi * a * a;
  out.onB = out.normal * n;
  const MindlinSpring& tangential = model.tangential;
  if (tangential.friction > 0.0) {
    const double G = tangential.effectiveShear;
    const Vec3 vt = motion.relativeVelocity - motion.relativeVelocity.dot(n) * n;
    out.onB += tangential.circleForce(8.0 * G * a, rootMassRadius * roots.rootTangential, n, vt,
                                      tangential.friction * std::max(out.normal, 0.0), history.spring, dt);
  }
  return out;
}

}  // namespace sqdem::detail
