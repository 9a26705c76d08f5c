#include "sqdem/mechanics/roughness_gw.hpp"

#include "sqdem/mechanics/jkr_elliptic.hpp"

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <numbers>

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

/// N A_n int_0^inf g(sigma s) phi(s + h) ds.
template <class G>
double asperitySum(const RoughContact& rough, double h, G g) {
  boost::math::quadrature::exp_sinh<double> integrator;
  return rough.asperityCount * integrator.integrate([&](double s) -> double {
    return g(rough.sigma * s) * std::exp(-0.5 * (s + h) * (s + h)) / std::sqrt(2.0 * std::numbers::pi);
  });
}

}  // namespace

NormalResponse RoughJkrLaw::force(const NormalContact& c, double overlap, History&) const {
  if (!(overlap > -4.0 * rough.sigma)) return {.acting = false};  // beyond its range
  const EllipticJkr jkr(c.effectiveModulus, 2.0 * surfaceEnergy, c.radii);
  const auto forceAt = [&](double h) { return asperitySum(rough, h, [&](double w) { return jkr.evaluate(w).force; }); };
  const double h = -overlap / rough.sigma, step = 1e-4;
  return {.force = forceAt(h),
          .stiffness = (forceAt(h - step) - forceAt(h + step)) / (2.0 * step * rough.sigma),
          .area = asperitySum(rough, h, [&](double w) { return jkr.evaluate(w).area; })};  // Coulomb limit mu F_n
}

}  // namespace sqdem
