#include "sqdem/mechanics/jkr_circular.hpp"

#include <cmath>
#include <numbers>

namespace sqdem {

using std::numbers::pi;

double CircularJkr::overlapAt(double a) const {
  return a * a / radius - std::sqrt(2.0 * pi * workOfAdhesion * a / effectiveModulus);
}

double CircularJkr::forceAt(double a) const {
  return 4.0 * effectiveModulus * a * a * a / (3.0 * radius) -
         std::sqrt(8.0 * pi * workOfAdhesion * effectiveModulus * a * a * a);
}

double CircularJkr::minimumContactRadius() const {
  return std::cbrt(pi * workOfAdhesion * radius * radius / (8.0 * effectiveModulus));
}

double CircularJkr::contactRadius(double overlap) const {
  // delta(a) is increasing and convex for a >= a_min: Newton from a point with delta(a) >=
  // overlap converges monotonically from above.
  const double aMin = minimumContactRadius();
  if (overlap <= overlapAt(aMin)) return aMin;
  double a = std::max(2.0 * aMin, std::sqrt(radius * std::max(overlap, 0.0)));
  while (overlapAt(a) < overlap) a *= 2.0;
  for (int it = 0; it < 100; ++it) {
    const double slope = 2.0 * a / radius -
                         0.5 * std::sqrt(2.0 * pi * workOfAdhesion / (effectiveModulus * a));
    const double step = (overlapAt(a) - overlap) / slope;
    a -= step;
    if (std::abs(step) <= 1e-15 * a) break;
  }
  return a;
}

double CircularJkr::pullOffForce() const { return 1.5 * pi * workOfAdhesion * radius; }

}  // namespace sqdem
