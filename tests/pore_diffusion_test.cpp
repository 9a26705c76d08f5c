// The pore transport of the electrode analysis (analysis/voxel_image.hpp, pore_diffusion.hpp)
// against closed forms: an open box and straight channels conduct with tortuosity factor 1
// exactly (the finite volumes are exact for a linear profile), a blocked path gives nothing, and
// a simple cubic array of insulating spheres approaches Maxwell's effective conductivity
// 2 (1 - phi) / (2 + phi) (Maxwell 1873, A Treatise on Electricity and Magnetism, Art. 314; for the
// simple cubic array Rayleigh 1892, Phil. Mag. 34, 481-502, adds terms of order phi^(10/3): 5e-5
// at phi = 0.05) as the voxels shrink.

#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <cstring>
#include <random>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "sqdem/analysis/pore_diffusion.hpp"
#include "sqdem/analysis/voxel_image.hpp"

namespace sqdem {
namespace {

/// An image of the given size and voxel edges, pore where `pore(i, j, k)`.
template <typename F>
VoxelImage imageOf(std::array<int, 3> size, const Vec3& voxel, F&& pore) {
  VoxelImage image;
  image.size = size;
  image.voxel = voxel;
  image.pore.resize(image.count());
  for (int k = 0; k < size[2]; ++k) {
    for (int j = 0; j < size[1]; ++j) {
      for (int i = 0; i < size[0]; ++i) image.pore[image.index(i, j, k)] = pore(i, j, k) ? 1 : 0;
    }
  }
  return image;
}

TEST(PoreDiffusion, AnOpenBoxConductsAsTheFreeSpace) {
  const VoxelImage open = imageOf({7, 5, 9}, Vec3(1.0, 1.5, 0.7), [](int, int, int) { return true; });
  for (int axis = 0; axis < 3; ++axis) {
    for (const bool periodic : {true, false}) {
      const PoreDiffusion r = solvePoreDiffusion(open, axis, periodic);
      EXPECT_TRUE(r.percolates);
      EXPECT_NEAR(r.diffusivityRatio, 1.0, 1e-9) << "axis " << axis;
      EXPECT_NEAR(r.tortuosityFactor, 1.0, 1e-9) << "axis " << axis;
      EXPECT_LT(r.fluxImbalance, 1e-9);
      // The profile is linear: c = 1 - (x + h/2) / L at the voxel centres.
      EXPECT_NEAR(r.concentration[open.index(0, 0, 0)], 1.0 - 0.5 / open.size[axis], 1e-9);
    }
  }
}

// Channels along z (pore where i % 4 < 2 and j % 4 < 2: a quarter of the box): D_eff / D0 = eps,
// tau = 1 along z; along x and y the channels are closed: no path.
TEST(PoreDiffusion, StraightChannelsHaveTortuosityFactorOne) {
  const VoxelImage channels = imageOf({8, 8, 12}, Vec3(1.0, 1.0, 1.0), [](int i, int j, int) { return i % 4 < 2 && j % 4 < 2; });
  const PoreDiffusion z = solvePoreDiffusion(channels, 2, true);
  EXPECT_DOUBLE_EQ(z.porosity, 0.25);
  EXPECT_NEAR(z.diffusivityRatio, 0.25, 1e-9);
  EXPECT_NEAR(z.tortuosityFactor, 1.0, 1e-9);
  for (const int axis : {0, 1}) {
    const PoreDiffusion across = solvePoreDiffusion(channels, axis, true);
    EXPECT_FALSE(across.percolates);
    EXPECT_EQ(across.diffusivityRatio, 0.0);
    EXPECT_EQ(across.tortuosityFactor, std::numeric_limits<double>::infinity());
  }
}

// A slab of pore (x < 3 of 10) between solid: along z and y it conducts with tau = 1; a solid
// layer across z stops it; an isolated pore pocket is left out (NaN) and changes nothing.
TEST(PoreDiffusion, ASlabConductsAlongItAndALayerBlocksIt) {
  const auto slab = [](int i, int, int) { return i < 3; };
  const VoxelImage image = imageOf({10, 6, 8}, Vec3(1.0, 1.0, 1.0), slab);
  for (const int axis : {1, 2}) {
    const PoreDiffusion r = solvePoreDiffusion(image, axis, true);
    EXPECT_NEAR(r.diffusivityRatio, 0.3, 1e-9);
    EXPECT_NEAR(r.tortuosityFactor, 1.0, 1e-9);
  }
  const VoxelImage pocket = imageOf({10, 6, 8}, Vec3(1.0, 1.0, 1.0), [&](int i, int j, int k) { return slab(i, j, k) || (i == 6 && j == 3 && k == 4); });
  const PoreDiffusion withPocket = solvePoreDiffusion(pocket, 2, true);
  EXPECT_NEAR(withPocket.diffusivityRatio, 0.3, 1e-9);
  EXPECT_TRUE(std::isnan(withPocket.concentration[pocket.index(6, 3, 4)]));
  const VoxelImage blocked = imageOf({10, 6, 8}, Vec3(1.0, 1.0, 1.0), [&](int i, int j, int k) { return slab(i, j, k) && k != 5; });
  const PoreDiffusion none = solvePoreDiffusion(blocked, 2, true);
  EXPECT_FALSE(none.percolates);
  EXPECT_EQ(none.diffusivityRatio, 0.0);
  EXPECT_EQ(none.concentration[blocked.index(0, 0, 0)], 1.0);  // connected to the inlet only
  EXPECT_EQ(none.concentration[blocked.index(0, 0, 7)], 0.0);  // to the outlet only
}

// A sphere voxelised in a periodic box: the same voxels wherever it sits by whole voxels (here
// across the box's corner), and its volume within the staircase's O(h) of 4/3 pi R^3.
TEST(VoxelImage, APeriodicSphereKeepsItsVoxelsAcrossTheBoxFaces) {
  const Superquadric sphere = Superquadric::sphere(0.3);
  const std::array<bool, 3> periodic{true, true, true};
  const std::vector<PlacedShape> middle{{&sphere, Vec3(0.5, 0.5, 0.5), Quat::Identity()}};
  const std::vector<PlacedShape> corner{{&sphere, Vec3(0.0, 1.0, 0.0), Quat::Identity()}};
  const VoxelImage a = voxelise(middle, Vec3::Zero(), Vec3::Ones(), periodic, 40);
  const VoxelImage b = voxelise(corner, Vec3::Zero(), Vec3::Ones(), periodic, 40);
  EXPECT_EQ(a.porosity(), b.porosity());
  const double solid = 1.0 - a.porosity(), exact = 4.0 / 3.0 * std::numbers::pi * 0.027;
  EXPECT_NEAR(solid, exact, 3.0 * 0.025 / 0.3 * exact);  // 3 h / R relative, h = 1/40
}

// A simple cubic array of insulating spheres (one per periodic cell) at phi = 0.05: the pore
// phase conducts at Maxwell's 2 (1 - phi) / (2 + phi), tau = 1 + phi / 2, with phi the voxels' own
// solid fraction; the voxel error falls as the voxels shrink (printed).
TEST(PoreDiffusion, AnArrayOfInsulatingSpheresApproachesMaxwell) {
  const double phi = 0.05, radius = std::cbrt(3.0 * phi / (4.0 * std::numbers::pi));
  const Superquadric sphere = Superquadric::sphere(radius);
  const std::vector<PlacedShape> cell{{&sphere, Vec3(0.5, 0.5, 0.5), Quat::Identity()}};
  double previous = 1.0;
  for (const int n : {24, 48}) {
    const VoxelImage image = voxelise(cell, Vec3::Zero(), Vec3::Ones(), {true, true, false}, n);
    const PoreDiffusion r = solvePoreDiffusion(image, 2, true);
    const double f = 1.0 - image.porosity(), maxwell = 2.0 * (1.0 - f) / (2.0 + f);
    const double error = std::abs(r.diffusivityRatio / maxwell - 1.0);
    std::printf("N = %d: phi %.5f, D_eff/D0 %.6f, Maxwell %.6f (error %.2e), tau %.5f, %ld CG iterations\n", n, f,
                r.diffusivityRatio, maxwell, error, r.tortuosityFactor, r.iterations);
    EXPECT_LT(error, previous);
    EXPECT_LT(error, 0.01);
    previous = error;
  }
}

// A random image (55 % pore, odd sizes along the periodic axes so that the multigrid's last
// blocks are single layers): the preconditioned solve converges, conserves the flux to its
// tolerance, and gives the same bits with one thread as with two (voxel_operator.hpp).
TEST(PoreDiffusion, ARandomImageConvergesAndIsTheSameBitsWithAnyThreadCount) {
  std::mt19937_64 random(29);
  std::bernoulli_distribution pore(0.55);
  const VoxelImage image = imageOf({37, 29, 40}, Vec3(1.0, 1.2, 0.9), [&](int, int, int) { return pore(random); });
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const PoreDiffusion one = solvePoreDiffusion(image, 2, true);
  omp_set_num_threads(2);
  const PoreDiffusion two = solvePoreDiffusion(image, 2, true);
  omp_set_num_threads(threads);
  std::printf("random image: D_eff/D0 %.6f, tau %.4f, %ld CG iterations, flux imbalance %.1e\n", one.diffusivityRatio,
              one.tortuosityFactor, one.iterations, one.fluxImbalance);
  ASSERT_TRUE(one.percolates);
  EXPECT_TRUE(one.converged);
  EXPECT_LT(one.fluxImbalance, 1e-8);
  EXPECT_EQ(one.diffusivityRatio, two.diffusivityRatio);
  EXPECT_EQ(one.iterations, two.iterations);
  EXPECT_EQ(0, std::memcmp(one.concentration.data(), two.concentration.data(), one.concentration.size() * sizeof(double)));
}

TEST(PoreDiffusion, RefusesAnEmptyImageAndABadAxis) {
  EXPECT_THROW(solvePoreDiffusion(VoxelImage{}, 2, true), std::invalid_argument);
  const VoxelImage open = imageOf({2, 2, 2}, Vec3(1.0, 1.0, 1.0), [](int, int, int) { return true; });
  EXPECT_THROW(solvePoreDiffusion(open, 3, true), std::invalid_argument);
}

}  // namespace
}  // namespace sqdem
