// Particle against the outside of a cylinder (detector.hpp): infinite, or finite with rounded ends.
//
// Only normals n perpendicular to the axis u separate a convex body from an infinite cylinder,
// so the signed distance along the common normal is the one-dimensional maximum over the
// angle theta of n(theta) in the plane normal to u (separating axes):
//     f(theta) = n . d - h_A(n) - R,
// d the vector from A's centre to the axis, h_A A's support function about its centre, R the
// radius. At the maximum (d - s_A(n)) is parallel to n within that plane (f' = 0), so A's
// support point s_A(n) and the cylinder point at the same axial station, R from the axis along
// -n, are a common-normal pair: overlap = -f. f is maximised by Brent's method on an interval of
// half-width pi/2 about the direction from A's centre to the axis (warm: 0.2 rad about the last
// normal), where the support function of A's shadow seen from the axis has its one minimum as
// long as the axis lies outside A, then polished to round-off as the root of f'. Radius 0 is a
// straight line: a mesh edge (line_contact.hpp).
// A finite cylinder is solved as the infinite one; when the contact falls beyond the barrel, the
// nearer end takes it: a rounded end as A against the sphere of the cylinder's radius centred at
// the end of the axis segment (the pair detector), a flat end as its disc or its rim
// (flatEndContact).

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "line_contact.hpp"
#include "sqdem/contact/detector.hpp"

namespace sqdem {
namespace {

/// Brent's bits of precision for theta: its limit, sqrt of the double epsilon (~1.5e-8 rad;
/// the overlap's error is of second order in it).
constexpr int angleBits = 26;
/// Half-width of the warm bracket (rad); a maximum within 1 % of its ends is searched cold.
constexpr double warmHalfWidth = 0.2;

struct Shadow {  // A seen from the axis, in the plane normal to it
  const Superquadric& A;
  const Mat3& R;  // A's rotation
  Vec3 d;         // from A's centre to the axis, normal to it (m)
  Vec3 e1, e2;    // orthonormal basis of that plane, e1 x e2 = axis

  Vec3 normal(double theta) const { return std::cos(theta) * e1 + std::sin(theta) * e2; }
  /// A's support point along n, relative to its centre, in the world frame.
  Vec3 support(const Vec3& n) const { return R * A.supportPoint(R.transpose() * n); }
  /// f + R: the signed distance from A to the axis along n.
  double reach(double theta) const {
    const Vec3 n = normal(theta);
    return n.dot(d - support(n));
  }
  /// f'(theta) = t . (d - s_A(n)), t = dn/dtheta: zero where d - s_A is parallel to n.
  double slope(double theta) const {
    const Vec3 n = normal(theta);
    return (std::cos(theta) * e2 - std::sin(theta) * e1).dot(d - support(n));
  }
};

/// The maximum of reach over [-halfWidth, halfWidth] about e1: its angle; adds the evaluations
/// and notes whether Brent ran out of them.
double maximise(const Shadow& s, double halfWidth, int maxEvaluations, int& evaluations, bool& exhausted) {
  std::uintmax_t used = static_cast<std::uintmax_t>(maxEvaluations);
  const auto best = boost::math::tools::brent_find_minima([&](double t) { return -s.reach(t); }, -halfWidth,
                                                          halfWidth, angleBits, used);
  evaluations += static_cast<int>(used);
  exhausted = exhausted || used >= static_cast<std::uintmax_t>(maxEvaluations);
  return best.first;
}

/// The common normal near a maximum found by Brent (to ~1e-8 rad), to round-off: the root of f'
/// by a bracketed solve (f is strictly concave where A lies beyond the axis: f' falls through
/// zero once there). On a face of a blocky body the support point slides across the face within
/// a tiny turn of n, so the root's bracket [lo, hi] can be an ulp wide and still hold two support
/// points far apart: A's point is then taken on the chord between them where d - s is parallel to
/// n (the face's point under the axis; the chord leaves the surface by |s_hi - s_lo|^2 k / 8).
struct Polished {
  Vec3 normal;
  Vec3 support;
};

Polished polish(const Shadow& s, double theta, int& evaluations) {
  double step = 1e-7;
  while (step < 0.1 && !(s.slope(theta - step) > 0.0 && s.slope(theta + step) < 0.0)) {
    step *= 4.0;
    evaluations += 2;
  }
  if (!(step < 0.1)) {  // no bracket: Brent's maximum as it is
    const Vec3 n = s.normal(theta);
    return {n, s.support(n)};
  }
  std::uintmax_t iterations = 60;
  const auto [lo, hi] = boost::math::tools::toms748_solve([&](double t) { return s.slope(t); }, theta - step, theta + step,
                                                          boost::math::tools::eps_tolerance<double>(), iterations);
  evaluations += static_cast<int>(iterations);
  const Vec3 n = s.normal(0.5 * (lo + hi)), t = s.normal(0.5 * (lo + hi) + 0.5 * std::numbers::pi);
  const Vec3 first = s.support(s.normal(lo)), last = s.support(s.normal(hi));
  const double across = t.dot(last - first);
  const double lambda = across != 0.0 ? std::clamp(t.dot(s.d - first) / across, 0.0, 1.0) : 0.5;
  return {n, first + lambda * (last - first)};
}

}  // namespace

ContactGeometry lineContact(const Superquadric& A, const Pose& poseA, const Cylinder& roller,
                            const DetectorSettings& settings, const WarmStart* previous) {
  const Vec3& u = roller.axis;
  const Vec3 d = -roller.fromAxis(poseA.position);
  const double distance = d.norm();
  ContactGeometry g;
  if (distance - A.boundingRadius() - roller.radius > settings.cutoff) {
    g.overlap = -(distance - A.boundingRadius() - roller.radius);
    return g;  // Separated
  }
  const Mat3 R = poseA.rotation();
  const Vec3 cold = distance > 0.0 ? Vec3(d / distance) : u.unitOrthogonal();  // towards the axis
  Vec3 e1 = cold;
  double halfWidth = 0.5 * std::numbers::pi;
  if (previous != nullptr && !A.isSphere()) {
    const Vec3 n = R * A.outwardNormal(previous->localPointA);
    const Vec3 inPlane = n - n.dot(u) * u;
    if (inPlane.norm() > 0.5) {
      e1 = inPlane.normalized();
      halfWidth = warmHalfWidth;
    }
  }
  Shadow shadow{A, R, d, e1, u.cross(e1)};
  double theta = 0.0;  // a sphere's support point is its centre + r n: n = d / |d| exactly
  int evaluations = 0;
  bool exhausted = false;
  if (!A.isSphere()) {
    theta = maximise(shadow, halfWidth, settings.maxIterations, evaluations, exhausted);
    if (halfWidth < 0.5 * std::numbers::pi && std::abs(theta) > 0.99 * halfWidth) {  // left the warm bracket
      shadow.e1 = cold;
      shadow.e2 = u.cross(cold);
      exhausted = false;
      theta = maximise(shadow, 0.5 * std::numbers::pi, settings.maxIterations, evaluations, exhausted);
    }
  }
  const auto [n, s] = A.isSphere() ? Polished{shadow.normal(theta), shadow.support(shadow.normal(theta))}
                                    : polish(shadow, theta, evaluations);
  const double gap = n.dot(d - s) - roller.radius;
  g.iterations = evaluations;
  if (gap > settings.cutoff) {
    g.overlap = -gap;
    return g;  // Separated
  }
  if (-gap >= A.halfExtents().minCoeff()) {
    g.status = ContactStatus::Degenerate;  // deeper than A's thinnest half-width: the axis may be inside A
  } else if (exhausted) {
    g.status = ContactStatus::MaxIterations;
    return g;  // no overlap, as every unresolved pair
  } else {
    g.status = ContactStatus::Converged;
  }
  g.normal = n;
  g.overlap = -gap;
  g.pointA = poseA.position + s;
  g.pointB = g.pointA + gap * n;
  g.localPointA = R.transpose() * s;
  g.localPointB = g.pointB;  // kinematic bodies keep world-frame points
  if (settings.curvatures && g.converged()) addCurvatures(g, A, poseA);
  return g;
}

namespace {

/// A against the infinite cylinder `roller`: the line contact with the barrel's curvatures.
ContactGeometry barrelContact(const Superquadric& A, const Pose& poseA, const Cylinder& roller,
                              const DetectorSettings& settings, const WarmStart* previous) {
  ContactGeometry g = lineContact(A, poseA, roller, settings, previous);
  if (g.converged() || g.status == ContactStatus::Degenerate) g.curvatureB = roller.curvatures(-g.normal);
  return g;
}

/// A beyond the barrel of a flat-ended cylinder: the end disc (the plane through `end` facing
/// `out`, kept when the touching point lies within the radius), else its rim. On the rim the
/// contact is the point contact (point_detector.cpp) at the rim point of largest overlap
/// (smallest gap): there A's normal is normal to the rim, a common normal. That point is found
/// by Brent's method over the rim's angle, within 2 bounding radii of A's azimuth (to ~1.5e-8
/// rad). The rim, a kink, is seen by the laws as flat (mesh_detector.cpp).
ContactGeometry flatEndContact(const Superquadric& A, const Pose& poseA, const Cylinder& c, const Vec3& end, const Vec3& out,
                               const DetectorSettings& settings) {
  if ((poseA.position - end).dot(out) > 0.0) {  // in front of the disc
    ContactGeometry disc = detectContact(A, poseA, Plane{end, out}, settings);
    const Vec3 q = disc.pointB - end;
    if (!disc.converged() || (q - q.dot(out) * out).norm() <= c.radius) return disc;
  }
  const Vec3 q = poseA.position - end, radial = q - q.dot(out) * out;
  const Vec3 e1 = radial.norm() > 0.0 ? Vec3(radial.normalized()) : out.unitOrthogonal(), e2 = out.cross(e1);
  const auto rimPoint = [&](double angle) { return end + c.radius * (std::cos(angle) * e1 + std::sin(angle) * e2); };
  WarmStart last{};
  bool warm = false;
  int evaluations = 0;
  // The search sees the signed distance everywhere (no cut-off: no plateau of culled points).
  DetectorSettings search = settings;
  search.cutoff = std::numeric_limits<double>::infinity();
  search.curvatures = false;
  const auto solve = [&](double angle, const DetectorSettings& s) {
    ContactGeometry g = detectContact(A, poseA, rimPoint(angle), s, warm ? &last : nullptr);
    evaluations += g.iterations + 1;
    if (g.converged()) last = {g.localPointA, g.localPointB, g.overlap}, warm = true;
    return g;
  };
  const double halfWidth = std::min(0.5 * std::numbers::pi, 2.0 * A.boundingRadius() / c.radius);
  std::uintmax_t used = static_cast<std::uintmax_t>(settings.maxIterations);
  const auto best = boost::math::tools::brent_find_minima(
      [&](double angle) {
        const ContactGeometry g = solve(angle, search);
        return g.converged() ? -g.overlap : std::numeric_limits<double>::max();
      },
      -halfWidth, halfWidth, angleBits, used);
  ContactGeometry g = solve(best.first, settings);
  g.iterations = evaluations;
  if (g.converged() && used >= static_cast<std::uintmax_t>(settings.maxIterations)) g.status = ContactStatus::MaxIterations;
  return g;
}

}  // namespace

ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Cylinder& roller,
                              const DetectorSettings& settings, const WarmStart* previous) {
  if (!roller.finite()) return barrelContact(A, poseA, roller, settings, previous);
  Cylinder barrel = roller;
  barrel.halfLength = std::numeric_limits<double>::infinity();
  ContactGeometry g = barrelContact(A, poseA, barrel, settings, previous);
  if (g.status == ContactStatus::Separated) return g;  // from the infinite cylinder: from the finite one too
  const double along = (g.converged() ? g.pointB : poseA.position).dot(roller.axis) - roller.point.dot(roller.axis);
  if (std::abs(along) <= roller.halfLength) return g;  // on the barrel
  const Vec3 end = roller.point + std::copysign(roller.halfLength, along) * roller.axis;
  ContactGeometry cap = roller.flatEnds ? flatEndContact(A, poseA, roller, end, std::copysign(1.0, along) * roller.axis, settings)
                                        : detectContact(A, poseA, Superquadric::sphere(roller.radius), Pose{end, Quat::Identity()}, settings);
  cap.localPointB = cap.pointB;  // kinematic bodies keep world-frame points
  cap.iterations += g.iterations;
  return cap;
}

}  // namespace sqdem
