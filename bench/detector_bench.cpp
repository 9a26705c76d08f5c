// Detector and curvature micro-benchmarks: cold and warm solves for sphere, ellipsoid and
// n = 6 superquadric pairs (planted contacts, overlaps 1e-6..1e-1 R_vol), reporting ns per
// call and mean iterations per solve.

#include <benchmark/benchmark.h>

#include <vector>

#include "sqdem/contact/detector.hpp"
#include "support/random_pairs.hpp"

namespace sqdem {
namespace {

enum class Family { Sphere, Ellipsoid, Superquadric6 };

struct Case {
  testing::PlantedPair pair;
  Pose movedB;               ///< B after a DEM-like step (1e-5 rad, 1e-6 R_vol)
  ContactGeometry previous;  ///< the solution before the step (warm-start data)
};

std::vector<Case> makeCases(Family family) {
  testing::PairGenerator gen(42);
  if (family != Family::Superquadric6) gen.minExponent = gen.maxExponent = 2.0;
  else gen.minExponent = gen.maxExponent = 6.0;
  std::vector<Case> cases;
  while (cases.size() < 512) {
    testing::PlantedPair p = gen.next();
    if (family == Family::Sphere) {
      p.A = Superquadric::sphere(p.A.a());
      p.B = Superquadric::sphere(p.B.a());
      p.poseB.position = p.poseA.position + (p.A.a() + p.B.a() - p.overlap) * p.normal;
    } else if (family == Family::Superquadric6 && p.A.isEllipsoid()) {
      continue;  // the generator draws 20 % ellipsoids
    }
    const double L = referenceVolumeRadius(p.A, p.B);
    Pose moved = p.poseB;
    moved.orientation = Quat(Eigen::AngleAxisd(1e-5, gen.randomUnit())) * moved.orientation;
    moved.position += 1e-6 * L * gen.randomUnit();
    const ContactGeometry previous = detectContact(p.A, p.poseA, p.B, p.poseB);
    cases.push_back({p, moved, previous});
  }
  return cases;
}

void run(benchmark::State& state, Family family, bool warm) {
  const std::vector<Case> cases = makeCases(family);
  DetectorSettings settings;
  settings.cutoff = 1.0;
  std::size_t k = 0;
  long iterations = 0, solves = 0, failures = 0;
  for (auto _ : state) {
    const Case& c = cases[k++ % cases.size()];
    const ContactGeometry g =
        warm ? detectContact(c.pair.A, c.pair.poseA, c.pair.B, c.movedB, settings, c.previous)
             : detectContact(c.pair.A, c.pair.poseA, c.pair.B, c.pair.poseB, settings);
    benchmark::DoNotOptimize(g.overlap);
    iterations += g.iterations;
    failures += !g.converged();
    ++solves;
  }
  state.counters["iterations"] = double(iterations) / solves;
  state.counters["failures"] = double(failures);
}

void BM_DetectSphereCold(benchmark::State& s) { run(s, Family::Sphere, false); }
void BM_DetectEllipsoidCold(benchmark::State& s) { run(s, Family::Ellipsoid, false); }
void BM_DetectEllipsoidWarm(benchmark::State& s) { run(s, Family::Ellipsoid, true); }
void BM_DetectSuperquadric6Cold(benchmark::State& s) { run(s, Family::Superquadric6, false); }
void BM_DetectSuperquadric6Warm(benchmark::State& s) { run(s, Family::Superquadric6, true); }
BENCHMARK(BM_DetectSphereCold);
BENCHMARK(BM_DetectEllipsoidCold);
BENCHMARK(BM_DetectEllipsoidWarm);
BENCHMARK(BM_DetectSuperquadric6Cold);
BENCHMARK(BM_DetectSuperquadric6Warm);

void curvature(benchmark::State& state, const Superquadric& s) {
  std::vector<Vec3> points;
  testing::PairGenerator gen(1);
  for (int k = 0; k < 256; ++k) points.push_back(s.projectRadially(gen.randomUnit()));
  std::size_t k = 0;
  for (auto _ : state) {
    const GaugeDerivatives d = s.derivatives(points[k++ % points.size()]);
    benchmark::DoNotOptimize(principalCurvatures(d.gradient, d.hessian).k1);
  }
}
void BM_CurvatureEllipsoid(benchmark::State& s) { curvature(s, Superquadric::ellipsoid(1, 0.6, 0.4)); }
void BM_CurvatureSuperquadric6(benchmark::State& s) { curvature(s, Superquadric(1, 1, 2, 6, 6)); }
BENCHMARK(BM_CurvatureEllipsoid);
BENCHMARK(BM_CurvatureSuperquadric6);

}  // namespace
}  // namespace sqdem
