#pragma once
// The contact law of a pair of materials in the engine: a composition chosen once per pair type
// (docs/architecture.md, "Layers") and evaluated per contact from ContactGeometry and the relative motion.
//
//   normal          one registered normal law (law_registry.hpp: elliptic Hertz, volume-sphere
//                   Hertz, Greenwood-Williamson roughness, Becker-Kamlah, Haervig's simplified
//                   JKR, elliptic JKR, Nan et al., Jamari) on the contact's relative radii and
//                   elliptic Hertz factors (004 Eqs. 3-14; relative radii capped at cap R_vol_ref),
//                   or on the volume-equivalent spheres (gamma = sqrt 2, beta = 2, Rc = R*/2):
//                   rate-independent force, area, stiffness S_n, its own history
//   damping         ViscousDamping (damping.hpp, 001 Eqs. 11-13): 2 sqrt(5/6) zeta sqrt(m* S_n)
//                   d(delta)/dt with the law's S_n, zeta from the restitution e
//   tangential      MindlinSpring (mindlin_spring.hpp): elliptic or circular Mindlin no-slip
//                   stiffness (004 Eqs. 56-57) with the Coulomb cap mu F_n, or mu |F_n + 2 F_C|
//                   for an adhesive law with pull-off F_C (001 Eq. 17)
//   rolling         HaervigRollingResistance (haervig.hpp, 001 Eqs. 18-22), with haervig_jkr
//   total normal force  not clamped: near the end of a damped contact it turns slightly tensile,
//                   which the restitution relation zeta(e) of 001 Eq. 12 assumes (clamping it
//                   would raise the effective e, 0.30 -> 0.40).
// Combinations refused, each with its reason, by the law registry and the scene loader:
// roughness with the plastic laws, Haervig's or Nan's, adhesion with Jamari, rolling resistance
// without haervig_jkr, elliptic Mindlin on volume spheres.
// Units: Pa, m, kg, s, N.

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/mechanics/law_registry.hpp"
#include "sqdem/mechanics/mindlin_spring.hpp"
#include "sqdem/mechanics/parallel_bond.hpp"

#include <optional>

namespace sqdem {

struct ContactModel {
  NormalLaw normal = HertzLaw{};
  bool curvatures = true;          ///< the normal law works on the detector's curvatures
  EccentricityMethod eccentricity = EccentricityMethod::Tabulated;
  double capFactor = 10.0;         ///< relative radii capped at capFactor R_vol_ref
  /// eps of curvature_cache.hpp: the law's curvature constants are re-evaluated when a contact
  /// point has moved by eps R_vol_ref on its body or the bodies turned by eps rad against each
  /// other since; 0: every step. Default 1e-5: contact forces within 5e-5 of the exact ones on
  /// ellipsoid and n = 6 beds (bench/accuracy_bench.cpp, README "Speed, memory and accuracy").
  double curvatureTolerance = 1e-5;
  double effectiveModulus = 0.0;   ///< E* (Pa), after any reduced stiffness
  ViscousDamping damping;          ///< normal and tangential
  MindlinSpring tangential;        ///< friction 0: none; on the circle without curvatures
  std::optional<HaervigRollingResistance> rolling;  ///< with normal: haervig_jkr only
  /// The pair's bonds, where they form (World::formBonds); they act beside the contact law.
  std::optional<ParallelBond> bond;
  /// Overlaps deeper than half the smaller volume radius belong to the model (a soft filler
  /// squeezed between hard grains, scene key `deep_overlaps: expected`): counted apart
  /// (ContactStatistics::expectedDeepOverlaps), not taken for a too-large time step.
  bool deepOverlapsExpected = false;
  /// Bound of the normal law's range (m): the largest gap any of its contacts acts across
  /// (World::setContactModel sets it from the particle sizes).
  double reach = 0.0;

  bool usesCurvatures() const { return curvatures; }
};

/// What a contact remembers between steps: created at first touch, kept while the pair is
/// within the normal law's range (the law may hold it without acting, e.g. a detached contact
/// in a plastic dent), dropped when the pair leaves it.
struct ContactHistory {
  Vec3 spring = Vec3::Zero();   ///< tangential spring (m)
  Vec3 rolling = Vec3::Zero();  ///< rolling displacement xi (m)
  NormalHistory normal;         ///< the normal law's own record

  /// range(history) of the normal law (m, normal_law.hpp): infinite while an adhesive contact holds.
  double range(const ContactModel& model) const { return normalRange(model.normal, normal); }
};

/// What the law needs besides the geometry.
struct ContactKinematics {
  Vec3 relativeVelocity = Vec3::Zero();  ///< velocity of B minus A at the contact point (m/s)
  double effectiveMass = 0.0;            ///< m* (kg)
  double volumeRadiusA = 0.0;            ///< R_vol of A (m)
  double volumeRadiusB = 0.0;            ///< R_vol of B (m); 0 for a wall
  Vec3 angularVelocityA = Vec3::Zero();  ///< (rad/s)
  Vec3 angularVelocityB = Vec3::Zero();  ///< (rad/s), 0 for a wall
};

/// What the law reads of a solved contact (contact_force.hpp builds it from ContactGeometry).
struct LawGeometry {
  double overlap = 0.0;          ///< (m)
  Vec3 normal = Vec3::UnitZ();   ///< unit, A to B
  NormalContact contact;         ///< relative radii, elliptic factors, E*, r_IJ
  Vec3 majorAxis = Vec3::Zero(); ///< unit major axis of the contact ellipse (elliptic Mindlin only)
};

struct ContactForce {
  Vec3 onB = Vec3::Zero();  ///< force on B (N); A receives -onB
  double normal = 0.0;      ///< normal force magnitude (N)
  double normalDamping = 0.0;  ///< its viscous part (N): normal - normalDamping is the elastic force
  double normalStiffness = 0.0;  ///< S_n = dF/d(delta) of the elastic part (N/m), as the damping uses it
  double area = 0.0;        ///< contact area (m^2)
  bool yielded = false;     ///< NormalResponse::yielded
  Vec3 momentOnB = Vec3::Zero();  ///< pure moment on B (N m), rolling resistance; A receives -momentOnB
  bool acting = true;  ///< false: the normal law does not act (NormalResponse::acting)
  bool valid = true;   ///< false: the law has no valid form at this contact (NormalResponse::valid)
};

/// Force of a contact within the law's range (overlap > -range); its history is updated; step
/// dt (s). When the normal law does not act (not yet formed, detached, or no valid law at this
/// contact) the force is zero, `acting` false, and only the normal law's record is kept.
ContactForce contactForce(const ContactModel& model, const ContactGeometry& geometry,
                          const ContactKinematics& motion, ContactHistory& history, double dt);

}  // namespace sqdem
