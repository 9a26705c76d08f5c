// Cost of the true-gap law (truegap/true_gap_curve.hpp) against elliptic Hertz and the detector
// on the same blocky pairs (16 seeded random pairs, four per pose class, tests/support/posed_pair.hpp):
//   true_gap_first_overlap  a new pose's first force: the two rungs around the overlap solved
//   true_gap_kept_rungs     a force between rungs already solved (the power law, the blend)
//   elliptic_hertz          the Hertz force of the same contact (its constants given)
//   detector                the common-normal detector on the pair, warm-started
// Overlaps spread over delta / R_ref = 1e-4 ... 1.7e-2.

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "sqdem/mechanics/hertz_law.hpp"
#include "sqdem/truegap/true_gap_curve.hpp"
#include "support/posed_pair.hpp"

namespace sqdem {
namespace {

struct Case {
  testing::PosedPair pair;
  RelativeRadii radii;
  double overlap;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = [] {
    std::mt19937 rng(20261205);
    std::vector<Case> c;
    for (int kind = 0; kind < 4; ++kind) {
      for (int k = 0; k < 4; ++k) {
        testing::PosedPair p;
        if (!testing::randomBlockyPair(kind, rng, p)) continue;
        const double R = referenceVolumeRadius(p.A, p.B);
        const RelativeRadii radii = relativeRadii(p.contact.curvatureA, p.contact.curvatureB, 10.0 * R);
        c.push_back({p, radii, R * 1e-4 * std::pow(300.0, (k + 0.5 * kind) / 5.0)});
      }
    }
    return c;
  }();
  return all;
}

TrueGapCurve curveOf(const Case& c) {
  const testing::PosedPair& p = c.pair;
  return TrueGapCurve({p.A, p.poseA}, {p.B, p.poseB}, p.contact, c.radii, 1e9, 16);
}

void trueGapFirstOverlap(benchmark::State& state) {
  std::size_t k = 0;
  for (auto _ : state) {
    const Case& c = cases()[k++ % cases().size()];
    TrueGapCurve curve = curveOf(c);
    benchmark::DoNotOptimize(curve.at(c.overlap).force);
  }
}

void trueGapKeptRungs(benchmark::State& state) {
  std::vector<TrueGapCurve> curves;
  for (const Case& c : cases()) {
    curves.push_back(curveOf(c));
    curves.back().at(c.overlap);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ % curves.size();
    benchmark::DoNotOptimize(curves[i].at(cases()[i].overlap * 1.01).force);
  }
}

void ellipticHertz(benchmark::State& state) {
  std::vector<NormalContact> contacts;
  for (const Case& c : cases()) contacts.push_back({c.radii, hertzFactors(c.radii.ratio(), EccentricityMethod::Exact), 1e9});
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ % contacts.size();
    HertzLaw::History none;
    benchmark::DoNotOptimize(HertzLaw{}.force(contacts[i], cases()[i].overlap, none).force);
  }
}

void detector(benchmark::State& state) {
  DetectorSettings settings;
  std::size_t k = 0;
  for (auto _ : state) {
    const testing::PosedPair& p = cases()[k++ % cases().size()].pair;
    settings.cutoff = 4.0 * (p.A.boundingRadius() + p.B.boundingRadius());
    benchmark::DoNotOptimize(detectContact(p.A, p.poseA, p.B, p.poseB, settings, p.contact).overlap);
  }
}

BENCHMARK(trueGapFirstOverlap)->Name("true_gap_first_overlap")->Unit(benchmark::kMicrosecond);
BENCHMARK(trueGapKeptRungs)->Name("true_gap_kept_rungs");
BENCHMARK(ellipticHertz)->Name("elliptic_hertz");
BENCHMARK(detector)->Name("detector")->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace sqdem
