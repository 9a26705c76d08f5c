#pragma once
// Normal contact laws behind one interface for the single-contact driver (`sqdem contact`):
// each is built once from the contact's relative radii (the laws' undeformed-curvature
// assumption) and then evaluated along a prescribed overlap history, keeping its own history.

#include <memory>
#include <optional>
#include <string>

#include "json_input.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem::cli {

struct LawSample {
  double force = 0.0;                ///< normal force (N), > 0 repulsive
  std::optional<double> area;        ///< contact area (m^2), where the law defines one
  const char* regime = "separated";  ///< branch / regime name
};

/// A reference point for normalised plots: (delta_Y, F_pY) or (alpha_y, f_y).
struct YieldPoint {
  double overlap = 0.0;  ///< (m)
  double force = 0.0;    ///< (N)
};

class DrivenLaw {
 public:
  virtual ~DrivenLaw() = default;
  /// Next point of the history (overlap in m).
  virtual LawSample at(double overlap) = 0;
  virtual std::optional<YieldPoint> yield() const { return std::nullopt; }
  /// Law constants worth reporting (pull-off force, l_max, ...), as a JSON object.
  virtual json constants() const { return json::object(); }
  /// Laws without adhesion can drive the Mindlin-Deresiewicz tangential law.
  virtual bool adhesive() const { return false; }
};

/// Materials of the two bodies (Pa, -).
struct ContactMaterials {
  double youngsA, poissonA, youngsB, poissonB;
  double effectiveModulus() const;       ///< E* (Pa)
  double effectiveShearModulus() const;  ///< G* = ((2 - nuA)/GA + (2 - nuB)/GB)^-1 (Pa)
  double meanPoisson() const { return 0.5 * (poissonA + poissonB); }
};

/// Builds the law described by `law` ({"type": ..., parameters}); `meanRadiusSum` r_IJ (m) is
/// needed only by the NMC fits of Becker-Kamlah (0 when unknown).
std::unique_ptr<DrivenLaw> makeDrivenLaw(const json& law, const std::string& where, const RelativeRadii& radii,
                                         const ContactMaterials& materials, double meanRadiusSum);

}  // namespace sqdem::cli
