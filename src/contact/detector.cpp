#include "sqdem/contact/detector.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <vector>

#include "pair_surfaces.hpp"
#include "penetration_depth.hpp"
#include "pivoted_lu.hpp"
#include "sqdem/geometry/oriented_box.hpp"

namespace sqdem {
namespace {

using Mat4 = Eigen::Matrix4d;
using detail::EllipsoidSurfaces;
using detail::PairFrame;
using detail::SuperquadricSurfaces;

/// One evaluation of the common-normal residual (see detector.hpp); its Jacobian is computed
/// only when a Newton step is taken from it (withJacobian): a warm solve's last evaluation
/// passes the tolerance and needs none.
template <class Surfaces>
struct Iterate {
  typename Surfaces::Point a, b;
  Vec3 t1, t2;    // tangent basis at A
  Vec3 tb1, tb2;  // tangent basis at B, aligned with (t1, t2) when nB = -nA (withJacobian)
  Vec4 r;
  Mat4 J;
  double overlap = 0.0, lengthScale = 0.0;
  double norm = 0.0;
  bool finite = false;
};

template <class Surfaces>
Iterate<Surfaces> evaluate(const PairFrame& f, const Surfaces& surfaces, const Vec3& pA, const Vec3& pB) {
  Iterate<Surfaces> it;
  it.a = surfaces.onA(pA);
  it.b = surfaces.onB(pB);
  const Vec3& nA = it.a.normal;
  const Vec3& nB = it.b.normal;
  tangentBasis(nA, it.t1, it.t2);
  const double L = f.lengthScale;
  const Vec3 gap = pB - pA;
  const Vec3 normalSum = nA + nB;
  it.overlap = -gap.dot(nA);
  it.lengthScale = L;
  it.r << L * it.t1.dot(normalSum), L * it.t2.dot(normalSum), it.t1.dot(gap), it.t2.dot(gap);
  it.norm = it.r.norm();
  it.finite = it.r.allFinite() && surfaces.finite(it.a) && surfaces.finite(it.b);
  return it;
}

/// Sets B's tangent basis and it.J; it.finite becomes false if J is not finite.
template <class Surfaces>
void withJacobian(const Surfaces& surfaces, Iterate<Surfaces>& it) {
  const double L = it.lengthScale;
  const Vec3& nB = it.b.normal;
  const Vec3 u1 = it.t1 - nB * nB.dot(it.t1), u2 = it.t2 - nB * nB.dot(it.t2);
  if (u1.squaredNorm() >= u2.squaredNorm()) {
    it.tb1 = u1.normalized();
    it.tb2 = it.tb1.cross(nB);
  } else {
    it.tb2 = u2.normalized();
    it.tb1 = nB.cross(it.tb2);
  }
  const Vec3 tA[2] = {it.t1, it.t2};
  const Vec3 tB[2] = {it.tb1, it.tb2};
  const Vec3 SA[2] = {surfaces.shapeOperator(it.a, tA[0]), surfaces.shapeOperator(it.a, tA[1])};
  const Vec3 SB[2] = {surfaces.shapeOperator(it.b, tB[0]), surfaces.shapeOperator(it.b, tB[1])};
  for (int i = 0; i < 2; ++i) {
    const Vec3 tiOnB = tA[i] - nB * nB.dot(tA[i]);  // P_B t_i
    for (int j = 0; j < 2; ++j) {
      const double kA = tA[i].dot(SA[j]);  // shape operator of A
      const double kB = tiOnB.dot(SB[j]);  // shape operator of B
      it.J(i, j) = L * kA;
      it.J(i, j + 2) = L * kB;
      // d(t_i.(pB - pA)): -t_i.t_j from moving pA, overlap*kA from the basis turning with nA.
      it.J(i + 2, j) = (i == j ? -1.0 : 0.0) + it.overlap * kA;
      it.J(i + 2, j + 2) = tA[i].dot(tB[j]);
    }
  }
  it.finite = it.finite && it.J.allFinite();
}

/// Support points of A along n and of B along -n (A's frame) and the support gap
/// h_A(n) + h_B(-n) = n.(pA - pB): the support function of the Minkowski difference A - B,
/// whose minimum over unit n is the overlap (or minus the distance) of the pair.
struct SupportPair {
  Vec3 normal, pointA, pointB;
  double gap = 0.0;
  int iterations = 0;
};

SupportPair supportPair(const PairFrame& f, const Vec3& n) {
  SupportPair s{n, f.supportOfA(n), f.supportOfB(n), 0.0, 0};
  s.gap = n.dot(s.pointA - s.pointB);
  return s;
}

/// Initial guess: descends the support gap over the unit sphere from startNormal (gradient
/// P (pA - pB), step 1/(rA + rB) as for two spheres, backtracking) into the basin it starts in,
/// whose minimum the Newton solve then polishes (the least penetration only if that basin is
/// the global minimum's: detector.hpp).
SupportPair minimiseSupportGap(const PairFrame& f, const Vec3& startNormal,
                               double relativeTolerance = 1e-3, int maxIterations = 40) {
  SupportPair best = supportPair(f, startNormal);
  double step = 1.0 / (f.A.boundingRadius() + f.B.boundingRadius());
  const double tolerance = relativeTolerance * f.lengthScale;
  int iterations = 0;
  while (iterations < maxIterations) {
    const Vec3 d = best.pointA - best.pointB;
    const Vec3 gradient = d - best.normal * best.normal.dot(d);
    if (gradient.norm() < tolerance) break;
    ++iterations;
    const SupportPair trial = supportPair(f, (best.normal - step * gradient).normalized());
    if (trial.gap < best.gap) {
      best = trial;
      step *= 1.5;
    } else {
      step *= 0.3;
    }
  }
  best.iterations = iterations;
  return best;
}

/// Least-squares solution of [J; sqrt(damping) I] step = [-r; 0] by column-pivoted QR, which
/// does not square J's condition number (large where the relative curvature nearly vanishes,
/// as in flat-on-flat contacts) and returns the minimum-norm-like basic step when J is singular.
/// The undamped step of a well-conditioned J (the common case) uses the cheaper partially
/// pivoted LU (pivoted_lu.hpp), which gives the same solution; "well-conditioned" is judged by
/// the ratio of the smallest to the largest pivot (cheap; an rcond() estimate costs as much as
/// the solve).
template <class Surfaces>
Vec4 dampedStep(const Iterate<Surfaces>& it, double damping) {
  if (damping == 0.0) {
    const detail::PivotedLu<4> lu(it.J);
    if (lu.wellConditioned(1e-6)) return lu.solve(-it.r);
    return it.J.colPivHouseholderQr().solve(-it.r);
  }
  Eigen::Matrix<double, 8, 4> augmented;
  augmented << it.J, std::sqrt(damping) * Mat4::Identity();
  Eigen::Matrix<double, 8, 1> rhs;
  rhs << -it.r, Vec4::Zero();
  return augmented.colPivHouseholderQr().solve(rhs);
}

/// Scales a tangent step so that it moves a point at most maxLength.
Vec2 capped(const Vec2& step, double maxLength) {
  const double n = step.norm();
  return n > maxLength ? Vec2(step * (maxLength / n)) : step;
}

/// Principal curvatures (world frame) of a body at a point of its surface (body frame).
PrincipalCurvatures curvaturesAt(const Superquadric& s, const Pose& pose, const Vec3& localPoint) {
  const GaugeDerivatives d = s.derivatives(localPoint);
  return principalCurvatures(d.gradient, d.hessian).rotated(pose.rotation());
}

/// The answer at surface points pA, pB (A's body frame) with A's normal nA there, in world frame:
/// what finish() and confirmContact both return (one packing, the same bits).
ContactGeometry atPoints(const PairFrame& f, const Pose& poseA, const Mat3& RA, const Vec3& pA, const Vec3& pB,
                         const Vec3& nA) {
  ContactGeometry g;
  g.localPointA = pA;
  g.localPointB = f.toB(pB);
  g.pointA = poseA.toWorld(pA);
  g.pointB = poseA.toWorld(pB);
  g.normal = RA * nA;
  g.overlap = -(pB - pA).dot(nA);
  return g;
}

/// Packs a solved pair (points in A's body frame) into world-frame ContactGeometry.
template <class Surfaces>
ContactGeometry finish(const PairFrame& f, const Surfaces& surfaces, const Pose& poseA, const Iterate<Surfaces>& it,
                       ContactStatus status, int iterations, bool curvatures) {
  const Mat3 RA = poseA.rotation();
  ContactGeometry g = atPoints(f, poseA, RA, it.a.point, it.b.point, it.a.normal);
  g.status = status;
  if (iterations == 0) {  // an answer a confirmation may keep (confirmContact)
    g.localNormalA = it.a.normal;
    g.localNormalB = f.R.transpose() * it.b.normal;
  }
  if (curvatures) {
    g.curvatureA = surfaces.curvatures(it.a).rotated(RA);
    g.curvatureB = surfaces.curvatures(it.b).rotated(RA);
  }
  g.iterations = iterations;
  g.residual = it.norm;
  return g;
}

ContactGeometry separated(double gapLowerBound) {
  ContactGeometry g;
  g.status = ContactStatus::Separated;
  g.overlap = -std::max(gapLowerBound, 0.0);
  return g;
}

/// A round contact as a full ContactGeometry (no body-frame points or curvatures yet).
ContactGeometry asGeometry(const RoundContact& c) {
  ContactGeometry g;
  g.status = c.status;
  g.overlap = c.overlap;
  g.normal = c.normal;
  g.pointA = c.pointA;
  g.pointB = c.pointB;
  return g;
}

/// A sphere's curvatures at the point with outward normal n: 1/r in every direction.
PrincipalCurvatures sphereCurvatures(const Vec3& n, double r) {
  PrincipalCurvatures c = PrincipalCurvatures::flat(n);
  c.k1 = c.k2 = 1.0 / r;
  return c;
}

ContactGeometry sphereSphere(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                             const Pose& poseB, const DetectorSettings& settings) {
  const double rA = A.a(), rB = B.a();
  ContactGeometry g = asGeometry(detectSpheres(poseA.position, rA, poseB.position, rB, settings.cutoff));
  if (!g.converged()) return g;
  g.localPointA = poseA.toBody(g.pointA);
  g.localPointB = poseB.toBody(g.pointB);
  if (!settings.curvatures) return g;
  g.curvatureA = sphereCurvatures(g.normal, rA);
  g.curvatureB = sphereCurvatures(-g.normal, rB);
  return g;
}

/// Safeguarded Gauss-Newton on the common-normal residual from surface points pA, pB (A's frame),
/// with its own budget of settings.maxIterations; earlierIterations are added to the count.
template <class Surfaces>
ContactGeometry newtonSolve(const PairFrame& f, const Surfaces& surfaces, const Pose& poseA, const Vec3& pA,
                            const Vec3& pB, int earlierIterations, const DetectorSettings& settings) {
  const double tolerance = settings.tolerance * f.lengthScale;
  const double maxStepA = 0.5 * f.A.halfExtents().minCoeff();
  const double maxStepB = 0.5 * f.B.halfExtents().minCoeff();
  Iterate<Surfaces> current = evaluate(f, surfaces, pA, pB);
  ContactStatus status = ContactStatus::Converged;
  // Safeguarded Gauss-Newton: the full step, then halved steps (nearly singular, flat
  // directions overshoot), then Levenberg-Marquardt steps of growing damping (far from the
  // solution); the first trial that lowers |r| is taken.
  constexpr int halvings = 4;
  constexpr double dampings[] = {1e-6, 1e-4, 1e-2, 1.0, 1e2, 1e4};
  constexpr int attempts = halvings + static_cast<int>(std::size(dampings));
  Vec4 newton = Vec4::Zero();
  int iterations = 0;
  for (int attempt = 0;;) {
    if (!current.finite) {
      status = ContactStatus::NonFinite;
      break;
    }
    if (current.norm <= tolerance) break;
    if (iterations >= settings.maxIterations) {
      status = ContactStatus::MaxIterations;
      break;
    }
    if (attempt == attempts) {
      status = ContactStatus::Stalled;
      break;
    }
    if (attempt == 0) {
      withJacobian(surfaces, current);
      if (!current.finite) {
        status = ContactStatus::NonFinite;
        break;
      }
      newton = dampedStep(current, 0.0);
    }
    const Vec4 step = attempt < halvings ? Vec4(std::ldexp(1.0, -attempt) * newton)
                                         : dampedStep(current, dampings[attempt - halvings]);
    const Vec2 stepA = capped(step.head<2>(), maxStepA);
    const Vec2 stepB = capped(step.tail<2>(), maxStepB);
    const Vec3 yA = current.a.point + stepA.x() * current.t1 + stepA.y() * current.t2;
    const Vec3 yB = current.b.point + stepB.x() * current.tb1 + stepB.y() * current.tb2;
    const Iterate<Surfaces> trial = evaluate(f, surfaces, surfaces.projectOnA(yA), surfaces.projectOnB(yB));
    ++iterations;
    if (trial.finite && trial.norm < current.norm) {
      current = trial;
      attempt = 0;
    } else {
      ++attempt;
    }
  }
  if (status == ContactStatus::NonFinite) {
    ContactGeometry g;
    g.status = status;
    g.iterations = earlierIterations + iterations;
    return g;
  }
  ContactGeometry g = finish(f, surfaces, poseA, current, status, earlierIterations + iterations, settings.curvatures);
  if (g.converged()) {
    const bool antiparallel = current.a.normal.dot(current.b.normal) < 0.0;
    const bool facesB = current.a.normal.dot(f.c) >= 0.0;
    if (!antiparallel || !facesB) {
      g.status = ContactStatus::WrongBranch;
    } else if (-g.overlap > settings.cutoff) {
      g.status = ContactStatus::Separated;
    }
  }
  if (!g.converged() && g.status != ContactStatus::Separated) g.overlap = 0.0;  // an unsolved pair has no overlap
  return g;
}

/// Warm-start budget before falling back to the support-gap descent.
constexpr int warmIterationBudget = 8;

/// A solve that found the pair's common normal (touching, or separated by its gap).
bool settled(const ContactGeometry& g) {
  return g.status == ContactStatus::Converged || g.status == ContactStatus::Separated;
}

/// The side check (detector.hpp): an overlapping answer's points lie inside or on the other
/// body, a separated answer's outside or on it, to `sideSlack` in gauge units (a relative
/// distance; a solve to tolerance misplaces them by ~1e-10).
constexpr double sideSlack = 1e-7;
bool pointsOnTheirSides(const PairFrame& f, const ContactGeometry& g) {
  const double inB = f.B.gauge(f.toB(g.localPointA)) - 1.0;
  const double inA = f.A.gauge(f.fromB(g.localPointB)) - 1.0;
  return g.overlap >= 0.0 ? std::max(inA, inB) <= sideSlack : std::min(inA, inB) >= -sideSlack;
}

/// A stationary pair that is not the contact: not converged, no overlap.
ContactGeometry notTheContact(ContactGeometry g) {
  g.status = ContactStatus::WrongBranch;
  g.overlap = 0.0;
  return g;
}

/// An answer of a pair solved before continues the last one when its overlap moved by at most
/// 1e-2 L (a stable step moves a particle by ~1e-4 of its size); otherwise it is new.
bool continues(const PairFrame& f, const ContactGeometry& g, const WarmStart* previous) {
  constexpr double overlapJump = 1e-2;
  return previous != nullptr && std::abs(g.overlap - previous->overlap) <= overlapJump * f.lengthScale;
}

/// Starting directions of the global stage: the line of centres, the body axes of A and B and
/// A's diagonals (both signs), ordered by their support gap, smallest (deepest) first.
std::vector<SupportPair> rankedStarts(const PairFrame& f) {
  std::vector<Vec3> directions;
  if (f.c.norm() > 0.0) directions.push_back(f.c.normalized());
  for (int k = 0; k < 3; ++k) {
    directions.push_back(Vec3::Unit(k));
    directions.push_back(f.R.col(k));
  }
  for (const double x : {-1.0, 1.0}) {
    for (const double y : {-1.0, 1.0}) directions.push_back(Vec3(x, y, 1.0).normalized());
  }
  std::vector<SupportPair> starts;
  for (const Vec3& d : directions) {
    starts.push_back(supportPair(f, d));
    starts.push_back(supportPair(f, -d));
  }
  std::stable_sort(starts.begin(), starts.end(), [](const SupportPair& x, const SupportPair& y) { return x.gap < y.gap; });
  return starts;
}

/// The minimum of the support gap over all directions from the ranked starts: for convex
/// bodies the penetration depth of the Minkowski difference (the answer for degenerate pairs).
SupportPair globalSupportMinimum(const PairFrame& f, int& iterations) {
  std::optional<SupportPair> best;
  for (const SupportPair& start : rankedStarts(f)) {
    const SupportPair s = minimiseSupportGap(f, start.normal, 1e-7, 400);
    iterations += s.iterations;
    if (!best || s.gap < best->gap) best = s;
  }
  return *best;  // rankedStarts is never empty
}

/// The least penetration is found to this fraction of L (EPA's tolerance): of two common-normal
/// pairs whose overlaps differ by less, the first found is reported.
constexpr double leastPenetrationTolerance = 1e-8;

/// Global stage (detector.hpp: which pair is reported), for answers that are not certain. With
/// EPA's bounds of the least penetration (penetration_depth.hpp): an answer at the lower bound
/// stands; otherwise the descent from EPA's normal is polished and kept when shallower. An
/// answer is believed within EPA's bounds, or without them (the bodies do not overlap, EPA's
/// start was flat or its polytope never enclosed the origin) when it passes the side check. While
/// none is believed: descents from the ranked starts, those that undercut a believed answer or
/// else the four best, the shallowest kept. An answer still not believed is not the contact.
/// A later answer replaces an earlier only when shallower by more than the tolerance, so a pair
/// found twice keeps its first bits.
template <class Polish>
ContactGeometry leastPenetration(const PairFrame& f, ContactGeometry best, const Polish& polish) {
  const double tolerance = leastPenetrationTolerance * f.lengthScale;
  int iterations = best.iterations;
  const auto keepShallower = [&](const ContactGeometry& g) {
    iterations = g.iterations;
    if (settled(g) && (!settled(best) || g.overlap < best.overlap - tolerance)) best = g;
  };
  const std::optional<detail::Penetration> epa = detail::penetrationDepth(f, leastPenetrationTolerance);
  if (epa) iterations += epa->iterations;
  // Every common-normal pair's overlap is at least EPA's lower bound, the least penetration's
  // at most its upper bound (bounds also when EPA stopped short of its tolerance).
  const bool bounded = epa && std::isfinite(epa->lowerBound);
  const auto believed = [&](const ContactGeometry& g) {
    if (!settled(g)) return false;
    if (!bounded) return pointsOnTheirSides(f, g);
    return g.overlap >= epa->lowerBound - tolerance && g.overlap <= epa->upperBound + tolerance;
  };
  if (epa && !(settled(best) && best.overlap <= epa->lowerBound + tolerance)) {
    keepShallower(polish(minimiseSupportGap(f, epa->normal, 1e-7, 400), iterations));
  }
  if (!believed(best)) {
    constexpr int globalStarts = 4;
    int tried = 0;
    for (const SupportPair& start : rankedStarts(f)) {
      if (believed(best) ? start.gap >= best.overlap - tolerance : tried == globalStarts) break;
      ++tried;
      keepShallower(polish(minimiseSupportGap(f, start.normal, 1e-7, 400), iterations));
    }
  }
  if (settled(best) && !believed(best)) best = notTheContact(best);
  best.iterations = iterations;
  return best;
}

/// Below this overlap a common-normal pair is the least penetration (detector.hpp): the smallest
/// principal radius of curvature of A plus B's, known for ellipsoids (c^2 / a, at the ends of
/// the longest axis), taken as 0 for other exponents.
double uniqueMinimumReach(const PairFrame& f) {
  const auto leastRadius = [](const Superquadric& s) {
    const Vec3& e = s.halfExtents();
    return s.isEllipsoid() ? e.minCoeff() * e.minCoeff() / e.maxCoeff() : 0.0;
  };
  return leastRadius(f.A) + leastRadius(f.B);
}

/// A new answer that needs no search (detector.hpp): separated with its points outside the other
/// body, or overlapping below the unique-minimum reach.
bool certain(const PairFrame& f, const ContactGeometry& g) {
  return g.overlap < 0.0 ? pointsOnTheirSides(f, g) : g.overlap < uniqueMinimumReach(f);
}

/// A pair the common-normal model cannot describe: coincident centres, or a centre inside the
/// other body.
bool degenerate(const PairFrame& f) {
  return f.c.norm() <= 1e-9 * f.lengthScale || f.A.gauge(f.c) < 1.0 || f.B.gauge(f.toB(Vec3::Zero())) < 1.0;
}

/// Cold solve from startNormal (of a new pair, or of a warm one whose Newton did not settle, from
/// its last normal): support-gap descent then Newton; a longer descent if that did not settle. A
/// certain answer stands, and one that continues the pair's branch; every other goes through
/// the global stage.
template <class Surfaces>
ContactGeometry coldSolve(const PairFrame& f, const Surfaces& surfaces, const Pose& poseA, const Vec3& startNormal,
                          int earlierIterations, const DetectorSettings& settings, const WarmStart* previous) {
  if (degenerate(f)) {
    int iterations = earlierIterations;
    const SupportPair depth = globalSupportMinimum(f, iterations);
    ContactGeometry g;
    g.status = ContactStatus::Degenerate;
    g.normal = poseA.rotation() * depth.normal;
    g.overlap = depth.gap;  // the support "gap" n.(pA - pB) is the overlap along n
    g.pointA = poseA.toWorld(depth.pointA);
    g.pointB = poseA.toWorld(depth.pointB);
    g.localPointA = depth.pointA;
    g.localPointB = f.toB(depth.pointB);
    g.iterations = iterations;
    return g;
  }
  const auto polish = [&](const SupportPair& s, int iterations) {
    return newtonSolve(f, surfaces, poseA, s.pointA, s.pointB, iterations + s.iterations, settings);
  };
  const SupportPair guess = minimiseSupportGap(f, startNormal);
  ContactGeometry g = polish(guess, earlierIterations);
  // Deep overlaps: the Newton basin is narrower, so descend the support gap much further (its
  // minimum is itself a common-normal pair) before the second Newton attempt.
  if (!settled(g)) g = polish(minimiseSupportGap(f, guess.normal, 1e-7, 400), g.iterations);
  // The cold solve of a warm pair continues its branch when, besides the overlap, the normal
  // (startNormal, the last one) turned by less than ~0.1 rad.
  const bool sameBranch = continues(f, g, previous) && (poseA.rotation().transpose() * g.normal).dot(startNormal) > 0.995;
  if (settled(g) && (sameBranch || certain(f, g))) return g;
  return leastPenetration(f, g, polish);
}

/// Warm solve from the previous points, or cold, of a pair that passed the culls.
template <class Surfaces>
ContactGeometry solvePair(const PairFrame& f, const Pose& poseA, const DetectorSettings& settings,
                          const WarmStart* previous) {
  const Surfaces surfaces(f);
  if (previous != nullptr) {
    // Warm: Newton from the previous points; if that does not settle quickly (a contact that
    // jumps across a flat face), a cold solve from the previous normal instead.
    DetectorSettings quick = settings;
    quick.maxIterations = std::min(settings.maxIterations, warmIterationBudget);
    const ContactGeometry g =
        newtonSolve(f, surfaces, poseA, previous->localPointA, f.fromB(previous->localPointB), 0, quick);
    if (settled(g) && (continues(f, g, previous) || certain(f, g))) return g;
    return coldSolve(f, surfaces, poseA, f.A.outwardNormal(previous->localPointA), g.iterations, settings, previous);
  }
  const double distance = f.c.norm();
  return coldSolve(f, surfaces, poseA, distance > 0.0 ? Vec3(f.c / distance) : Vec3::UnitX(), 0, settings, nullptr);
}

/// The pair seen from A's body frame (one construction for the solve and confirmContact).
[[gnu::always_inline]] inline PairFrame pairFrame(const Superquadric& A, const Mat3& RA, const Superquadric& B, const Mat3& RB, const Vec3& centres) {
  return {A, B, RA.transpose() * RB, RA.transpose() * centres, referenceVolumeRadius(A, B)};
}

/// The culls of a pair that may be apart (bounding spheres, then boxes): its Separated answer, or
/// nullopt. A pair that touched at its last solve is not further apart than the cut-off one step
/// later: it is not culled.
std::optional<ContactGeometry> culled(const Superquadric& A, const Pose& poseA, const Mat3& RA, const Superquadric& B,
                                      const Pose& poseB, const Mat3& RB, const DetectorSettings& settings,
                                      const WarmStart* previous) {
  if (previous != nullptr && previous->overlap >= 0.0) return std::nullopt;
  const double sphereGap = (poseB.position - poseA.position).norm() - A.boundingRadius() - B.boundingRadius();
  if (sphereGap > settings.cutoff) return separated(sphereGap);
  const OrientedBox boxA{poseA.position, RA, A.halfExtents()};
  const OrientedBox boxB{poseB.position, RB, B.halfExtents()};
  if (!boxesOverlap(boxA, boxB, 0.5 * settings.cutoff)) return separated(std::max(sphereGap, settings.cutoff));
  return std::nullopt;
}

ContactGeometry solve(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                      const Pose& poseB, const DetectorSettings& settings, const WarmStart* previous) {
  if (A.isSphere() && B.isSphere()) return sphereSphere(A, poseA, B, poseB, settings);

  const Vec3 centres = poseB.position - poseA.position;
  const Mat3 RA = poseA.rotation(), RB = poseB.rotation();
  if (const std::optional<ContactGeometry> apart = culled(A, poseA, RA, B, poseB, RB, settings, previous)) return *apart;
  const PairFrame f = pairFrame(A, RA, B, RB, centres);
  if (A.isEllipsoid() && B.isEllipsoid()) return solvePair<EllipsoidSurfaces>(f, poseA, settings, previous);
  return solvePair<SuperquadricSurfaces>(f, poseA, settings, previous);
}

}  // namespace

ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                              const Pose& poseB, const DetectorSettings& settings) {
  return solve(A, poseA, B, poseB, settings, nullptr);
}

ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                              const Pose& poseB, const DetectorSettings& settings, const WarmStart& previous) {
  return solve(A, poseA, B, poseB, settings, &previous);
}

std::optional<ContactGeometry> confirmContact(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                                              const Pose& poseB, const DetectorSettings& settings,
                                              const WarmStart& previous, const Vec3& normalA, const Vec3& normalB) {
  if ((A.isSphere() && B.isSphere()) || settings.curvatures) return std::nullopt;  // solve()'s closed form; no curvatures here
  const Mat3 RA = poseA.rotation(), RB = poseB.rotation();
  const PairFrame f = pairFrame(A, RA, B, RB, poseB.position - poseA.position);
  // evaluate() at the warm start's points, in A's frame, with the kept normals: |r|^2 is the
  // tangential part (to nA) of L (nA + nB) and of pB - pA, whatever the tangent basis.
  const Vec3& pA = previous.localPointA;
  const Vec3 pB = f.fromB(previous.localPointB), nB = f.R * normalB;
  const auto tangential = [&](const Vec3& v) { return Vec3(v - v.dot(normalA) * normalA); };
  const Vec3 normalSum = tangential(normalA + nB), gap = tangential(pB - pA);
  const double residual = std::sqrt(f.lengthScale * f.lengthScale * normalSum.squaredNorm() + gap.squaredNorm());
  // The margin covers kept against evaluated normals (round-off, and B's point re-expressed in each
  // new frame since: WarmSkip::mostInARow), which does not shrink with the tolerance: 1e-11 L.
  const double margin = std::max(1e-3 * settings.tolerance, 1e-11) * f.lengthScale;
  if (!(residual <= settings.tolerance * f.lengthScale - margin)) return std::nullopt;
  if (culled(A, poseA, RA, B, poseB, RB, settings, &previous)) return std::nullopt;  // solve() returns the cull's answer
  // finish() of that first iterate, as newtonSolve returns it after its checks (antiparallel
  // normals, facing B, within the cut-off) and solvePair's continuation.
  ContactGeometry g = atPoints(f, poseA, RA, pA, pB, normalA);
  g.status = ContactStatus::Converged;
  g.localNormalA = normalA;
  g.localNormalB = normalB;
  g.residual = residual;
  if (!(normalA.dot(nB) < 0.0) || !(normalA.dot(f.c) >= 0.0) || -g.overlap > settings.cutoff || !continues(f, g, &previous)) {
    return std::nullopt;
  }
  return g;
}

ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Superquadric& B,
                              const Pose& poseB, const DetectorSettings& settings,
                              const ContactGeometry& previous) {
  if (!previous.converged()) return solve(A, poseA, B, poseB, settings, nullptr);
  const WarmStart warm{previous.localPointA, previous.localPointB, previous.overlap};
  return solve(A, poseA, B, poseB, settings, &warm);
}

ContactGeometry detectContact(const Superquadric& A, const Pose& poseA, const Plane& wall,
                              const DetectorSettings& settings) {
  if (A.isSphere()) {
    ContactGeometry g = asGeometry(detectSphereWall(poseA.position, A.a(), wall, settings.cutoff));
    if (!g.converged()) return g;
    g.localPointA = poseA.toBody(g.pointA);
    g.localPointB = g.pointB;
    if (settings.curvatures) g.curvatureA = sphereCurvatures(g.normal, A.a());
    g.curvatureB = PrincipalCurvatures::flat(wall.normal);
    return g;
  }
  const Vec3 n = -wall.normal;
  const Mat3 RA = poseA.rotation();
  ContactGeometry g;
  g.localPointA = A.supportPoint(RA.transpose() * n);
  g.pointA = poseA.toWorld(g.localPointA);
  g.overlap = (wall.point - g.pointA).dot(wall.normal);
  if (-g.overlap > settings.cutoff) return separated(-g.overlap);
  g.status = ContactStatus::Converged;
  g.normal = n;
  g.pointB = g.pointA + g.overlap * wall.normal;
  g.localPointB = g.pointB;  // the wall's frame is the world frame
  if (settings.curvatures) g.curvatureA = curvaturesAt(A, poseA, g.localPointA);
  g.curvatureB = PrincipalCurvatures::flat(wall.normal);
  return g;
}

void addCurvatures(ContactGeometry& g, const Superquadric& A, const Pose& poseA, const Superquadric& B,
                   const Pose& poseB) {
  g.curvatureA = curvaturesAt(A, poseA, g.localPointA);
  g.curvatureB = curvaturesAt(B, poseB, g.localPointB);
}

void addCurvatures(ContactGeometry& g, const Superquadric& A, const Pose& poseA) {
  g.curvatureA = curvaturesAt(A, poseA, g.localPointA);
}

}  // namespace sqdem
