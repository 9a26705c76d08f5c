#pragma once
// Rayleigh time of a particle (000 Eq. 71): the time a Rayleigh surface wave takes to cross it,
// pi R sqrt(rho / G) / (0.1631 nu + 0.8766) (s). Explicit DEM steps are a fraction of it.

namespace sqdem {

/// radius R (m), density rho (kg/m^3), shear modulus G (Pa), Poisson ratio nu.
double rayleighTimeStep(double radius, double density, double shearModulus, double poisson);

}  // namespace sqdem
