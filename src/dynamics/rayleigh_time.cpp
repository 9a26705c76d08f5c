#include "sqdem/dynamics/rayleigh_time.hpp"

#include <cmath>
#include <numbers>

namespace sqdem {

double rayleighTimeStep(double radius, double density, double shearModulus, double poisson) {
  return std::numbers::pi * radius * std::sqrt(density / shearModulus) / (0.1631 * poisson + 0.8766);
}

}  // namespace sqdem
