#include "sqdem/scene/compaction_fit.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace sqdem {

double CompactionFit::porosity(double load) const {
  return porosityMin + (porosityStart - porosityMin) * std::exp(-load / resistance);
}

namespace {

/// For a fixed gamma_c: eps = A + B x with x = exp(-p / gamma_c), the least-squares A, B
/// (the normal equations of a straight line in x) and the sum of squares left.
struct LinearPart {
  double a = 0.0, b = 0.0, squares = std::numeric_limits<double>::infinity();
};

LinearPart linearPart(std::span<const double> load, std::span<const double> porosity, double resistance) {
  const double n = static_cast<double>(load.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < load.size(); ++i) {
    const double x = std::exp(-load[i] / resistance);
    sx += x;
    sy += porosity[i];
    sxx += x * x;
    sxy += x * porosity[i];
  }
  const double det = n * sxx - sx * sx;
  LinearPart fit;
  if (!(det > 0.0)) return fit;
  fit.b = (n * sxy - sx * sy) / det;
  fit.a = (sy - fit.b * sx) / n;
  fit.squares = 0.0;
  for (std::size_t i = 0; i < load.size(); ++i) {
    const double r = porosity[i] - (fit.a + fit.b * std::exp(-load[i] / resistance));
    fit.squares += r * r;
  }
  return fit;
}

}  // namespace

std::optional<CompactionFit> fitCompaction(std::span<const double> load, std::span<const double> porosity) {
  if (load.size() != porosity.size() || load.size() < 4) return std::nullopt;
  const auto [least, most] = std::ranges::minmax(load);
  if (!(most > least) || !(most > 0.0)) return std::nullopt;
  const auto squares = [&](double logResistance) { return linearPart(load, porosity, std::exp(logResistance)).squares; };
  std::uintmax_t iterations = 200;
  const auto [logResistance, _] = boost::math::tools::brent_find_minima(squares, std::log(1e-3 * most), std::log(1e3 * most),
                                                                      std::numeric_limits<double>::digits / 2, iterations);
  const double resistance = std::exp(logResistance);
  const LinearPart best = linearPart(load, porosity, resistance);
  if (!std::isfinite(best.squares)) return std::nullopt;
  return CompactionFit{best.a, best.a + best.b, resistance, std::sqrt(best.squares / static_cast<double>(load.size()))};
}

}  // namespace sqdem
