// The pore solver (analysis/pore_diffusion.hpp, voxel_operator.hpp) on a classical cell problem
// near touching, where the voxels must resolve narrow throats: label validation (28 s).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "sqdem/analysis/pore_diffusion.hpp"
#include "sqdem/analysis/voxel_image.hpp"

namespace sqdem {
namespace {

// A simple cubic array of insulating spheres up to touching (phi = pi/6) against the multipole
// solution of the cell problem by Blees & Leyte (1994, J. Colloid Interface Sci. 166, 118-127),
// D_eff / (eps D0) = 1 / tau, interpolated linearly between their tabulated points
// (docs/electrode_analysis.md, "Accuracy", says where the numbers come from). The voxel answer
// converges at first order in the voxel edge h (the staircase surface), so it is extrapolated
// from 128 and 192 voxels per cell, 1/tau(0) = 1/tau(h2) + (1/tau(h2) - 1/tau(h1)) h2 / (h1 - h2).
TEST(PoreDiffusion, AnArrayOfInsulatingSpheresNearTouchingMatchesTheMultipoleSolution) {
  struct Point {
    double phi, inverseTau;
  };
  // Pairs of Blees & Leyte's points around each solid fraction below (the last pair, which ends at
  // phi = 0.522, extended to pi/6).
  const std::vector<std::array<Point, 2>> bracket{{{{0.295968, 0.866831}, {0.302590, 0.863309}}},
                                                  {{{0.399085, 0.817513}, {0.402867, 0.814697}}},
                                                  {{{0.499330, 0.748508}, {0.505002, 0.743580}}},
                                                  {{{0.517289, 0.730208}, {0.522011, 0.723171}}}};
  const std::vector<double> fractions{0.30, 0.40, 0.50, std::numbers::pi / 6.0};
  for (std::size_t f = 0; f < fractions.size(); ++f) {
    const double phi = fractions[f], radius = std::cbrt(3.0 * phi / (4.0 * std::numbers::pi));
    const auto& [a, b] = bracket[f];
    const double reference = a.inverseTau + (phi - a.phi) / (b.phi - a.phi) * (b.inverseTau - a.inverseTau);
    const Superquadric sphere = Superquadric::sphere(std::min(radius, 0.5));
    const std::vector<PlacedShape> cell{{&sphere, Vec3(0.5, 0.5, 0.5), Quat::Identity()}};
    std::array<double, 2> inverseTau{};
    const std::array<int, 2> voxels{128, 192};
    for (int i = 0; i < 2; ++i) {
      const VoxelImage image = voxelise(cell, Vec3::Zero(), Vec3::Ones(), {true, true, false}, voxels[i]);
      const PoreDiffusion r = solvePoreDiffusion(image, 2, true);
      ASSERT_TRUE(r.converged);
      inverseTau[i] = 1.0 / r.tortuosityFactor;
    }
    const double h1 = 1.0 / voxels[0], h2 = 1.0 / voxels[1];
    const double extrapolated = inverseTau[1] + (inverseTau[1] - inverseTau[0]) * h2 / (h1 - h2);
    const double error = extrapolated / reference - 1.0;
    std::printf("phi %.4f: 1/tau %.5f (128 voxels), %.5f (192), extrapolated %.5f; Blees & Leyte %.5f (error %+.2e)\n", phi,
                inverseTau[0], inverseTau[1], extrapolated, reference, error);
    EXPECT_LT(std::abs(error), 5e-3) << "phi " << phi;
  }
}

}  // namespace
}  // namespace sqdem
