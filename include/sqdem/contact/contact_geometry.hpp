#pragma once
// ContactGeometry: everything the contact laws may know about a contact (docs/architecture.md,
// "Layers": geometry and mechanics meet only here).

#include <cstdint>

#include "sqdem/geometry/curvature.hpp"
#include "sqdem/math/types.hpp"

namespace sqdem {

enum class ContactStatus : std::uint8_t {
  Converged,      ///< common-normal pair found to tolerance (overlap may be negative: a gap)
  Separated,      ///< further apart than the cut-off (culled or solved); no contact
  MaxIterations,  ///< iteration limit reached before the tolerance
  Stalled,        ///< the safeguarded Newton iteration could not reduce the residual further
  /// converged to a common-normal pair that is not the contact: on the far side of a body,
  /// deeper than the least penetration, or (apart) with a point inside the other body
  WrongBranch,
  NonFinite,      ///< a non-finite number appeared (degenerate input)
  /// Coincident centres or a centre inside the other body: no reliable common normal. The
  /// answer approximates the penetration depth of the Minkowski difference (the least support
  /// gap that descents from 22 ranked directions find): normal, overlap and support points are
  /// set, curvatures are not.
  Degenerate,
};
inline constexpr int contactStatusCount = static_cast<int>(ContactStatus::Degenerate) + 1;

/// One-line reason for a status, for logs and reports.
const char* describe(ContactStatus status);

struct ContactGeometry {
  ContactStatus status = ContactStatus::Separated;
  Vec3 pointA = Vec3::Zero();  ///< surface point of body A (world, m)
  Vec3 pointB = Vec3::Zero();  ///< surface point of body B (world, m)
  Vec3 normal = Vec3::UnitZ(); ///< unit outward normal of A at pointA, pointing towards B
  /// Overlap along the normal (m): > 0 interpenetration, < 0 the gap of a separated pair
  /// within the cut-off. For status Separated, -overlap is only a lower bound of the gap.
  double overlap = 0.0;
  PrincipalCurvatures curvatureA;  ///< principal curvatures/directions of A at pointA (world)
  PrincipalCurvatures curvatureB;  ///< principal curvatures/directions of B at pointB (world)
  Vec3 localPointA = Vec3::Zero(); ///< pointA in A's body frame (warm-start data)
  Vec3 localPointB = Vec3::Zero(); ///< pointB in B's body frame (warm-start data)
  /// The outward unit normals at localPointA and localPointB in their bodies' frames, for
  /// confirmContact: set by the pair solve when it took no Newton step (zero otherwise)
  Vec3 localNormalA = Vec3::Zero(), localNormalB = Vec3::Zero();
  int iterations = 0;              ///< Newton iterations used (0 for closed forms and culls)
  double residual = 0.0;           ///< final residual of the common-normal equations (m)

  bool converged() const { return status == ContactStatus::Converged; }
  bool touching() const { return converged() && overlap > 0.0; }
};

}  // namespace sqdem
