// Eccentricity e^2 (004 Eqs. 13-14) three ways, and the full Hertz factors (e^2, gamma, beta),
// over Ri/Rj spread log-uniformly in [1e-4, 1]; the error of each method against the exact
// root is printed by the unit tests (elliptic_test.cpp).

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {
namespace {

std::vector<double> ratios() {
  std::vector<double> r;
  for (int k = 0; k < 1024; ++k) r.push_back(std::pow(10.0, -4.0 * ((k * 37) % 1024) / 1024.0));
  return r;
}

void eccentricity(benchmark::State& state, EccentricityMethod method) {
  const std::vector<double> r = ratios();
  eccentricitySquared(0.5, method);  // builds the table outside the timing
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(eccentricitySquared(r[k++ % r.size()], method));
}

void factors(benchmark::State& state, EccentricityMethod method) {
  const std::vector<double> r = ratios();
  hertzFactors(0.5, method);
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(hertzFactors(r[k++ % r.size()], method).gamma);
}

BENCHMARK_CAPTURE(eccentricity, exact, EccentricityMethod::Exact);
BENCHMARK_CAPTURE(eccentricity, tabulated, EccentricityMethod::Tabulated);
BENCHMARK_CAPTURE(eccentricity, explicit, EccentricityMethod::Explicit);
BENCHMARK_CAPTURE(factors, exact, EccentricityMethod::Exact);
BENCHMARK_CAPTURE(factors, tabulated, EccentricityMethod::Tabulated);
BENCHMARK_CAPTURE(factors, explicit, EccentricityMethod::Explicit);

}  // namespace
}  // namespace sqdem
