#pragma once
// The force law a pair of materials/shapes uses in the engine, chosen once per pair type
// (DESIGN.md §2) and evaluated per contact from ContactGeometry and the relative motion.
//
//   normal, elliptic Hertz    F = 4/3 E* Rc^1/2 gamma delta^3/2, A = pi Rc beta delta
//                             (004 Eqs. 1-2, 11-14; relative radii capped at cap R_vol_ref)
//   normal, volume spheres    the same with the volume-equivalent spheres' R* (gamma = sqrt 2,
//                             beta = 2, Rc = R*/2): no curvature is used
//   damping                   001 Eqs. 11-13: 2 sqrt(5/6) zeta sqrt(m* S_n) d(delta)/dt with
//                             S_n = 2 E* sqrt(R_eff delta), R_eff = gamma^2 Rc (so that S_n is
//                             dF/d(delta) of the elliptic law), zeta from the restitution e
//   tangential                incremental spring xi kept in the tangent plane (rotated with the
//                             contact), F_t = -K_t xi - damping, Coulomb cap |F_t| <= mu F_n.
//     elliptic Mindlin        K_t = 8 G* a_c (u u^T / Phi(0) + v v^T / Phi(pi/2)): Mindlin's no-slip
//                             stiffness of the contact ellipse (004 Eqs. 56-57, a_c semi-major
//                             axis, u its direction, v the minor one); a force along theta from u
//                             then meets the stiffness 8 G* a_c / Phi(theta) of Eq. 56 exactly
//     circular Mindlin        K_t = 8 G* a I, a = sqrt(A/pi) (the area-equivalent circle, Phi = 1)
//                             damping per axis 2 sqrt(5/6) zeta sqrt(m* k_axis)
//                             (the partial-slip softening of 004 Eqs. 59-67 is not applied: the
//                             spring is linear up to the Coulomb limit)
//   normal, Becker-Kamlah     002's elasto-plastic law for ellipsoids (becker_kamlah.hpp) on the
//                             detector's curvatures: elastic (Eq. 10), elastic-plastic with the
//                             lambda(c) transition or elastic-fully-plastic, elastic unloading/
//                             reloading from the largest overlap reached (history, Eqs. 32-49);
//                             area pi c^2; lambda_max, eps_max explicit or from the NMC fits
//                             (Eq. 54, r_IJ = sum of the volume-equivalent radii; for a wall
//                             r_IJ = 2 r_I, the particle and its mirror image: an assumption,
//                             002 treats particle pairs only). Damping as above with the elliptic
//                             Hertz stiffness; the history is dropped when the pair separates.
//   roughness (optional)      Greenwood-Williamson (004 Eqs. 29-36) in place of the smooth elastic
//                             force: F = 4/3 N A_n E* Rc^1/2 sigma^3/2 gamma F_3/2(h), area
//                             pi N A_n Rc sigma beta F_1(h), h = -delta/sigma the standardised
//                             separation of the mean surfaces (the detector's overlap, < 0 for a
//                             gap), Rc, gamma, beta of the particles' elliptic contact as 004
//                             prescribes after Eq. 34; the force acts from a gap of 4 sigma
//                             (F_3/2(4)/F_3/2(0) = 1.0e-5), damping with S_n = dF/d(delta).
//   adhesion (optional)       Haervig's simplified JKR (001 Eqs. 7-10) in place of the elastic
//                             Hertz term, on the Hertz-equivalent sphere R* = gamma^2 Rc; the
//                             contact acts for overlap > 0 only (the simplified model breaks at
//                             delta = 0), the Coulomb cap becomes mu |F_n + 2 F_C| (001 Eq. 17)
//   rolling (optional, with   Dominik-Tielens/Krijt rolling resistance as in Haervig (001 Eqs.
//   adhesion)                 18-22): rolling displacement xi integrated from
//                             v_L = R (w_A - w_B) x n + 1/2 (r_A - r_B)/(r_A + r_B) v_S (Eq. 20;
//                             n from A to B, v_S the sliding velocity of A relative to B, R the
//                             Hertz-equivalent radius, r_k volume radii, r_B -> inf for a wall),
//                             kept in the tangent plane, truncated at |xi| <= xi_crit =
//                             a_0/12 (dgamma/gamma) (Eqs. 18, 22); moment on A -k_r n x xi,
//                             k_r = 4 F_C (a/a_0)^3/2 (Eq. 21). With reduced stiffness F_C and
//                             xi_crit use the real E* and gamma, a/a_0 the modified contact
//                             (001 Section 3.2).
//   total normal force        not clamped: near the end of a damped contact it turns slightly
//                             tensile, which the restitution relation zeta(e) of 001 Eq. 12
//                             assumes (clamping it would raise the effective e, 0.30 -> 0.40).
// Units: Pa, m, kg, s, N.

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

enum class NormalLaw { EllipticHertz, VolumeSphereHertz, BeckerKamlah };
enum class TangentialLaw { EllipticMindlin, CircularMindlin };

struct ContactModel {
  NormalLaw normal = NormalLaw::EllipticHertz;
  /// Elliptic needs the ellipse of the elliptic Hertz law; with volume spheres it is the circle.
  TangentialLaw tangential = TangentialLaw::EllipticMindlin;
  EccentricityMethod eccentricity = EccentricityMethod::Tabulated;
  double capFactor = 10.0;         ///< relative radii capped at capFactor R_vol_ref
  double effectiveModulus = 0.0;   ///< E* (Pa)
  double effectiveShear = 0.0;     ///< G* = ((2 - nuA)/GA + (2 - nuB)/GB)^-1 (Pa)
  double poissonRatio = 0.0;       ///< nu of Eq. 57: the mean of the two materials' (-)
  double friction = 0.0;           ///< mu (-)
  double dampingRatio = 0.0;       ///< zeta(e) (-), 0 for e = 1
  double surfaceEnergy = 0.0;      ///< gamma (J/m^2), W = 2 gamma; > 0 adds JKR adhesion
  // Becker-Kamlah only:
  double yieldStrength = 0.0;      ///< Y (Pa), yield strength in simple tension
  bool plasticTransition = true;   ///< false: elastic - fully plastic (002 Eq. 24)
  double lambdaMax = 0.0;          ///< l_max (-); 0: NMC fit (002 Eq. 54)
  double epsilonMax = 0.0;         ///< e_max (-); 0: NMC fit (002 Eq. 54)

  // Greenwood-Williamson roughness: sigma = 0 = smooth.
  double roughnessSigma = 0.0;     ///< sigma_s, standard deviation of asperity heights (m)
  double asperityCount = 0.0;      ///< N A_n, asperities on the nominal contact area (-)
  // Rolling resistance (needs adhesion): 0 = off.
  double rollingHysteresis = 0.0;  ///< dgamma/gamma (-), Eq. 18
  double realModulus = 0.0;        ///< E* of the unreduced material (Pa), for F_C and xi_crit
  double realSurfaceEnergy = 0.0;  ///< gamma of the unreduced material (J/m^2)

  /// Largest gap (m) at which the law still acts: 4 sigma for rough contacts, else 0.
  double range() const { return 4.0 * roughnessSigma; }
  /// True for laws whose elliptic contact needs the detector's curvatures.
  bool usesCurvatures() const { return normal != NormalLaw::VolumeSphereHertz; }
};

/// What a contact remembers between steps (kept while it touches, dropped at separation).
struct ContactHistory {
  Vec3 spring = Vec3::Zero();  ///< tangential spring (m)
  double maxOverlap = 0.0;     ///< largest overlap reached (m): the plastic state of Becker-Kamlah
  Vec3 rolling = Vec3::Zero(); ///< rolling displacement xi (m)
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
};

/// Force of a contact within the law's range (overlap > -range()); its history is updated;
/// step dt (s).
ContactForce contactForce(const ContactModel& model, const ContactGeometry& geometry,
                          const ContactKinematics& motion, ContactHistory& history, double dt);

}  // namespace sqdem
