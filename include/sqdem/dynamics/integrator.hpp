#pragma once
// Velocity Verlet for translation and NO_SQUISH for rotation (Miller et al., J. Chem. Phys. 116,
// 8649 (2002); the scheme LAMMPS uses for aspherical
// bodies). Both are symplectic and time-reversible. One step of length h:
//
//   kick(h/2):  v += h/2 F/m;   p += h/2 · 2 q ⊗ (0, τ_body)           (Miller Eq. 2.12)
//   drift(h):   x += h v;       free rotor by the symmetric split
//               R3(h/2) R2(h/2) R1(h) R2(h/2) R3(h/2), where R_k(t) is the exact flow of
//               H_k = (p · P_k q)^2 / (8 I_k), P_k q = q ⊗ e_k:
//               zeta = t (p · P_k q) / (4 I_k); q <- cos zeta q + sin zeta P_k q,
//               p <- cos zeta p + sin zeta P_k p                         (Miller Eqs. 2.14-2.16)
//               (isotropic bodies, I1 = I2 = I3: the exact flow, a rotation by |w| h about
//               the constant world angular velocity w)
//   (forces at the new positions)
//   kick(h/2)
//
// Each R_k is invariant under world rotations, so the world angular momentum of a free body is
// conserved to round-off and the energy error stays bounded (tested on an asymmetric top).

#include "sqdem/dynamics/particle_store.hpp"

namespace sqdem {

/// Half kick of particle i with its force and torque (world frame).
void kick(ParticleStore& particles, std::size_t i, double halfStep);
/// Drift of particle i: translation and, when it `turns`, free rotation over a full step (a body
/// that does not turn keeps its orientation and its world angular momentum: p = 2 (0, L) ⊗ q
/// holds for the fixed q, the kicks stay exact; World::setSphereOrientations).
void drift(ParticleStore& particles, std::size_t i, double step, bool turns = true);

}  // namespace sqdem
