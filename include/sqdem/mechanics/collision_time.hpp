#pragma once
// Duration of an elastic Hertz impact (Johnson, Contact Mechanics, 1985, §11.4):
//   t_c = 2.9432 delta_max / v,  delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^2/5
//       = 2.868 (m*^2 / (R* E*^2 v))^1/5
// for effective mass m* (kg), radius R* (m), modulus E* (Pa) and impact speed v (m/s).
// 2.9432 = 2 int_0^1 dx / sqrt(1 - x^5/2).

#include <cmath>

namespace sqdem {

inline double hertzCollisionTime(double effectiveMass, double effectiveRadius, double effectiveModulus, double speed) {
  const double maxOverlap = std::pow(15.0 * effectiveMass * speed * speed / (16.0 * effectiveModulus * std::sqrt(effectiveRadius)), 0.4);
  return 2.9432 * maxOverlap / speed;
}

}  // namespace sqdem
