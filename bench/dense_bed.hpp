#pragma once
// The benchmarks' dense bed: a fully periodic simple-cubic lattice of one superquadric (affinely
// stretched for ellipsoids, so each particle touches its six neighbours with a 0.5 % overlap,
// mean coordination ~6), small random tilts and velocities; or, still, touching without overlap
// at rest (nothing moves: for costs that must not depend on the motion).

#include <array>
#include <random>

#include "sqdem/world/world.hpp"

namespace sqdem {

struct Case {
  const char* name;
  Superquadric shape;
  bool curvatures;  ///< elliptic Hertz on the curvatures, else volume-sphere Hertz
};

/// The benchmarks' four beds: ellipsoids with and without the curvature-exact law, n = 6
/// blocks, spheres (R = 1 mm).
inline const std::array<Case, 4>& denseBedCases() {
  constexpr double R = 1e-3;
  static const std::array<Case, 4> cases{{
      {"ellipsoids 1:0.8:0.6, elliptic Hertz", Superquadric::ellipsoid(R, 0.8 * R, 0.6 * R), true},
      {"ellipsoids 1:0.8:0.6, volume-sphere Hertz", Superquadric::ellipsoid(R, 0.8 * R, 0.6 * R), false},
      {"superquadrics n = 6, elliptic Hertz", Superquadric(R, 0.8 * R, 0.6 * R, 6.0, 6.0), true},
      {"spheres, Hertz", Superquadric::sphere(R), false},
  }};
  return cases;
}

/// cells: the lattice's particles along x, y and z.
inline World denseBed(const Case& c, const Eigen::Vector3i& cells, std::uint64_t seed, bool still = false) {
  const Vec3 spacing = 2.0 * (still ? 1.0 : 0.995) * c.shape.halfExtents();
  Domain domain;
  domain.hi = cells.cast<double>().cwiseProduct(spacing);
  domain.periodic = {true, true, true};
  const Material m{1e7, 0.3, 1000.0, 0.3, 0.5};
  World world({c.shape}, {m}, domain, 0.1 * c.shape.halfExtents().minCoeff());
  ContactModel model = world.defaultContactModel(0, 0);
  model.curvatures = c.curvatures;
  world.setContactModel(0, 0, model);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> tilt(0.0, 0.02), speed(0.0, 0.01);
  for (int i = 0; i < cells.x(); ++i) {
    for (int j = 0; j < cells.y(); ++j) {
      for (int k = 0; k < cells.z(); ++k) {
        const Vec3 axis(tilt(rng), tilt(rng), tilt(rng));
        const Quat q = axis.norm() > 0 ? Quat(Eigen::AngleAxisd(axis.norm(), axis.normalized())) : Quat::Identity();
        const std::size_t n = world.addParticle(0, 0, (Vec3(i, j, k) + Vec3::Constant(0.5)).cwiseProduct(spacing), q);
        if (!still) world.particles().velocity[n] = Vec3(speed(rng), speed(rng), speed(rng));
      }
    }
  }
  world.setTimeStep(0.2 * world.rayleighTimeStep());
  return world;
}

/// edge^3 particles.
inline World denseBed(const Case& c, int edge, std::uint64_t seed, bool still = false) {
  return denseBed(c, Eigen::Vector3i::Constant(edge), seed, still);
}

}  // namespace sqdem
