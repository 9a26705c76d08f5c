#include "sqdem/mechanics/roughness_gw.hpp"

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace sqdem {

double greenwoodWilliamsonForceIntegral(double h) {
  using std::numbers::pi;
  if (h > 0.0) {
    const double x = 0.25 * h * h;
    return std::exp(-x) * std::sqrt(h) *
           ((h * h + 1.0) * boost::math::cyl_bessel_k(0.25, x) -
            h * h * boost::math::cyl_bessel_k(0.75, x)) /
           (4.0 * std::sqrt(pi));
  }
  // int_0^inf s^3/2 phi(s + h) ds
  boost::math::quadrature::exp_sinh<double> integrator;
  return integrator.integrate([h](double s) -> double {
    return s * std::sqrt(s) * std::exp(-0.5 * (s + h) * (s + h)) / std::sqrt(2.0 * pi);
  });
}

double greenwoodWilliamsonAreaIntegral(double h) {
  return std::exp(-0.5 * h * h) / std::sqrt(2.0 * std::numbers::pi) -
         0.5 * h * boost::math::erfc(h / std::numbers::sqrt2);
}

double RoughContact::force(double effectiveModulus, double Rc, double gamma, double h) const {
  return 4.0 / 3.0 * asperityCount * effectiveModulus * std::sqrt(Rc) * sigma * std::sqrt(sigma) *
         gamma * greenwoodWilliamsonForceIntegral(h);
}

double RoughContact::area(double Rc, double beta, double h) const {
  return std::numbers::pi * asperityCount * Rc * sigma * beta * greenwoodWilliamsonAreaIntegral(h);
}

NormalResponse GreenwoodWilliamsonLaw::force(const NormalContact& c, double overlap, History&) const {
  if (!(overlap > -4.0 * rough.sigma)) return {.acting = false};  // beyond its range
  const double E = c.effectiveModulus, Rc = c.radii.Rc, gamma = c.factors.gamma;
  const double h = -overlap / rough.sigma, step = 1e-4;
  return {.force = rough.force(E, Rc, gamma, h),
          .stiffness = (rough.force(E, Rc, gamma, h - step) - rough.force(E, Rc, gamma, h + step)) / (2.0 * step * rough.sigma),
          .area = rough.area(Rc, c.factors.beta, h)};
}

namespace {

/// The asperity sums of RoughJkrLaw (roughness_gw.hpp) at separation h: F, dF/dh and A.
struct AsperitySums {
  double force = 0.0, forceSlope = 0.0, area = 0.0;
};

/// N A_n int_0^inf (f, A_JG)(sigma s) phi(s + h) ds and the force's d/dh (phi' = -(s + h) phi), in
/// one pass of Gauss-Legendre rules (20 points per panel): every node's curve point serves all
/// three integrals. The integrals run over |s + h| <= 9 (phi(9) / phi(0) = 2.6e-18) clipped to
/// s >= 0, in panels split at the Gaussian's peak s = -h and, from s = 0, at 4^k times the
/// detachment gap in units of sigma (|delta_d| / sigma, k = 0, 1, ...): where the asperities'
/// JKR curve bends, panels that small (up to 100 sigma / |delta_d|: 5 panels more).
AsperitySums asperitySums(const RoughContact& rough, const EllipticJkr& jkr, double h) {
  using Rule = boost::math::quadrature::gauss<double, 20>;
  constexpr double halfWidth = 9.0;
  const double lo = std::max(0.0, -h - halfWidth), hi = -h + halfWidth;
  std::vector<double> ends{lo, hi};
  if (-h > lo && -h < hi) ends.push_back(-h);
  for (double s = -jkr.detachmentOverlap() / rough.sigma; s < hi; s *= 4.0) {
    if (s > lo) ends.push_back(s);
  }
  std::sort(ends.begin(), ends.end());
  AsperitySums sum;
  const auto add = [&](double s, double weight) {
    const EllipticJkrState asperity = jkr.evaluate(rough.sigma * s);
    const double density = weight * std::exp(-0.5 * (s + h) * (s + h)) / std::sqrt(2.0 * std::numbers::pi);
    sum.force += asperity.force * density;
    sum.forceSlope -= asperity.force * (s + h) * density;
    sum.area += asperity.area * density;
  };
  for (std::size_t p = 0; p + 1 < ends.size(); ++p) {
    const double centre = 0.5 * (ends[p] + ends[p + 1]), half = 0.5 * (ends[p + 1] - ends[p]);
    for (std::size_t k = 0; k < Rule::abscissa().size(); ++k) {
      const double x = Rule::abscissa()[k], weight = half * Rule::weights()[k];
      add(centre + half * x, weight);
      if (x != 0.0) add(centre - half * x, weight);
    }
  }
  sum.force *= rough.asperityCount;
  sum.forceSlope *= rough.asperityCount;
  sum.area *= rough.asperityCount;
  return sum;
}

}  // namespace

NormalResponse RoughJkrLaw::force(const NormalContact& c, double overlap, History&) const {
  if (!(overlap > -4.0 * rough.sigma)) return {.acting = false};  // beyond its range
  const AsperitySums sums = asperitySums(rough, EllipticJkr(c.effectiveModulus, 2.0 * surfaceEnergy, c.radii, curve),
                                         -overlap / rough.sigma);
  // dF/d(delta) = -dF/dh / sigma; the Coulomb limit stays mu F_n
  return {.force = sums.force, .stiffness = -sums.forceSlope / rough.sigma, .area = sums.area};
}

}  // namespace sqdem
