#pragma once
// Critical velocities of a sphere hitting a flat wall under Nan et al.'s law (000 Section 4,
// Eqs. 73-79), with R* = R, m* = m = 4/3 pi R^3 rho, k_el = k_p = pi R p_y (Eq. 52), no damping:
//   V_s  = sqrt(2 W_0/m), W_0 = W_JKR (Eq. 35)          adhesive sticking velocity (Eq. 73);
//   V_y0 = sqrt(2 W_y/m)                                 yield velocity without adhesion (Eq. 74);
//   V_y  = sqrt((f_y^2 - f_0^2)/(m k_el))                yield velocity with adhesion (Eq. 75),
//          reported as 0 when f_y < f_0 (the contact yields as soon as it forms, 000 Fig. 9
//          shaded zone);
//   V_ys = V_s if V_y >= V_s, else the fixed point of
//          m V_ys^2/2 = m V_y^2/2 + (f_max^2 - f_y^2)/(2 k_p)       (Eq. 79)
//          with m V_y^2/2 = W_2 - W_1 keeping its sign (negative when f_y < f_0): this reproduces
//          all eight V_ys of Table 6 to their printed digits (clipping at 0 gave +3 to +4.3 %);
//          f_max^2  = f_cp^2 (1 + 56/81 k_e/k_c)                    (Eq. 78)
//          with alpha_max (Eq. 10), k_e (Eq. 46), f_cp (Eq. 59) of nan_adhesive.hpp, iterated
//          from f_max = f_y as the seed prescribes.
// The seed's typos around Eqs. 35-38 and in Table 4 are handled in nan_adhesive.hpp.

namespace sqdem {

struct StickingVelocityInput {
  double radius = 0.0;          ///< R (m)
  double density = 0.0;         ///< rho (kg/m^3)
  double youngs = 0.0;          ///< E of the particle (Pa)
  double poisson = 0.0;         ///< nu of the particle
  double wallYoungs = 0.0;      ///< E of the wall (Pa)
  double wallPoisson = 0.0;     ///< nu of the wall
  double workOfAdhesion = 0.0;  ///< W = 2 gamma (J/m^2), the seed's Gamma in f_ce = 3/2 pi Gamma R
  double yieldPressure = 0.0;   ///< p_y (Pa), the softer body's yield contact pressure
};

struct StickingVelocities {
  double Vs = 0.0, Vy0 = 0.0, Vy = 0.0, Vys = 0.0;  ///< (m/s)
  int iterations = 0;                               ///< fixed-point iterations for V_ys
};

StickingVelocities stickingVelocities(const StickingVelocityInput& input);

}  // namespace sqdem
