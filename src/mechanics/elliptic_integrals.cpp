#include "sqdem/mechanics/elliptic_integrals.hpp"

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <numbers>

namespace sqdem {
namespace {

/// C(m) = int_0^{pi/2} sin^2 cos^2 / (1 - m sin^2)^{3/2}: binomial series of the denominator,
/// term ratio m (k + 3/2)^2 / ((k + 1)(k + 3)), first term pi/16.
double seriesC(double m) {
  double term = std::numbers::pi / 16.0, sum = term;
  for (int k = 0; k < 200 && term > 1e-17 * sum; ++k) {
    term *= m * (k + 1.5) * (k + 1.5) / ((k + 1.0) * (k + 3.0));
    sum += term;
  }
  return sum;
}

}  // namespace

EllipticIntegrals ellipticIntegrals(double m, double oneMinusM) {
  EllipticIntegrals I;
  I.K = boost::math::ellint_rf(0.0, oneMinusM, 1.0);
  I.D = boost::math::ellint_rd(0.0, oneMinusM, 1.0) / 3.0;
  I.E = I.K - m * I.D;
  I.B = I.K - I.D;
  I.C = m < 0.25 ? seriesC(m) : (I.D - I.B) / m;
  return I;
}

}  // namespace sqdem
