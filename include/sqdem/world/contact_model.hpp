#pragma once
// The contact law of a pair of materials in the engine: a composition chosen once per pair type
// (DESIGN.md §2) and evaluated per contact from ContactGeometry and the relative motion.
//
//   normal          one registered normal law (law_registry.hpp: elliptic Hertz, volume-sphere
//                   Hertz, Greenwood-Williamson roughness, Becker-Kamlah, Haervig's simplified
//                   JKR, elliptic JKR, Nan et al., Jamari) on the contact's relative radii and
//                   elliptic Hertz factors (004 Eqs. 3-14; relative radii capped at cap R_vol_ref),
//                   or on the volume-equivalent spheres (gamma = sqrt 2, beta = 2, Rc = R*/2):
//                   rate-independent force, area, stiffness S_n, its own history
//   damping         001 Eqs. 11-13: 2 sqrt(5/6) zeta sqrt(m* S_n) d(delta)/dt with the law's S_n
//                   (the elliptic Hertz dF/d(delta) for the Hertz-type laws), zeta from the
//                   restitution e
//   tangential      incremental spring xi kept in the tangent plane (rotated with the contact),
//                   F_t = -K_t xi - damping, Coulomb cap |F_t| <= mu F_n, or mu |F_n + 2 F_C| for
//                   an adhesive law with pull-off F_C (001 Eq. 17)
//     elliptic Mindlin  K_t = 8 G* a_c (u u^T / Phi(0) + v v^T / Phi(pi/2)): Mindlin's no-slip
//                   stiffness of the contact ellipse (004 Eqs. 56-57, a_c semi-major axis from
//                   the law's area and e^2, u its direction, v the minor one); a force along theta
//                   from u then meets the stiffness 8 G* a_c / Phi(theta) of Eq. 56 exactly
//     circular Mindlin  K_t = 8 G* a I, a = sqrt(A/pi) (the area-equivalent circle, Phi = 1)
//                   damping per axis 2 sqrt(5/6) zeta sqrt(m* k_axis) (the partial-slip softening
//                   of 004 Eqs. 59-67 is not applied: the spring is linear up to the Coulomb limit)
//   rolling         Dominik-Tielens/Krijt rolling resistance as in Haervig (001 Eqs. 18-22), with
//   (haervig_jkr)   normal: haervig_jkr: rolling displacement xi integrated from
//                   v_L = R (w_A - w_B) x n + 1/2 (r_A - r_B)/(r_A + r_B) v_S (Eq. 20; n from A
//                   to B, v_S the sliding velocity of A relative to B, R the Hertz-equivalent
//                   radius, r_k volume radii, r_B -> inf for a wall), kept in the tangent plane,
//                   truncated at |xi| <= xi_crit = a_0/12 (dgamma/gamma) (Eqs. 18, 22); moment on
//                   A -k_r n x xi, k_r = 4 F_C (a/a_0)^3/2 (Eq. 21). With reduced stiffness F_C and
//                   xi_crit use the real E* and gamma, a/a_0 the modified contact (001 Section 3.2)
//   total normal force  not clamped: near the end of a damped contact it turns slightly tensile,
//                   which the restitution relation zeta(e) of 001 Eq. 12 assumes (clamping it
//                   would raise the effective e, 0.30 -> 0.40).
// Combinations refused, each with its reason, by the scene loader: roughness with a plastic or
// adhesive law, rolling resistance without haervig_jkr, elliptic Mindlin on volume spheres.
// Units: Pa, m, kg, s, N.

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/mechanics/law_registry.hpp"

namespace sqdem {

enum class TangentialLaw { EllipticMindlin, CircularMindlin };

struct ContactModel {
  NormalLaw normal = HertzLaw{};
  bool curvatures = true;          ///< the normal law works on the detector's curvatures
  /// Elliptic needs the ellipse of a curvature law; with volume spheres it is the circle.
  TangentialLaw tangential = TangentialLaw::EllipticMindlin;
  EccentricityMethod eccentricity = EccentricityMethod::Tabulated;
  double capFactor = 10.0;         ///< relative radii capped at capFactor R_vol_ref
  double effectiveModulus = 0.0;   ///< E* (Pa), after any reduced stiffness
  double effectiveShear = 0.0;     ///< G* = ((2 - nuA)/GA + (2 - nuB)/GB)^-1 (Pa)
  double poissonRatio = 0.0;       ///< nu of Eq. 57: the mean of the two materials' (-)
  double friction = 0.0;           ///< mu (-)
  double dampingRatio = 0.0;       ///< zeta(e) (-), 0 for e = 1
  // Rolling resistance (normal: haervig_jkr only): 0 = off.
  double rollingHysteresis = 0.0;  ///< dgamma/gamma (-), Eq. 18
  double realModulus = 0.0;        ///< E* of the unreduced material (Pa), for F_C and xi_crit
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

struct ContactForce {
  Vec3 onB = Vec3::Zero();  ///< force on B (N); A receives -onB
  double normal = 0.0;      ///< normal force magnitude (N)
  double normalDamping = 0.0;  ///< its viscous part (N): normal - normalDamping is the elastic force
  double normalStiffness = 0.0;  ///< S_n = dF/d(delta) of the elastic part (N/m), as the damping uses it
  double area = 0.0;        ///< contact area (m^2)
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
