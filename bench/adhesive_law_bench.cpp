// Cost of one evaluation of the adhesive elliptic laws, the Johnson-Greenwood curve solved per
// contact (JkrCurve::Exact) or read from its table (JkrCurve::Tabulated): elliptic_jkr smooth
// and with Greenwood-Williamson roughness, over Ri/Rj spread log-uniformly in [1e-2, 1] and
// overlaps from the detachment gap to 30 JKR overlap scales (a law object per contact, as the
// engine's kernels build it). The tables' error is printed by tests/jkr_test.cpp.

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "sqdem/mechanics/jkr_elliptic.hpp"
#include "sqdem/mechanics/roughness_gw.hpp"

namespace sqdem {
namespace {

struct Sample {
  NormalContact contact;
  double overlap;
};

std::vector<Sample> samples() {
  const double E = 1e9, W = 0.2, R = 1e-5;
  const double scale = std::pow(9.0 * M_PI * W * std::sqrt(R) / (4.0 * E), 2.0 / 3.0);  // JKR overlap scale
  std::vector<Sample> s;
  for (int k = 0; k < 1024; ++k) {
    const double ratio = std::pow(10.0, -2.0 * ((k * 37) % 1024) / 1024.0);
    NormalContact c;
    c.radii = {.Ri = R * ratio, .Rj = R, .cosOmega = 1.0, .Rc = R * ratio / (1.0 + ratio)};
    c.factors = hertzFactors(ratio, EccentricityMethod::Tabulated);
    c.effectiveModulus = E;
    s.push_back({c, scale * (-0.5 + 30.0 * ((k * 101) % 1024) / 1024.0)});
  }
  return s;
}

template <class Law>
void evaluate(benchmark::State& state, Law law) {
  const std::vector<Sample> s = samples();
  std::size_t k = 0;
  law.force(s[0].contact, s[0].overlap, *std::make_unique<typename Law::History>());  // builds the table outside the timing
  for (auto _ : state) {
    const Sample& x = s[k++ % s.size()];
    typename Law::History h{};
    if constexpr (std::is_same_v<Law, EllipticJkrLaw>) h.attached = true;
    benchmark::DoNotOptimize(law.force(x.contact, x.overlap, h).force);
  }
}

BENCHMARK_CAPTURE(evaluate, elliptic_jkr_exact, EllipticJkrLaw{0.1, JkrCurve::Exact});
BENCHMARK_CAPTURE(evaluate, elliptic_jkr_tabulated, EllipticJkrLaw{0.1, JkrCurve::Tabulated});
BENCHMARK_CAPTURE(evaluate, rough_jkr_exact, RoughJkrLaw{{.asperityCount = 50, .sigma = 2e-9}, 0.1, JkrCurve::Exact});
BENCHMARK_CAPTURE(evaluate, rough_jkr_tabulated, RoughJkrLaw{{.asperityCount = 50, .sigma = 2e-9}, 0.1, JkrCurve::Tabulated});

}  // namespace
}  // namespace sqdem
