#pragma once
// Complete elliptic integrals of parameter m = e^2 used by the elliptic contact laws:
//   K(m), E(m)                      first and second kind;
//   D(m) = (K - E)/m                004 Eq. 24;
//   B(m) = K - D                    004 Eq. 25;
//   C(m) = (D - B)/m                004 Eq. 26, C(0) = pi/16.
// K and D come from Carlson's R_F and R_D with the complementary parameter 1 - m passed directly,
// so nothing cancels as m -> 1; C is summed as a power series below m = 1/4, where (D - B)/m
// would lose digits, and taken from its definition above.

namespace sqdem {

struct EllipticIntegrals {
  double K = 0.0, E = 0.0, B = 0.0, C = 0.0, D = 0.0;
};

/// All five integrals at m in [0, 1); oneMinusM = 1 - m when the caller has it more accurately.
EllipticIntegrals ellipticIntegrals(double m, double oneMinusM);
inline EllipticIntegrals ellipticIntegrals(double m) { return ellipticIntegrals(m, 1.0 - m); }

}  // namespace sqdem
