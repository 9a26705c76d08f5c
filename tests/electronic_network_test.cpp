// The electronic network of the electrode analysis (analysis/conductor_network.hpp,
// electronic_network.hpp) against closed forms: Kirchhoff's laws on resistor lattices and chains
// (series 1/g = sum 1/g_i, parallel g = sum g_i; a simple cubic lattice of bonds g at spacing d
// conducts sigma = g / d), a network without a path conducts nothing and says so, and a contact
// spot's resistance is Holm's elliptic constriction K(e) / (2 pi sigma a) (Holm 1967, Electric
// Contacts, Secs. 4-5): 1 / (4 sigma a) for a circle, ln(4 a / b) / (2 pi sigma a) for a slender
// ellipse; two ellipsoids conduct through the Hertz ellipse of their curvatures (below). A
// lattice of Hertz spheres at overlap delta has a = (R delta / 2)^(1/2) (Hertz: a^2 = R* delta,
// R* = R / 2) and sigma_eff / sigma = 2 a / d.

#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "sqdem/analysis/conductor_network.hpp"
#include "sqdem/analysis/electronic_network.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/electrode_analysis.hpp"
#include "sqdem/scene/scene_loader.hpp"

namespace sqdem {
namespace {

constexpr double ideal = std::numeric_limits<double>::infinity();

/// An N x N x N lattice of nodes at spacing d in a box of edges N d, bonds g along the axes where
/// `along[d]`, periodic in x and y, the bottom layer held at the low electrode and the top at the
/// high one: in plane sigma = g / d, through z N^2 columns of N - 1 bonds, sigma = g N / ((N - 1) d).
ConductorNetwork lattice(int N, double d, double g, std::array<bool, 3> along) {
  ConductorNetwork net;
  net.nodes = static_cast<std::size_t>(N) * N * N;
  net.box = Vec3(N * d, N * d, N * d);
  const auto node = [N](int i, int j, int k) { return static_cast<std::uint32_t>(((i + N) % N) + N * (((j + N) % N) + N * k)); };
  for (int k = 0; k < N; ++k) {
    for (int j = 0; j < N; ++j) {
      for (int i = 0; i < N; ++i) {
        for (int a = 0; a < 3; ++a) {
          if (!along[a] || (a == 2 && k == N - 1)) continue;
          std::array<int, 3> next{i, j, k};
          ++next[a];
          ConductorNetwork::Link l{node(i, j, k), node(next[0], next[1], next[2]), g};
          if (a < 2 && next[a] == N) l.shift[a] = 1;
          l.branch[a] = d;
          net.links.push_back(l);
        }
        if (k == 0) net.low[2].push_back({node(i, j, k), ideal});
        if (k == N - 1) net.high[2].push_back({node(i, j, k), ideal});
      }
    }
  }
  return net;
}

TEST(ConductorNetwork, ACubicLatticeConductsGOverD) {
  const double d = 2e-6, g = 3.5e-4;
  const ConductorNetwork net = lattice(5, d, g, {true, true, true});
  for (int axis = 0; axis < 3; ++axis) {
    const NetworkConduction c = solveConduction(net, axis);
    EXPECT_TRUE(c.percolates);
    EXPECT_NEAR(c.conductivity / (g / d), axis < 2 ? 1.0 : 5.0 / 4.0, 1e-9) << "axis " << axis;
    EXPECT_EQ(c.carryingNodes, net.nodes);
  }
  EXPECT_LT(solveConduction(net, 2).currentImbalance, 1e-9);
}

TEST(ConductorNetwork, ALatticeWithGapsAlongXConductsInYAndZOnly) {
  const double d = 2e-6, g = 3.5e-4;
  const ConductorNetwork net = lattice(4, d, g, {false, true, true});
  const NetworkConduction x = solveConduction(net, 0);
  EXPECT_FALSE(x.percolates);
  EXPECT_EQ(x.conductivity, 0.0);
  EXPECT_EQ(x.carryingNodes, 0u);
  EXPECT_NEAR(solveConduction(net, 1).conductivity / (g / d), 1.0, 1e-9);
  EXPECT_NEAR(solveConduction(net, 2).conductivity / (g / d), 4.0 / 3.0, 1e-9);
}

/// Chains between the electrodes along z (box 1 x 1 x L), each with its own bonds and terminals.
struct Chain {
  double low;                   ///< terminal to the low electrode (S)
  std::vector<double> bonds;    ///< along the chain (S)
  double high;                  ///< terminal to the high one (S)
  double resistance() const {
    double r = (std::isinf(low) ? 0.0 : 1.0 / low) + (std::isinf(high) ? 0.0 : 1.0 / high);
    for (const double g : bonds) r += 1.0 / g;
    return r;
  }
};

ConductorNetwork chains(const std::vector<Chain>& list, double L) {
  ConductorNetwork net;
  net.box = Vec3(1.0, 1.0, L);
  for (const Chain& c : list) {
    const auto first = static_cast<std::uint32_t>(net.nodes);
    net.nodes += c.bonds.size() + 1;
    for (std::size_t k = 0; k < c.bonds.size(); ++k) {
      net.links.push_back({static_cast<std::uint32_t>(first + k), static_cast<std::uint32_t>(first + k + 1), c.bonds[k]});
    }
    net.low[2].push_back({first, c.low});
    net.high[2].push_back({static_cast<std::uint32_t>(net.nodes - 1), c.high});
  }
  return net;
}

TEST(ConductorNetwork, SeriesAndParallelChains) {
  const double L = 3.0;  // sigma = I L / (A dV), A = 1, dV = 1
  const Chain series{2.0, {1.0, 0.25, 4.0, 0.5}, 3.0};
  EXPECT_NEAR(solveConduction(chains({series}, L), 2).conductivity, L / series.resistance(), 1e-12);
  const Chain held{ideal, {1.0, 2.0, 0.125}, ideal};
  EXPECT_NEAR(solveConduction(chains({held}, L), 2).conductivity, L / held.resistance(), 1e-12);
  const NetworkConduction both = solveConduction(chains({series, held}, L), 2);
  EXPECT_NEAR(both.conductivity, L * (1.0 / series.resistance() + 1.0 / held.resistance()), 1e-12);
  EXPECT_LT(both.currentImbalance, 1e-12);
  // A node joined ideally to both electrodes is a short circuit.
  EXPECT_THROW(solveConduction(chains({Chain{ideal, {}, ideal}}, L), 2), std::invalid_argument);
}

TEST(ConductorNetwork, AnIsolatedClusterCarriesNothingAndIsLeftOut) {
  ConductorNetwork net = chains({Chain{1.0, {1.0, 1.0}, 1.0}}, 1.0);
  // Two clusters: one on the low electrode only, one joined to nothing.
  net.nodes += 4;
  net.links.push_back({3, 4, 1.0});
  net.low[2].push_back({3, 1.0});
  net.links.push_back({5, 6, 1.0});
  const NetworkConduction c = solveConduction(net, 2);
  EXPECT_NEAR(c.conductivity, 1.0 / 4.0, 1e-12);
  EXPECT_EQ(c.carryingNodes, 3u);
  for (const std::uint32_t i : {3u, 4u, 5u, 6u}) EXPECT_TRUE(std::isnan(c.potential[i]));
  // A broken chain, 0-1 on the low electrode and 2-3 on the high: no path, no current, and the
  // solver says so.
  ConductorNetwork cut;
  cut.nodes = 4;
  cut.box = Vec3(1.0, 1.0, 1.0);
  cut.links = {{0, 1, 1.0}, {2, 3, 1.0}};
  cut.low[2].push_back({0, ideal});
  cut.high[2].push_back({3, 1.0});
  const NetworkConduction broken = solveConduction(cut, 2);
  EXPECT_FALSE(broken.percolates);
  EXPECT_EQ(broken.conductivity, 0.0);
}

TEST(ConductorNetwork, APeriodicClusterThatDoesNotWrapCarriesNothing) {
  // Three nodes joined across the periodic face of x but not around the period.
  ConductorNetwork net;
  net.nodes = 3;
  net.box = Vec3(10.0, 1.0, 1.0);
  net.links.push_back({0, 1, 1.0, {1, 0, 0}, Vec3(1.0, 0.0, 0.0)});
  net.links.push_back({1, 2, 1.0, {0, 0, 0}, Vec3(1.0, 0.0, 0.0)});
  const NetworkConduction open = solveConduction(net, 0);
  EXPECT_FALSE(open.percolates);
  EXPECT_EQ(open.conductivity, 0.0);
  // Closed around the period by a link from 2 back to 0: a ring of three unit conductances.
  net.links.push_back({2, 0, 1.0, {0, 0, 0}, Vec3(8.0, 0.0, 0.0)});
  const NetworkConduction ring = solveConduction(net, 0);
  EXPECT_TRUE(ring.percolates);
  EXPECT_NEAR(ring.conductivity, (1.0 / 3.0) * 10.0 / 1.0, 1e-12);  // I L / (A dV), A = 1
}

TEST(ElectronicNetwork, HolmsEllipticConstriction) {
  const double sigma = 0.02, a = 3e-7;
  EXPECT_NEAR(spreadingResistance(a, a, sigma) * 4.0 * sigma * a, 1.0, 1e-14);
  for (const double ratio : {0.9, 0.5, 0.2, 0.05}) {
    const double K = boost::math::ellint_1(std::sqrt(1.0 - ratio * ratio));
    EXPECT_NEAR(spreadingResistance(a, ratio * a, sigma) / (K / (2.0 * std::numbers::pi * sigma * a)), 1.0, 1e-13);
  }
  // The slender limit K -> ln(4 a / b) + O((b/a)^2 ln).
  EXPECT_NEAR(spreadingResistance(a, 1e-4 * a, sigma) * 2.0 * std::numbers::pi * sigma * a / std::log(4e4), 1.0, 1e-8);
  EXPECT_EQ(spreadingResistance(a, a, ideal), 0.0);
}

/// A simple cubic lattice of equal spheres (radius R, spacing d = 2 R - delta), N per side, in a
/// box of edges N d periodic in x and y, with the scene's default law (Hertz on spheres).
std::string sphereLattice(int N, double R, double delta, double sigma) {
  const double d = 2.0 * R - delta;
  std::ostringstream s;
  s.precision(17);
  s << "domain: {lo: [0, 0, 0], hi: [" << N * d << ", " << N * d << ", " << N * d << "], periodic: [x, y]}\n"
    << "time_step: 1.0e-9\nmaterials:\n  nmc: {youngs_modulus: 1.0e9, poisson_ratio: 0.3, density: 4700, electronic_conductivity: " << sigma << "}\n"
    << "shapes:\n  ball: {semi_axes: [" << R << ", " << R << ", " << R << "]}\ninteractions:\n  - materials: [nmc, nmc]\nparticles:\n";
  for (int k = 0; k < N; ++k) {
    for (int j = 0; j < N; ++j) {
      for (int i = 0; i < N; ++i) {
        s << "  - {shape: ball, material: nmc, allow_overlap: true, centre: [" << (i + 0.5) * d << ", " << (j + 0.5) * d << ", " << (k + 0.5) * d << "]}\n";
      }
    }
  }
  s << "stages:\n  - {name: hold, duration: 1.0e-9}\n";
  return s.str();
}

TEST(ElectronicNetwork, ALatticeOfHertzSpheresAgainstItsClosedForm) {
  const int N = 4;
  const double R = 2e-6, delta = 1e-8, sigma = 0.05, d = 2.0 * R - delta;
  World world = buildWorld(sceneFromText(sphereLattice(N, R, delta, sigma)));
  world.computeForces();
  // The box's faces cut the bottom and the top layer (R > d / 2): those are held at the
  // electrodes, N - 1 contacts in series between them (the lattice's closed form above).
  const ConductorNetwork net = electronicNetwork(world, world.contactEllipses(), std::vector<double>{sigma}, 0.0, N * d);
  ASSERT_EQ(net.links.size(), 3u * N * N * N - N * N);
  const double a = std::sqrt(R * delta / 2.0);
  for (int axis = 0; axis < 3; ++axis) {
    const NetworkConduction c = solveConduction(net, axis);
    const double expected = 2.0 * a / d * (axis < 2 ? 1.0 : N / (N - 1.0));
    EXPECT_NEAR(c.conductivity / sigma, expected, 1e-9 * expected) << "axis " << axis;
  }
}

// Two equal aligned ellipsoids (semi-axes A > B > C) touching pole to pole along z at overlap
// delta, the lower cut by the low electrode, the upper by the high one: one contact of
// conductance g = pi sigma a / K(e) (two sides of Holm's resistance), sigma_eff = g L / A_box.
// The spot's aspect b / a is Hertz's for the relative curvatures A_h = C / A^2, B_h = C / B^2
// (both bodies' pole curvatures), solved here from Johnson's relation (Contact Mechanics, 1985,
// Eq. 4.39) B_h / A_h = ((a/b)^2 E(e) - K(e)) / (K(e) - E(e)), e^2 = 1 - (b/a)^2, with Boost's
// integrals; its area the law's.
TEST(ElectronicNetwork, TwoEllipsoidsConductThroughTheirEllipticSpot) {
  const double A = 6e-6, B = 4e-6, C = 3e-6, delta = 2e-8, sigma = 0.03, side = 40e-6;
  const double z1 = 3.5e-6, z2 = z1 + 2.0 * C - delta, zLow = 1e-6, zHigh = z2 + 1e-6;
  std::ostringstream text;
  text.precision(17);
  text << "domain: {lo: [0, 0, 0], hi: [" << side << ", " << side << ", 20.0e-6], periodic: [x, y]}\n"
       << "time_step: 1.0e-9\nmaterials:\n  nmc: {youngs_modulus: 1.0e9, poisson_ratio: 0.3, density: 4700, electronic_conductivity: " << sigma << "}\n"
       << "shapes:\n  grain: {semi_axes: [" << A << ", " << B << ", " << C << "]}\ninteractions:\n  - materials: [nmc, nmc]\nparticles:\n"
       << "  - {shape: grain, material: nmc, allow_overlap: true, centre: [20.0e-6, 20.0e-6, " << z1 << "]}\n"
       << "  - {shape: grain, material: nmc, allow_overlap: true, centre: [20.0e-6, 20.0e-6, " << z2 << "]}\n"
       << "stages:\n  - {name: hold, duration: 1.0e-9}\n";
  World world = buildWorld(sceneFromText(text.str()));
  world.computeForces();
  ASSERT_EQ(world.contacts().size(), 1u);
  const double area = (*world.contacts().begin()).normalLoad().area;
  const double curvatureRatio = (C / (B * B)) / (C / (A * A));
  const auto mismatch = [&](double k) {  // k = b / a
    const double e = std::sqrt(1.0 - k * k), K = boost::math::ellint_1(e), E = boost::math::ellint_2(e);
    return (E / (k * k) - K) / (K - E) - curvatureRatio;
  };
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(mismatch, 0.05, 0.999, boost::math::tools::eps_tolerance<double>(50), iterations);
  const double k = 0.5 * (bracket.first + bracket.second), a = std::sqrt(area / (std::numbers::pi * k));
  const double g = std::numbers::pi * sigma * a / boost::math::ellint_1(std::sqrt(1.0 - k * k));
  const ConductorNetwork net = electronicNetwork(world, world.contactEllipses(), std::vector<double>{sigma}, zLow, zHigh);
  ASSERT_EQ(net.links.size(), 1u);
  EXPECT_NEAR(net.links[0].conductance / g, 1.0, 1e-9);
  const NetworkConduction z = solveConduction(net, 2);
  EXPECT_NEAR(z.conductivity / (g * (zHigh - zLow) / (side * side)), 1.0, 1e-9);
  EXPECT_FALSE(solveConduction(net, 0).percolates);
  std::printf("b / a = %.6f, a = %.4g m, g = %.6g S (a circle of the same area: %.6g S)\n", k, a, g,
              2.0 * sigma * std::sqrt(area / std::numbers::pi));
}

// A sphere (radius R) pressed onto the floor by overlap delta, its top cut by the high electrode:
// the floor's contact is the low electrode, Holm's resistance on the sphere's side alone (the
// steel floor conducts ideally: no electronic_conductivity), g = 4 sigma a with Hertz's
// a = (R delta)^(1/2) for a sphere on a plane, and sigma_eff = g L / A_box. A second particle
// material without a conductivity, when the first has one, is refused by name.
TEST(ElectronicNetwork, TheFloorIsTheLowElectrodeThroughItsContacts) {
  const double R = 3e-6, delta = 1e-8, sigma = 0.02, side = 20e-6, zHigh = R;
  const std::string scene =
      "domain: {lo: [0, 0, 0], hi: [2.0e-5, 2.0e-5, 2.0e-5], periodic: [x, y]}\ntime_step: 1.0e-9\nmaterials:\n"
      "  nmc: {youngs_modulus: 1.0e9, poisson_ratio: 0.3, density: 4700, electronic_conductivity: 0.02}\n"
      "  steel: {youngs_modulus: 2.0e11, poisson_ratio: 0.3, density: 7800}\n"
      "shapes:\n  ball: {semi_axes: [3.0e-6, 3.0e-6, 3.0e-6]}\ninteractions:\n  - materials: [nmc, steel]\n  - materials: [nmc, nmc]\n"
      "  - materials: [steel, steel]\nwalls:\n  - {point: [0, 0, 0], normal: [0, 0, 1], material: steel}\nparticles:\n"
      "  - {shape: ball, material: nmc, allow_overlap: true, centre: [1.0e-5, 1.0e-5, 2.99e-6]}\n"
      "stages:\n  - {name: hold, duration: 1.0e-9}\n";
  const Scene parsed = sceneFromText(scene);
  const std::vector<double> conductivity = electronicConductivities(parsed, parsed.particles);
  EXPECT_EQ(conductivity[0], sigma);
  EXPECT_TRUE(std::isinf(conductivity[1]));
  World world = buildWorld(parsed);
  world.computeForces();
  const ConductorNetwork net = electronicNetwork(world, world.contactEllipses(), conductivity, 0.0, zHigh);
  ASSERT_EQ(net.low[2].size(), 1u);
  const double a = std::sqrt(R * delta), g = 4.0 * sigma * a;
  EXPECT_NEAR(net.low[2][0].conductance / g, 1.0, 1e-9);
  EXPECT_NEAR(solveConduction(net, 2).conductivity / (g * zHigh / (side * side)), 1.0, 1e-9);

  Scene mixed = parsed;
  mixed.particles.push_back(mixed.particles[0]);
  mixed.particles.back().material = 1;  // steel particles: a particle material without a conductivity
  try {
    electronicConductivities(mixed, mixed.particles);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("'materials.steel.electronic_conductivity': missing (S/m)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sqdem
