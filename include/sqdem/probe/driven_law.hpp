#pragma once
// A registered normal law (law_registry.hpp) driven along a prescribed overlap history for the
// single-contact driver (`sqdem contact`): built once from the contact's relative radii (the
// laws' undeformed-curvature assumption), keeping its own history; plus what the driver reports
// of each law (its constants and yield point).

#include <optional>
#include <string>

#include "sqdem/probe/json_input.hpp"
#include "sqdem/mechanics/law_registry.hpp"

namespace sqdem::probe {

struct LawSample {
  double force = 0.0;                ///< normal force (N), > 0 repulsive
  std::optional<double> area;        ///< contact area (m^2), where the law defines one
  const char* regime = "separated";  ///< branch / regime name
  bool contact = false;              ///< the law acts (attached, or touching)
};

/// Materials of the two bodies (Pa, -).
struct ContactMaterials {
  double youngsA, poissonA, youngsB, poissonB;
  double effectiveModulus() const;       ///< E* (Pa)
  double effectiveShearModulus() const;  ///< G* = ((2 - nuA)/GA + (2 - nuB)/GB)^-1 (Pa)
  double meanPoisson() const { return 0.5 * (poissonA + poissonB); }
  /// What the law registry reads a law with (law_registry.hpp).
  PairElasticity elasticity() const { return {.effectiveModulus = effectiveModulus(), .poissonRatio = meanPoisson()}; }
};

/// What the driver asks of a curve's law: a registered law (DrivenLaw) or the boundary-element
/// reference (boundary_element_law.hpp).
class CurveLaw {
 public:
  virtual ~CurveLaw() = default;
  /// Next point of the history (overlap in m).
  virtual LawSample at(double overlap) = 0;
  /// The law's first yield (YieldingLaw): the reference point of normalised plots.
  virtual std::optional<YieldPoint> yield() const { return std::nullopt; }
  /// The law's constants at this contact, as a JSON object.
  virtual json constants() const = 0;
  /// Adhesive laws cannot drive the Mindlin-Deresiewicz tangential law.
  virtual bool adhesive() const { return false; }
  /// A normal-only law (the reference) cannot drive it either.
  virtual bool normalOnly() const { return false; }
};

class DrivenLaw final : public CurveLaw {
 public:
  /// The law described by `law` ({"type": <registered name>, "eccentricity": exact | explicit |
  /// tabulated, the law's keys}); `meanRadiusSum` r_IJ (m) is needed only by the NMC fits of
  /// Becker-Kamlah (0 when unknown).
  DrivenLaw(const json& law, const std::string& where, const RelativeRadii& radii, const ContactMaterials& materials,
            double meanRadiusSum);

  LawSample at(double overlap) override;
  std::optional<YieldPoint> yield() const override;
  /// lawConstants of the law at this contact.
  json constants() const override;
  bool adhesive() const override { return adhesive_; }

 private:
  NormalLaw law_;
  NormalContact contact_;
  NormalHistory history_;
  bool adhesive_ = false;
};

}  // namespace sqdem::probe
