#pragma once
// Numerical health of a running World, checked cheaply every few steps (O(N) sweeps):
//
//  - non-finite state: any position, velocity, angular momentum or force that is NaN or inf;
//  - runaway energy: the kinetic energy exceeds 10 x the energy the run can have been given,
//      budget = E_kin(0) + E_el(0) + sum m |g| L_g + W_walls + sum m (1 m/s)^2 / 2,
//    with E_el(0) = sum 2/5 F_n delta over the initial contacts (Hertz: the stored elastic
//    energy), L_g the domain's extent along gravity (the largest fall), W_walls the accumulated
//    |F . v| dt of the moving walls, and a floor of 1 m/s per particle so that a scene starting
//    at rest without gravity has room for adhesion and small disturbances. A stable explicit
//    integration conserves or dissipates energy; an unstable one grows it geometrically, far
//    past this bound within a few dozen steps. State set between steps (scene/simulation.hpp)
//    adds the kinetic energy it gave, and after the next step the elastic energy of the
//    contacts then (the overlaps a moved particle made), to the budget (stateEdited);
//  - growing deep overlaps: contacts deeper than half the smaller volume radius in 10
//    consecutive checks (ContactStatistics::deepOverlaps: not those a model expects).

#include <cstdint>
#include <string>

#include "sqdem/world/world.hpp"

namespace sqdem {

class RunHealth {
 public:
  static constexpr int checkEvery = 10;  ///< steps between the O(N) checks

  /// Takes the energy budget from the world's current state (forces must be current).
  explicit RunHealth(const World& world);

  /// Call after every step; returns what went wrong, or an empty string.
  std::string afterStep(const World& world);

  double budget() const { return budget_ + wallWork_; }  ///< (J)
  /// Particle state was set between steps, giving them kineticGiven (J, >= 0).
  void stateEdited(double kineticGiven) {
    budget_ += kineticGiven;
    elasticPending_ = true;
  }

 private:
  double budget_ = 0.0, wallWork_ = 0.0;
  long steps_ = 0;
  long long lastDeepOverlaps_ = 0;
  int deepStreak_ = 0;
  bool elasticPending_ = false;  ///< the next step adds its contacts' elastic energy to the budget
};

}  // namespace sqdem
