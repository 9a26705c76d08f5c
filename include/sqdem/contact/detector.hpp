#pragma once
// Common-normal contact detector for superquadric-superquadric and superquadric-plane pairs.
//
// A contact is a pair of surface points pA on A and pB on B whose outward normals are
// antiparallel and whose connecting vector is parallel to them (the common normal, 004 §2.1):
//     nA(pA) = -nB(pB) = n,    pB - pA = -overlap * n.
// Each point lives on its own surface (moved along its tangent plane, then projected radially
// with the gauge, see superquadric.hpp), so the unknowns are two tangent displacements per body
// and the residual is the 4-vector (L t.(nA + nB), t.(pB - pA)) in a tangent basis t of nA,
// L = sqrt(R_vol,A R_vol,B). It is solved by a safeguarded Gauss-Newton iteration (full step,
// halved steps, then Levenberg-Marquardt damping; a step cap); the Jacobian uses the surfaces'
// shape operators, so it stays finite on flat faces and only loses rank where the relative
// curvature does (line and plane contacts), which a column-pivoted QR solve tolerates.
// Which pair is reported. Every common-normal pair is a stationary point of the support gap
// s(n) = h_A(n) + h_B(-n) over unit n, with s(n) its overlap; a separated pair has one facing the
// other body (s < 0, the distance), an overlapping pair may have several: far-side pairs, and
// for deep overlaps of blocky or elongated bodies more than one local minimum. A new pair (a
// cold solve) gets the **least penetration**, the global minimum of s (to 1e-8 L; of two pairs
// whose overlaps differ by less, the first found), or minus the distance. A warm pair follows
// its branch: while its answer continues the last one it stands, even where another pair has
// meanwhile become shallower (a contact does not jump to another normal; it is re-judged when
// its overlap jumps or its solve fails).
//
// Two facts decide when a stationary pair needs no search. The radius-of-curvature tensors of
// A at n and of B at -n add to K = A - B's, so K's least radius is >= rA + rB (Weyl) where A's
// radii are all >= rA and B's >= rB; then h_K - rA - rB is a support function (Blaschke's rolling
// ball) and s = h_K' + rA + rB. And a stationary point n of a support function with a negative
// value s is its global minimum: there the support point is s n, at distance -s from the
// origin, and every h(m) >= -dist(0, K) >= s. So a separated answer (s < 0) is the distance, and
// an overlapping one with overlap < rA + rB the least penetration. rA = c^2 / a for an ellipsoid
// (a >= b >= c); for other exponents no bound is used (0).
//
// Cold starts first descend s from the line of centres; Newton polishes the descent's end (a
// longer descent and a second Newton if it does not settle). The answer is certain, and
// stands, when it is separated and its points pass the side check (each outside, or on, the
// other body: one gauge evaluation each, against an answer only nearly stationary), or when it
// overlaps by less than rA + rB. Every other answer goes to the global stage: the expanding
// polytope algorithm on the bodies' support maps (src/contact/penetration_depth.hpp) bounds the
// least penetration from below and above; an answer at the lower bound stands, else the descent
// from EPA's normal is polished and the shallower answer kept, and an answer outside the bounds
// is not the contact (status WrongBranch). Where EPA finds the bodies apart or never encloses the origin,
// descents from the best of 22 ranked directions (line of centres, both bodies' axes, A's
// diagonals, both signs) replace it and the side check judges. The side check cannot judge an
// overlapping answer: where B is thin across the normal the least penetration pushes it out
// sideways and A's point lies beyond B, and a deeper local minimum can have both points inside.
// Warm starts begin at the previous points. A warm answer continues the last one when its
// overlap moved by at most 1e-2 L, and a cold solve a warm pair falls back to when, besides, its
// normal turned by less than ~0.1 rad; an answer that continues stands, one that jumped is judged
// as a new pair's. So a warm step costs one comparison more (tests/detector_construction_sweep_test.cpp,
// docs/performance.md). A non-converged answer carries no overlap (0). Degenerate pairs
// (coincident centres, or a centre inside the other body) are not solved: they get status
// Degenerate, with the least support gap the descents from the ranked directions find as
// overlap and its normal and support points.
//
// Closed forms: sphere-sphere and sphere-plane (round_contact.hpp), and every
// superquadric-plane pair (support map). Particle-cylinder: a one-dimensional search. Particle-
// mesh: per feature, the plane, line or point contact, kept in the feature's region.
// Before any iteration, pairs further apart than the cut-off are culled by bounding spheres and
// oriented boxes. The result is never NaN/inf: an unresolved pair is a status (contact_geometry.hpp).

#include <optional>

#include "sqdem/contact/contact_geometry.hpp"
#include "sqdem/contact/round_contact.hpp"
#include "sqdem/geometry/cylinder.hpp"
#include "sqdem/geometry/mesh_features.hpp"
#include "sqdem/geometry/plane.hpp"
#include "sqdem/geometry/pose.hpp"
#include "sqdem/geometry/superquadric.hpp"

namespace sqdem {

struct DetectorSettings {
  /// Separated pairs with a gap up to this distance (m) are still solved and reported with
  /// overlap = -gap; beyond it they are Separated.
  double cutoff = 0.0;
  /// Converged when the residual is below tolerance * L (L = sqrt(R_vol,A R_vol,B)).
  double tolerance = 1e-10;
  int maxIterations = 100;
  /// false: skip the principal curvatures (left default) for laws that do not use them.
  bool curvatures = true;
};

/// Cold solve: the initial guess descends the support gap from the line of centres.
ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                              const Pose& poseB, const DetectorSettings& settings = {});

/// What a warm solve needs of the pair's last converged solve.
struct WarmStart {
  Vec3 localPointA;  ///< on A, A's body frame (m)
  Vec3 localPointB;  ///< on B, B's body frame (m)
  double overlap;    ///< (m); >= 0: the pair touched, so the culls are skipped
};

/// Warm solve: Newton from the previous points; a cold solve if that does not settle quickly.
ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                              const Pose& poseB, const DetectorSettings& settings, const WarmStart& previous);

/// A warm answer confirmed without evaluating a surface: previous is the pair's last converged
/// answer and normalA, normalB the outward normals there in A's and B's body frames
/// (ContactGeometry::localNormalA, localNormalB). The residual is computed from the new relative
/// pose; where it is within the tolerance less a margin (1e-3 of it, at least 1e-11 L: kept and
/// evaluated normals differ by round-off) and the warm solve would keep the answer (antiparallel
/// normals, A's facing B, the overlap not jumped, within the cut-off, past the culls of a pair
/// that was apart), the result is the warm solve's answer to the same bits (its residual and B's
/// normal to round-off); otherwise nullopt: solve. Never for two spheres (solved in closed form)
/// or when curvatures are asked for.
std::optional<ContactGeometry> confirmContact(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                                              const Pose& poseB, const DetectorSettings& settings,
                                              const WarmStart& previous, const Vec3& normalA, const Vec3& normalB);

/// Warm solve from a previous result when it converged, otherwise a cold solve.
ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                              const Pose& poseB, const DetectorSettings& settings,
                              const ContactGeometry& previous);

/// Particle A against a wall (body B): closed form through A's support point along -wall.normal.
/// normal points from A into the wall (= -wall.normal); the wall's curvatures are zero.
ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Plane& wall,
                              const DetectorSettings& settings = {});

/// Particle A against the outside of a cylinder (body B, a roller): the normal is
/// perpendicular to the axis, found as the separating direction of largest signed distance
/// (cylinder_detector.cpp); closed form for a sphere. Warm: searched near the previous normal.
/// B's curvatures are 1/radius around the axis and 0 along it; B's point is in world frame. A
/// finite cylinder's rounded end is the sphere of its radius at the end of the axis segment
/// (the pair detector; cold).
ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Cylinder& roller,
                              const DetectorSettings& settings = {}, const WarmStart* previous = nullptr);

/// Particle A against a point (a mesh vertex): the common normal through the point, by Newton's
/// method on A's surface (point_detector.cpp); B's curvatures flat (a kink has no finite ones).
ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Vec3& point,
                              const DetectorSettings& settings = {}, const WarmStart* previous = nullptr);

/// Particle A against feature `feature` of a triangle mesh whose body frame is at poseB
/// (mesh_detector.cpp): Separated when that feature does not answer for the touch (the touch
/// belongs to a neighbouring feature, or there is none). localPointB in the mesh's frame.
ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const MeshFeatures& mesh, const Pose& poseB,
                              std::uint32_t feature, const DetectorSettings& settings = {},
                              const WarmStart* previous = nullptr);

/// Sets the principal curvatures of a solution found without them (settings.curvatures false)
/// at its surface points localPointA and localPointB (body frames).
void addCurvatures(ContactGeometry& g, const Superquadric& A, const Pose& poseA, const Superquadric& B, const Pose& poseB);
/// The same for particle A against a wall (the wall's curvatures are already set: flat).
void addCurvatures(ContactGeometry& g, const Superquadric& A, const Pose& poseA);

}  // namespace sqdem
