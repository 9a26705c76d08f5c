#pragma once
// The true gap of two posed superquadrics (docs/contact_laws.md, "The true gap"): the distance
// between their undeformed surfaces over the common tangent plane at the detector's contact, at
// the pose where they just touch.
//
// The plane: through the midpoint of the two contact points, normal n (A towards B), its axes
// t1 along the contact ellipse's major axis (mechanics/elliptic.hpp) and t2 = n x t1. Above the
// plane point q, the gap is the distance along n from A's top to B's bottom
// (contact/surface_along_line.hpp), plus the detector's overlap: B moved back along n until the
// bodies just touch (a translation along n shifts the gap uniformly). The gap is convex on the
// plane (each body's height over it is concave), 0 at the contact and +infinity where a line
// misses a body. Half-space theory takes both surfaces as flat on the contact's scale: the
// small-slope approximation of every Hertz-type law.

#include <limits>

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {

/// t1 laid on the plane normal to n (unit), or any tangent where it has no part there (a cache
/// that kept no major axis): the gap's axis t1 (below).
Vec3 planeAxis(const Vec3& t1, const Vec3& n);

struct PairBody {
  const Superquadric& shape;
  Pose pose;
};

class PairGap {
 public:
  /// The bodies are kept by reference to their shapes; throws std::invalid_argument when the
  /// detector's contact did not converge.
  PairGap(const PairBody& A, const PairBody& B, const ContactGeometry& contact);
  /// The gap of two bodies touching at A's body point `localA` and B's `localB`, B turned by
  /// `relative` = q_A* q_B against A: a contact as its curvature cache keeps it
  /// (interaction/curvature_cache.hpp), posed in A's frame; `majorAxisA` the contact ellipse's
  /// major axis (A's frame) and `radii` its relative radii then.
  static PairGap touchingAt(const Superquadric& A, const Superquadric& B, const Vec3& localA, const Vec3& localB,
                            const Quat& relative, const Vec3& majorAxisA, const RelativeRadii& radii);

  /// The two surfaces' heights along n above a plane point (m): A's top, B's bottom.
  struct Heights {
    double top = std::numeric_limits<double>::quiet_NaN(), bottom = std::numeric_limits<double>::quiet_NaN();
  };

  /// The gap (m) above the plane point origin + x t1 + y t2 (x, y in m).
  double operator()(double x, double y) const;
  /// The same, each surface's Newton line started from `near`, the heights above a point at most
  /// `distance` (m) away (surface_along_line.hpp: the same answer to Newton's tolerance, in fewer
  /// steps where the surfaces' slopes are below 1); `near` becomes this point's heights.
  double operator()(double x, double y, Heights& near, double distance) const;
  /// sqrt(R_vol,A R_vol,B) (m): the pair's length scale.
  double referenceLength() const { return referenceLength_; }
  /// sqrt(R_minor / R_major) of the gap's quadratic form at the contact (relative radii capped,
  /// at 10 R_vol,ref from a detector's contact): the aspect of the region where the gap is
  /// small, were it Hertz's.
  double quadraticAspect() const { return quadraticAspect_; }
  /// The larger relative radius (m), capped as above: the quadratic region along t1 is
  /// sqrt(2 R delta) long.
  double majorRadius() const { return majorRadius_; }

 private:
  /// The plane through `origin` with `normal` and axis t1 (projected on the plane), the gap
  /// shifted by `overlap`.
  PairGap(const PairBody& A, const PairBody& B, const Vec3& origin, const Vec3& normal, const Vec3& t1, double overlap,
          const RelativeRadii& radii);

  const Superquadric *shapeA_, *shapeB_;  // (pointers: a gap is assignable, as the engine's records are)
  Pose poseA_, poseB_;
  Vec3 origin_, normal_, t1_, t2_;
  double overlap_, referenceLength_, quadraticAspect_, majorRadius_;
};

}  // namespace sqdem
