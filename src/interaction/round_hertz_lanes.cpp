// Round contacts (sphere pairs, a sphere and a plane wall) under HertzLaw, W contacts per instruction (docs/performance.md, "SIMD across
// contacts"). A member list is taken in blocks of 32 contacts: their inputs are gathered into
// lanes (a structure of arrays), solved W at a time with GCC's vector extensions, and the results
// scattered back into the store. The lane code is detectRound (detectSpheres, detectSphereWall),
// kinematics and roundHertzForce (contact_kernels.cpp, contact_force.hpp, round_contact.hpp,
// mindlin_spring.hpp) written out with
// the same operations in the same order (Eigen's 3-vector sums run left to right), every branch
// computed on every lane and selected (a lane masked out may compute 0/0 or the root of a
// negative number: no floating-point trap is enabled). The build contracts nothing into fused
// multiply-adds and this file takes sqrt without errno (CMakeLists.txt), so each path gives
// the contact-by-contact bits. Spheres have radii > 0 (the scene's shapes are validated), so
// R* is always rA rB / (rA + rB).

#include "round_hertz_lanes.hpp"

#include <algorithm>
#include <cstring>
#include <numbers>
#include <stdexcept>

#include "contact_force.hpp"

// The lane helpers take and return vectors wider than the baseline's registers; they are always
// inlined into the path's function, whose instruction set has them, so no call passes one.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace sqdem::detail {
namespace {

constexpr int block = 32;  ///< contacts per gather: 10.5 kB of lanes, well inside L1

template <int W> struct VectorOf { typedef double type __attribute__((vector_size(8 * W))); };
template <int W> using Lane = typename VectorOf<W>::type;  ///< W contacts' values of one quantity
template <int W> struct Lane3 { Lane<W> x, y, z; };        ///< W contacts' 3-vectors

template <int W> [[gnu::always_inline]] inline Lane3<W> operator+(const Lane3<W>& u, const Lane3<W>& v) { return {u.x + v.x, u.y + v.y, u.z + v.z}; }
template <int W> [[gnu::always_inline]] inline Lane3<W> operator-(const Lane3<W>& u, const Lane3<W>& v) { return {u.x - v.x, u.y - v.y, u.z - v.z}; }
template <int W> [[gnu::always_inline]] inline Lane3<W> operator*(const Lane<W>& s, const Lane3<W>& v) { return {s * v.x, s * v.y, s * v.z}; }
template <int W> [[gnu::always_inline]] inline Lane3<W> operator*(const Lane3<W>& v, const Lane<W>& s) { return {v.x * s, v.y * s, v.z * s}; }
template <int W> [[gnu::always_inline]] inline Lane<W> dot(const Lane3<W>& u, const Lane3<W>& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
/// Eigen's cross (OrthoMethods.h), component by component.
template <int W> [[gnu::always_inline]] inline Lane3<W> cross(const Lane3<W>& u, const Lane3<W>& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
template <int W, typename Mask> [[gnu::always_inline]] inline Lane3<W> select(Mask m, const Lane3<W>& u, const Lane3<W>& v) {
  return {m ? u.x : v.x, m ? u.y : v.y, m ? u.z : v.z};
}
template <int W> [[gnu::always_inline]] inline Lane<W> sqrt(Lane<W> v) {
  for (int j = 0; j < W; ++j) v[j] = __builtin_sqrt(v[j]);  // one vector square root (no errno)
  return v;
}

/// A block's lanes: inputs, then outputs (spring both).
struct Block {
  alignas(64) double xA[3][block], xB[3][block], vA[3][block], vB[3][block], wA[3][block], wB[3][block];
  alignas(64) double rA[block], rB[block], mA[block], mB[block];
  alignas(64) double wallNormal[3][block];  ///< B a plane wall: its normal (its point in xB, its velocity in vB)
  alignas(64) double spring[3][block];
  alignas(64) double normal[3][block], point[3][block], force[3][block];
  alignas(64) double overlap[block], normalForce[block], damping[block], stiffness[block], area[block];
  alignas(64) std::int64_t degenerate[block], converged[block], acting[block];  ///< 0 or -1 (all bits)
};

template <int W> [[gnu::always_inline]] inline Lane<W> load(const double* p) {
  Lane<W> v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <int W> [[gnu::always_inline]] inline Lane3<W> load(const double (&p)[3][block], int i) {
  return {load<W>(p[0] + i), load<W>(p[1] + i), load<W>(p[2] + i)};
}
/// Lanes (a vector of values or masks) stored at p.
template <typename V> [[gnu::always_inline]] inline void put(void* p, const V& v) { std::memcpy(p, &v, sizeof v); }
template <int W> [[gnu::always_inline]] inline void put(double (&p)[3][block], int i, const Lane3<W>& v) {
  put(p[0] + i, v.x), put(p[1] + i, v.y), put(p[2] + i, v.z);
}
inline void put(double (&p)[3][block], int j, const Vec3& v) { p[0][j] = v.x(), p[1][j] = v.y(), p[2][j] = v.z(); }
inline Vec3 take(const double (&p)[3][block], int j) { return {p[0][j], p[1][j], p[2][j]}; }

/// The group's constants, as the scalar kernel forms them.
struct Constants {
  explicit Constants(const ContactModel& model, const InteractionScene& scene)
      : range(HertzLaw{}.range({})), cutoff(std::min(scene.skin, range)),  // detectRound's
        fourThirdsE(4.0 / 3.0 * model.effectiveModulus), twoE(2.0 * model.effectiveModulus),
        eightG(8.0 * model.tangential.effectiveShear), dampingScale(model.damping.scale()),
        friction(model.tangential.friction), dt(scene.dt) {
    const RoundHertz roots(model);
    rootNormal = roots.rootNormal, rootTangential = roots.rootTangential;
  }
  double range, cutoff, fourThirdsE, twoE, eightG, dampingScale, friction, dt, rootNormal = 0.0, rootTangential = 0.0;
};

template <int W> using Mask = decltype(Lane<W>{} < Lane<W>{});  ///< per lane 0, or -1 (all bits)

/// What detection hands the law, per lane.
template <int W> struct Detected {
  Lane3<W> normal, point;
  Lane<W> overlap;
  Mask<W> converged, degenerate;
};

/// Sphere pairs: detectRound's cull by the squared distance, then detectSpheres.
template <int W>
[[gnu::always_inline]] inline Detected<W> detectPairs(const Block& l, int i, const Constants& c) {
  const Lane3<W> xA = load<W>(l.xA, i), xB = load<W>(l.xB, i);
  const Lane<W> rA = load<W>(l.rA + i), rB = load<W>(l.rB + i), zero{}, one = zero + 1.0, half = zero + 0.5;
  const Lane3<W> d = xB - xA;
  const Lane<W> squared = dot(d, d), reach = rA + rB + c.cutoff;
  const auto inReach = ~(squared > reach * reach);
  const Lane<W> distance = sqrt<W>(squared), gap = distance - rA - rB;
  const auto apart = inReach & (gap > c.cutoff);
  const auto touching = inReach & ~apart;  // Converged or Degenerate: surface points set
  const auto degenerate = touching & ~(distance > 0.0);
  const auto converged = touching & ~degenerate;
  const Lane3<W> n = select<W>(converged, Lane3<W>{d.x / distance, d.y / distance, d.z / distance}, {zero, zero, one});
  const Lane<W> overlap = converged ? rA + rB - distance : degenerate ? rA + rB : apart ? -(gap < 0.0 ? zero : gap) : zero;
  const Lane3<W> pointA = xA + rA * n, pointB = xB - rB * n;
  return {n, select<W>(touching, half * (pointA + pointB), {zero, zero, zero}), overlap, converged, degenerate};
}

/// A sphere against a plane wall (B: the wall's point in xB, its normal in wallNormal):
/// detectSphereWall.
template <int W>
[[gnu::always_inline]] inline Detected<W> detectWalls(const Block& l, int i, const Constants& c) {
  const Lane3<W> xA = load<W>(l.xA, i), wallPoint = load<W>(l.xB, i), wallNormal = load<W>(l.wallNormal, i);
  const Lane<W> rA = load<W>(l.rA + i), zero{}, one = zero + 1.0, half = zero + 0.5;
  const Lane3<W> n{-wallNormal.x, -wallNormal.y, -wallNormal.z};
  const Lane3<W> pointA = xA + rA * n;
  const Lane<W> depth = dot(wallPoint - pointA, wallNormal), gap = -depth;
  const auto converged = ~(gap > c.cutoff);
  const Lane3<W> pointB = pointA + depth * wallNormal;
  return {select<W>(converged, n, {zero, zero, one}), select<W>(converged, half * (pointA + pointB), {zero, zero, zero}),
          converged ? depth : -(gap < 0.0 ? zero : gap), converged, Mask<W>{}};
}

/// Lanes i..i+W-1 of the block: detection, then within range kinematics and roundHertzForce; a
/// lane out of range gets the group kernel's cleared load and spring.
template <int W, bool OnWall>
[[gnu::always_inline]] inline void solve(Block& l, int i, const Constants& c) {
  const Detected<W> t = OnWall ? detectWalls<W>(l, i, c) : detectPairs<W>(l, i, c);
  const Lane3<W>& n = t.normal;
  const Lane<W>& overlap = t.overlap;
  const Lane<W> zero{};
  const Lane3<W> none{zero, zero, zero};
  const auto acting = t.converged & (overlap > -c.range) & (overlap > 0.0);  // in range; roundHertzForce acts
  // kinematics (a plane's surface moves with the wall's velocity, in vB)
  const Lane3<W> xA = load<W>(l.xA, i);
  const Lane<W> rA = load<W>(l.rA + i), mA = load<W>(l.mA + i);
  const Lane3<W> velocityA = load<W>(l.vA, i) + cross(load<W>(l.wA, i), t.point - xA);
  Lane3<W> relative = load<W>(l.vB, i) - velocityA;
  Lane<W> mass = mA, reducedRadius = rA;
  if constexpr (!OnWall) {
    const Lane<W> rB = load<W>(l.rB + i), mB = load<W>(l.mB + i);
    relative = load<W>(l.vB, i) + cross(load<W>(l.wB, i), t.point - load<W>(l.xB, i)) - velocityA;
    mass = mA * mB / (mA + mB);
    reducedRadius = rA * rB / (rA + rB);
  }
  // roundHertzForce
  const Lane<W> a = sqrt<W>(reducedRadius * overlap);
  const Lane<W> rootMassRadius = c.dampingScale * sqrt<W>(mass * a);
  const Lane<W> damping = rootMassRadius * c.rootNormal * -dot(relative, n);
  const Lane<W> normalForce = c.fourThirdsE * a * overlap + damping;
  Lane3<W> force = normalForce * n, spring = load<W>(l.spring, i);
  if (c.friction > 0.0) {  // MindlinSpring::circleForce with k = 8 G* a
    const Lane3<W> vt = relative - dot(relative, n) * n;
    const Lane<W> length2 = dot(spring, spring);  // keepInTangentPlane
    spring = spring - dot(spring, n) * n;
    const Lane<W> projected2 = dot(spring, spring);
    spring = select<W>(projected2 > 0.0, spring * sqrt<W>(length2 / projected2), spring);
    spring = spring + vt * (zero + c.dt);
    const Lane<W> k = c.eightG * a, eta = rootMassRadius * c.rootTangential;
    const Lane3<W> Ft{-(k * spring.x + eta * vt.x), -(k * spring.y + eta * vt.y), -(k * spring.z + eta * vt.z)};
    const Lane<W> limit = c.friction * (normalForce < 0.0 ? zero : normalForce);
    const auto slip = dot(Ft, Ft) > limit * limit;
    const Lane3<W> capped = Ft * (limit / sqrt<W>(dot(Ft, Ft)));
    const Lane3<W> held{-(capped.x + eta * vt.x) / k, -(capped.y + eta * vt.y) / k, -(capped.z + eta * vt.z) / k};
    spring = select<W>(slip, select<W>(k > 0.0, held, none), spring);
    force = force + select<W>(slip, capped, Ft);
  }
  put<W>(l.normal, i, n), put<W>(l.point, i, t.point), put(l.overlap + i, overlap);
  put<W>(l.force, i, select<W>(acting, force, none)), put<W>(l.spring, i, select<W>(acting, spring, none));
  put(l.normalForce + i, acting ? normalForce : zero), put(l.damping + i, acting ? damping : zero);
  put(l.stiffness + i, acting ? c.twoE * a : zero), put(l.area + i, acting ? std::numbers::pi * a * a : zero);
  put(l.degenerate + i, t.degenerate), put(l.converged + i, t.converged), put(l.acting + i, acting);
}

/// What a thread's share counts for the step's statistics.
struct Counts {
  long long calls = 0, degenerate = 0, deep = 0;
};

/// Contacts first .. first + count - 1 of the members gathered into the block's lanes, padded to a
/// whole vector with copies of the last (solved, never scattered).
template <int W, bool OnWall>
[[gnu::always_inline]] inline void gather(Block& l, const std::uint32_t* members, int count, const InteractionScene& scene,
                                          const ContactStore& s, std::ptrdiff_t left) {
  const ParticleStore& p = scene.particles;
  const int lanes = (count + W - 1) / W * W;
  for (int j = 0; j < lanes; ++j) {
    if (j < count && j + ContactStore::prefetchAhead < left) s.prefetch(members[j + ContactStore::prefetchAhead]);
    const std::uint32_t k = members[std::min(j, count - 1)], a = s.a[k], b = s.b[k];
    put(l.xA, j, p.position[a]), put(l.vA, j, p.velocity[a]), put(l.wA, j, p.angularVelocity[a]);
    l.rA[j] = p.boundingRadius[a], l.mA[j] = p.mass[a];
    if constexpr (OnWall) {
      const Wall& wall = scene.walls[b & ~wallFlag];
      const Plane& plane = wall.get<PlaneWall>().plane;
      put(l.xB, j, plane.point), put(l.vB, j, wall.velocity), put(l.wallNormal, j, plane.normal);
    } else {
      put(l.xB, j, p.position[b]), put(l.vB, j, p.velocity[b]), put(l.wB, j, p.angularVelocity[b]);
      l.rB[j] = p.boundingRadius[b], l.mB[j] = p.mass[b];
    }
    put(l.spring, j, s.spring[k]);
  }
}

/// The block's results into the store: what the group kernel writes for a round contact.
template <bool OnWall>
[[gnu::always_inline]] inline void scatter(const Block& l, const std::uint32_t* members, int count, ContactStore& s, Counts& counts) {
  const bool rolling = s.withRolling, moments = s.withMoment();  // (the byte stores below may alias them)
  for (int j = 0; j < count; ++j) {
    const std::uint32_t k = members[j];
    const bool acting = l.acting[j] != 0;
    s.status[k] = l.converged[j] != 0 ? ContactStatus::Converged : l.degenerate[j] != 0 ? ContactStatus::Degenerate : ContactStatus::Separated;
    s.normal[k] = take(l.normal, j);
    s.overlap[k] = l.overlap[j];
    s.point[k] = take(l.point, j);
    s.spring[k] = take(l.spring, j);
    if (!acting) s.normalHistory[k] = {};
    if (rolling && !acting) s.rolling[k].setZero();
    if (moments) s.moment[k].setZero();
    s.acting[k] = acting;
    s.force[k] = take(l.force, j);
    s.load[k] = {l.normalForce[j], l.damping[j], l.stiffness[j], l.area[j], false};
    counts.degenerate += l.degenerate[j] != 0;
    counts.deep += acting && deepOverlap(l.overlap[j], l.rA[j], OnWall ? 0.0 : l.rB[j]);
  }
  if constexpr (!OnWall) counts.calls += count;  // the detector's calls: particle pairs only
}

template <int W, bool OnWall>
[[gnu::always_inline]] inline Counts solveMembers(std::span<const std::uint32_t> members, const Constants& c,
                                                  const InteractionScene& scene, ContactStore& s) {
  Block l;
  Counts counts;
  const auto size = static_cast<std::ptrdiff_t>(members.size());
  for (std::ptrdiff_t first = 0; first < size; first += block) {
    const int count = static_cast<int>(std::min<std::ptrdiff_t>(block, size - first));
    gather<W, OnWall>(l, members.data() + first, count, scene, s, size - first);
    for (int i = 0; i < count; i += W) solve<W, OnWall>(l, i, c);
    scatter<OnWall>(l, members.data() + first, count, s, counts);
  }
  return counts;
}

Counts solveBaseline(bool walls, std::span<const std::uint32_t> members, const Constants& c, const InteractionScene& scene,
                     ContactStore& s) {
  return walls ? solveMembers<2, true>(members, c, scene, s) : solveMembers<2, false>(members, c, scene, s);
}
#if defined(__x86_64__)
[[gnu::target("arch=x86-64-v3")]] Counts solveAvx2(bool walls, std::span<const std::uint32_t> members, const Constants& c,
                                                   const InteractionScene& scene, ContactStore& s) {
  return walls ? solveMembers<4, true>(members, c, scene, s) : solveMembers<4, false>(members, c, scene, s);
}
#endif

}  // namespace

void roundHertzContacts(SimdPath path, PairKind kind, std::span<const std::uint32_t> members, const ContactModel& model,
                        const InteractionScene& scene, ContactStore& s, ContactStatistics& statistics) {
  const Constants c(model, scene);
  const bool walls = kind == PairKind::SphereWall;
  Counts counts;
  switch (path) {
    case SimdPath::Scalar: throw std::logic_error("roundHertzContacts: the scalar path is the group kernel's");
    case SimdPath::Baseline: counts = solveBaseline(walls, members, c, scene, s); break;
    case SimdPath::Avx2:
#if defined(__x86_64__)
      counts = solveAvx2(walls, members, c, scene, s);
      break;
#else
      throw std::logic_error("roundHertzContacts: no AVX2 path outside x86-64");
#endif
  }
#pragma omp critical(sqdem_contact_statistics)
  {
    statistics.detectorCalls += counts.calls;
    statistics.detectorFailures += counts.degenerate;
    statistics.failuresByStatus[static_cast<int>(ContactStatus::Degenerate)] += counts.degenerate;
    (model.deepOverlapsExpected ? statistics.expectedDeepOverlaps : statistics.deepOverlaps) += counts.deep;
  }
}

}  // namespace sqdem::detail
