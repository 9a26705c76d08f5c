#pragma once
// Becker & Kamlah's elasto-plastic normal law for two ellipsoids (002), a Thornton-type law on
// the elliptic Hertz contact of 002 Eqs. 1-10 (geometry A, B, R_e, f1, f2 in elliptic.hpp).
//
//   equivalent contact radius  c^2 = R_e delta f1^2 / f2                            (Eq. 9)
//   yield                       p_Y = 1.6 Y; c_Y = pi p_Y R_e f1^3 / (2 E*)        (Eq. 2 at p_0 = p_Y)
//                               delta_Y = c_Y^2 f2 / (R_e f1^2), F_pY = Hertz(delta_Y) (Eq. 10)
//   elastic                     F = 4/3 E* sqrt(R_e) delta^3/2 f2^-3/2              (Eq. 10)
//   elastic-plastic             F = pi lambda Y (c^2 - c_Y^2) + F_pY                (Eqs. 25-26)
//                               lambda = l_max - (l_max - 1.6) [(e_max c_Y - c)/((e_max - 1) c_Y)]^n
//                                                                      (Eq. 28, n = 1.8, c <= e_max c_Y)
//   fully plastic               F = pi l_max Y (c^2 - c_Y^2) + F_pY, delta > delta_max    (Eqs. 30-31)
//   NMC fits (Eq. 54, x = R_e / r_IJ, r_IJ = r_I + r_J with r_k = (a b c)^1/3 (Eq. 50)):
//                               l_max = 1.05 exp(-4.62 x) + 2.42, e_max = 8.19 exp(-6.14 x) + 1.14
//   unloading from delta_* > delta_Y (elastic, Eqs. 32-49):
//     F_*,pY = pi p_Y (c_*^2 - c_Y^2) + F_pY (elastic-fully-plastic force at delta_*),
//     R_e,p = 4 E* / (3 F_*,pY) ((F_*,pY + F_pY/2)/(pi p_Y))^3/2 / f1^3              (Eq. 44)
//     delta_p = delta_* (1 - R_e/R_e,p)                                               (Eq. 34)
//     beta = F(delta_*) / F_*,pY (Eq. 46 simplified with Eq. 43), R_e,pmax = beta^2 R_e,p (Eq. 48)
//     F = 4/3 E* sqrt(R_e,pmax) (delta - delta_p)^3/2 f2^-3/2, 0 below delta_p        (Eq. 49)
//   reloading follows the unloading curve back to delta_*, then the loading curve.
//
// The "elastic - fully plastic" variant (Thornton's law, 002 Fig. 5/15) drops the transition:
// lambda = 1.6 for every delta > delta_Y, i.e. Eq. 24, and beta = 1.
//
// Parameters: E* (Pa), yield strength in simple tension Y (Pa), r_IJ (m) for the fits (or
// explicit l_max, e_max). The fits are for NMC (002 Table 1) and aspect ratios 1:[0.5..2]:[0.5..2];
// contact curvature is that of the undeformed bodies (the law's assumption), so the geometry is
// computed once per contact. Finite deformations (c/r > 0.16..0.4) are outside its validity.

#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/mechanics/jkr_circular.hpp"
#include "sqdem/mechanics/law_input.hpp"
#include "sqdem/mechanics/normal_law.hpp"

namespace sqdem {

struct BeckerKamlahParameters {
  double effectiveModulus = 0.0;  ///< E* (Pa)
  double yieldStrength = 0.0;     ///< Y (Pa); p_Y = 1.6 Y
  double lambdaMax = 0.0;         ///< l_max (-), e.g. from nmcBeckerKamlahFits
  double epsilonMax = 1.0;        ///< e_max (-), c_max / c_Y
  double exponent = 1.8;          ///< n of Eq. 28
  bool transition = true;         ///< false: elastic - fully plastic (Eq. 24)
};

/// Eq. 54: l_max and e_max for NMC from R_e and r_IJ = r_I + r_J (m).
struct BeckerKamlahFits {
  double lambdaMax, epsilonMax;
};
BeckerKamlahFits nmcBeckerKamlahFits(double Re, double meanRadiusSum);

enum class PlasticRegime { Separated, Elastic, ElasticPlastic, FullyPlastic, Unloading };
const char* describe(PlasticRegime regime);

/// Per-contact history: the largest overlap ever reached (delta_*).
struct BeckerKamlahHistory {
  double maxOverlap = 0.0;
};

struct BeckerKamlahState {
  double force = 0.0;          ///< (N), >= 0
  double contactRadius = 0.0;  ///< equivalent contact radius c (m), area pi c^2
  double plasticOverlap = 0.0; ///< delta_p (m)
  PlasticRegime regime = PlasticRegime::Separated;
};

/// The elastic contact Becker-Kamlah unloads on after loading to delta_*: effective radius
/// R_e,pmax (Eq. 48; R_e before yield) and the plastic overlap delta_p (Eq. 34; 0 before yield).
struct BeckerKamlahDent {
  double radius = 0.0;          ///< (m)
  double plasticOverlap = 0.0;  ///< (m)
};

class BeckerKamlah {
 public:
  BeckerKamlah(const BeckerFactors& geometry, const BeckerKamlahParameters& parameters);

  /// Force at this overlap; updates delta_* when the overlap exceeds it.
  BeckerKamlahState evaluate(double overlap, BeckerKamlahHistory& history) const;

  double yieldOverlap() const { return deltaY_; }  ///< delta_Y (m)
  double yieldForce() const { return forceY_; }    ///< F_pY (N)
  double plasticLimitOverlap() const { return deltaMax_; }  ///< delta_max, Eq. 30 (m)

  /// Loading curve (monotonic, no history), Eqs. 10, 25-31.
  double loadingForce(double overlap) const;
  /// The elastic contact after loading to delta_* (m); at delta = delta_* its Hertz force is the
  /// loading force (Eqs. 46-49).
  BeckerKamlahDent dentAfter(double deltaStar) const;
  /// The radius of the sphere whose Hertz force equals Eq. 10 with effective radius Re:
  /// Re f2^-3 (m).
  double hertzSphereRadius(double Re) const;

 private:
  double squaredContactRadius(double overlap) const { return g_.Re * overlap * g_.f1 * g_.f1 / g_.f2; }
  /// Eq. 10 with effective radius Re (R_e loading, R_e,pmax unloading) (N).
  double hertz(double Re, double overlap) const;

  BeckerFactors g_;
  BeckerKamlahParameters p_;
  double pY_, cY_, deltaY_, forceY_, deltaMax_;
};

/// normal: becker_kamlah (normal_law.hpp component) on the detector's curvatures. Keys:
/// yield_strength Y (Pa; default the weaker material's), plastic_transition (default true),
/// lambda_max and epsilon_max (both or neither; neither: the NMC fits of Eq. 54 per contact with
/// r_IJ = NormalContact::radiusSum), exponent n of Eq. 28 (default 1.8), surface_energy gamma
/// (J/m^2, W = 2 gamma; default 0: no adhesion). Area pi c^2; S_n for the damping is the
/// elliptic Hertz stiffness 2 E* gamma (Rc delta)^1/2. History: the largest overlap.
///
/// With surface_energy: adhesion in the style of Thornton & Ning (Powder Technol. 99, 1998),
/// who unload an adhesive elastic-plastic sphere along the JKR curve of its plastically flattened
/// contact; the seeds give no adhesive law for ellipsoids. Becker-Kamlah defines at every state
/// an elastic contact whose Hertz force is the law's force: the undeformed contact before yield,
/// the flattened one (R_e,pmax, delta_p of Eqs. 34, 48; BeckerKamlahDent) after it, during
/// plastic loading (at delta = delta_*: Eqs. 46-49) and unloading alike. The adhesive law is the
/// JKR contact (jkr_circular.hpp) of the sphere with that Hertz force, R = R_e,pmax f2^-3, at the
/// elastic overlap delta - delta_p: F = 4 E* a^3/(3R) - sqrt(8 pi W E* a^3), area pi a^2,
/// S_n = 2 E* a. W -> 0 gives Becker-Kamlah's force back; before yield it is JKR. The contact
/// forms when the elastic overlap reaches 0 (the surfaces touch: delta = 0, or delta_p in a dent)
/// and detaches below JKR's displacement-controlled detachment overlap; while attached its range
/// is unbounded. History then also: attached.
struct BeckerKamlahLaw {
  struct History {
    BeckerKamlahHistory plastic;
    bool attached = false;
  };
  static constexpr std::array<std::string_view, 6> keys{"yield_strength", "plastic_transition", "lambda_max", "epsilon_max",
                                                        "exponent",       "surface_energy"};
  BeckerKamlahParameters parameters;  ///< effectiveModulus is taken from each contact
  double surfaceEnergy = 0.0;         ///< gamma (J/m^2), 0: no adhesion

  static BeckerKamlahLaw read(const LawInput& in, const PairElasticity& pair);
  /// The parameters at this contact: E*, and l_max, e_max from the NMC fits when not given.
  BeckerKamlahParameters at(const NormalContact& c, const BeckerFactors& geometry) const;
  NormalResponse force(const NormalContact& c, double overlap, History& h) const;
  /// Without adhesion: the contact unloads along the Hertz curve of its dent (Eq. 49; at
  /// delta = delta_* also while it yields), whose integral from delta_p is 2/5 F (delta -
  /// delta_p) (J); what the dent took beyond that is dissipated.
  bool storesEnergy() const { return surfaceEnergy == 0.0; }
  double storedEnergy(const NormalContact& c, double overlap, const History& h, double force) const;
  double range(const History& h) const;
  /// With adhesion: 4 |delta_d| of the JKR contact of radius R, covering dents of radius up to
  /// 64 R (delta_d ~ R^1/3); else 0.
  double reach(double effectiveModulus, double R) const;
  bool adhesive() const { return surfaceEnergy > 0.0; }
  /// The NMC fits (002 Eq. 54) need the contact's r_IJ.
  void check(const NormalContact& c) const;
  /// (delta_Y, F_pY) at this contact.
  YieldPoint yieldPoint(const NormalContact& c) const;
  /// delta_Y, F_pY, delta_max, lambda_max, epsilon_max at this contact.
  std::vector<LawConstant> constants(const NormalContact& c) const;

 private:
  NormalResponse attached(const BeckerKamlah& law, const NormalContact& c, double overlap, History& h) const;
};

}  // namespace sqdem
