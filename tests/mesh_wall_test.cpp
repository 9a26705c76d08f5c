// Mesh walls in the engine (issue 13: "a plane and a cylinder given as meshes give the same
// contact forces as the analytic bodies on a small scene").
//   plane     A bed of ellipsoids poured onto a floor given as an STL grid of 200 triangles (its
//             particles slide across the triangles' edges) and onto the analytic plane, from
//             one scene file each: without friction the runs are the same bit for bit (a face
//             contact is the plane's closed form; coplanar faces share their edges without
//             double counting). With friction the tangential spring restarts when a touch
//             passes to the neighbouring face (one contact per feature, each with its own
//             history): the difference is measured and stated, not hidden.
//   cylinder  A faceted cylinder (N flat facets, circumscribed: the facets' centre lines at the
//             radius R) against the analytic one: a sphere under a facet's centre line has the
//             same overlap and normal; the force is the sphere-on-plane force (a facet is flat:
//             0 curvature where the cylinder has 1/R), which equals the cylinder's for a law
//             that does not use curvatures (volume_sphere_hertz). Under an edge between facets
//             the overlap is larger by the edge's distance beyond the radius,
//             R (1 / cos(pi / N) - 1).
//   turning   A flat mesh turning about its normal (a turntable, angular_velocity in the scene)
//             under a sphere at rest: the table's orientation is exp(Omega t); friction drags the
//             sphere along the table's surface velocity Omega x r until it rolls without
//             slipping (its contact point moves with the table), and then its velocity turns
//             at 2 Omega / 7 (differentiating the no-slip condition with I = 2 m r^2 / 5:
//             dv/dt = I / (I + m r^2) Omega z x v);
//             the sphere brakes the table (torque against Omega); the energy ledger, whose
//             bodies' work includes T . Omega, balances.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>

#include "sqdem/contact/detector.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/scene_loader.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

std::filesystem::path scratch(const std::string& name) { return std::filesystem::temp_directory_path() / ("sqdem_test_" + name); }

/// An ASCII STL of the square [lo, hi]^2 at z = 0, facing +z, as cells x cells quads.
void writeFloor(const std::filesystem::path& path, double lo, double hi, int cells) {
  std::ofstream out(path);
  out.precision(17);
  out << "solid floor\n";
  const auto x = [&](int i) { return lo + (hi - lo) * i / cells; };
  const auto facet = [&](double x0, double y0, double x1, double y1, double x2, double y2) {
    out << "facet normal 0 0 1\nouter loop\n";
    out << "vertex " << x0 << ' ' << y0 << " 0\nvertex " << x1 << ' ' << y1 << " 0\nvertex " << x2 << ' ' << y2 << " 0\n";
    out << "endloop\nendfacet\n";
  };
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      facet(x(i), x(j), x(i + 1), x(j), x(i + 1), x(j + 1));
      facet(x(i), x(j), x(i + 1), x(j + 1), x(i), x(j + 1));
    }
  }
  out << "endsolid floor\n";
}

/// The poured bed's scene with the floor `floor` (a YAML wall entry) and friction mu.
std::filesystem::path writeScene(const std::string& name, const std::string& floor, double friction) {
  const std::filesystem::path path = scratch(name + ".yaml");
  std::ofstream out(path);
  out << "seed: 5\n"
         "domain: {lo: [0, 0, 0], hi: [0.01, 0.01, 0.02], periodic: [x, y]}\n"
         "gravity: [0, 0, -9.81]\n"
         "time_step: auto\n"
         "materials:\n"
         "  grain: {youngs_modulus: 1.0e7, poisson_ratio: 0.3, density: 2500, friction: "
      << friction
      << ", restitution: 0.5}\n"
         "shapes:\n"
         "  grain: {semi_axes: [0.8e-3, 0.5e-3, 0.4e-3]}\n"
         "interactions:\n"
         "  - {materials: [grain, grain], normal: elliptic_hertz, tangential: elliptic_mindlin}\n"
         "walls:\n"
         "  - "
      << floor
      << "\n"
         "insert:\n"
         "  - {count: 40, shape: grain, material: grain, region: {lo: [0, 0, 1.0e-3], hi: [0.01, 0.01, 0.008]}}\n"
         "stages:\n"
         "  - {name: pour, duration: 0.05}\n";
  return path;
}

struct Pour {
  std::vector<double> floorForce;  ///< the floor's z force every step (N; < 0: the bed presses down)
  std::vector<Vec3> positions;     ///< at the end, by particle id
  long long meshContactsSeen = 0;
};

Pour pour(const std::filesystem::path& scene, int steps) {
  World world = buildWorld(loadScene(scene.string()));
  Pour p;
  for (int s = 1; s <= steps; ++s) {
    world.step();
    p.floorForce.push_back(world.walls()[0].force.z());
    for (const ContactView c : world.contacts()) p.meshContactsSeen += c.onWall() && c.feature() > 0;
  }
  p.positions.resize(world.particles().size());
  for (std::size_t i = 0; i < world.particles().size(); ++i) p.positions[world.particles().id[i]] = world.particles().position[i];
  return p;
}

TEST(MeshWall, FrictionlessPourOnAMeshFloorIsThePlanesBitForBit) {
  writeFloor(scratch("floor.stl"), -0.002, 0.012, 10);
  const Pour plane = pour(writeScene("plane_floor", "{point: [0, 0, 0], normal: [0, 0, 1], material: grain}", 0.0), 40000);
  const Pour mesh = pour(writeScene("mesh_floor", "{mesh: sqdem_test_floor.stl, point: [0, 0, 0], material: grain}", 0.0), 40000);
  ASSERT_EQ(plane.floorForce.size(), mesh.floorForce.size());
  EXPECT_LT(plane.floorForce.back(), 0.0);  // the bed rests on the floor
  EXPECT_GT(mesh.meshContactsSeen, 0);      // on faces other than the first
  for (std::size_t k = 0; k < plane.floorForce.size(); ++k) ASSERT_EQ(plane.floorForce[k], mesh.floorForce[k]) << "step " << k + 1;
  for (std::size_t i = 0; i < plane.positions.size(); ++i) EXPECT_EQ(plane.positions[i], mesh.positions[i]) << "particle " << i;
}

TEST(MeshWall, WithFrictionTheSpringRestartsAtFaceEdges) {
  writeFloor(scratch("floor.stl"), -0.002, 0.012, 10);
  const Pour plane = pour(writeScene("plane_floor_mu", "{point: [0, 0, 0], normal: [0, 0, 1], material: grain}", 0.5), 40000);
  const Pour mesh = pour(writeScene("mesh_floor_mu", "{mesh: sqdem_test_floor.stl, point: [0, 0, 0], material: grain}", 0.5), 40000);
  std::size_t first = 0;
  while (first < plane.floorForce.size() && plane.floorForce[first] == mesh.floorForce[first]) ++first;
  std::cout << "friction 0.5: the floor forces are equal bit for bit up to step " << first << " of " << plane.floorForce.size()
            << "; at the end the bed's load " << -plane.floorForce.back() << " N (plane) and " << -mesh.floorForce.back()
            << " N (mesh); the pours differ from there on (a granular pour is chaotic: any difference grows)\n";
  EXPECT_GT(first, 0u);  // identical until a frictional touch first crosses a face edge
  EXPECT_LT(plane.floorForce.back(), 0.0);
  EXPECT_NEAR(mesh.floorForce.back() / plane.floorForce.back(), 1.0, 0.05);  // the bed's weight either way, at rest
}

/// The lateral surface of a cylinder along y through the origin as a mesh of `facets` flat
/// facets whose centre lines lie at radius R (vertices at R / cos(pi / facets)), y in [-h, h].
TriangleMesh facetedCylinder(double R, int facets, double h) {
  TriangleMesh m;
  const double corner = R / std::cos(std::numbers::pi / facets);
  for (int k = 0; k < facets; ++k) {
    // Facet k is centred on the angle 2 pi k / facets from -z towards +x; its vertices half a step either side.
    const double angle = 2.0 * std::numbers::pi * (k + 0.5) / facets;
    const Vec3 radial(corner * std::sin(angle), 0.0, -corner * std::cos(angle));
    m.vertices.push_back(radial - h * Vec3::UnitY());
    m.vertices.push_back(radial + h * Vec3::UnitY());
  }
  for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(facets); ++k) {
    const std::uint32_t a = 2 * k, b = 2 * ((k + 1) % facets);  // outward: counter-clockwise seen from outside
    m.triangles.push_back({a, a + 1, b + 1});
    m.triangles.push_back({a, b + 1, b});
  }
  return m;
}

TEST(MeshWall, FacetedCylinderUnderAFacetAndUnderAnEdge) {
  const double R = 5e-3, r = 1e-3, squeeze = 2e-6;
  const int facets = 64;
  const Superquadric ball = Superquadric::sphere(r);
  const MeshFeatures mesh(facetedCylinder(R, facets, 0.02));
  const Vec3 axis(0.0, 0.0, R + r - squeeze);  // the particle at the origin, the axis above it
  const Cylinder cylinder{axis, Vec3::UnitY(), R};
  const auto contacts = [&](const Pose& pose) {
    std::vector<ContactGeometry> found;
    for (std::uint32_t f = 0; f < mesh.featureCount(); ++f) {
      const ContactGeometry g = detectContact(ball, pose, mesh, Pose{axis, Quat::Identity()}, f);
      if (g.touching()) found.push_back(g);
    }
    return found;
  };
  // Under the facet k = 0 (centred straight below the axis).
  const std::vector<ContactGeometry> facet = contacts(Pose{});
  const ContactGeometry exact = detectContact(ball, Pose{}, cylinder);
  ASSERT_EQ(facet.size(), 1u);
  EXPECT_NEAR(facet[0].overlap, exact.overlap, 1e-18);
  EXPECT_NEAR((facet[0].normal - exact.normal).norm(), 0.0, 1e-15);
  EXPECT_EQ(facet[0].curvatureB.k1, 0.0);
  EXPECT_EQ(exact.curvatureB.k1, 1.0 / R);
  // Under the edge between facets 0 and 1: rotate the particle's position about the axis.
  const double half = std::numbers::pi / facets;
  const Vec3 underEdge = axis + Eigen::AngleAxisd(-half, Vec3::UnitY()) * (Vec3::Zero() - axis);
  const std::vector<ContactGeometry> edge = contacts(Pose{underEdge, Quat::Identity()});
  const ContactGeometry exactThere = detectContact(ball, Pose{underEdge, Quat::Identity()}, cylinder);
  ASSERT_EQ(edge.size(), 1u);
  EXPECT_NEAR(edge[0].overlap - exactThere.overlap, R * (1.0 / std::cos(half) - 1.0), 1e-17);
  std::cout << facets << " facets of a " << R << " m cylinder: under an edge the overlap is " << edge[0].overlap << " m against "
            << exactThere.overlap << " m on the cylinder (+" << R * (1.0 / std::cos(half) - 1.0) << " m)\n";
}

/// The roller pressing a sphere onto a floor (materials: 0 grain, 1 steel), the roller either
/// analytic or the faceted mesh; the law with or without the surfaces' curvatures.
double rollerForce(bool asMesh, bool curvatures) {
  const double R = 5e-3, r = 1e-3, squeeze = 2e-6;
  Domain box;
  box.lo = Vec3::Constant(-0.1);
  box.hi = Vec3::Constant(0.1);
  const Material grain{1e8, 0.3, 2500.0, 0.0, 0.5}, steel{2e8, 0.3, 7800.0, 0.0, 0.5};
  World world({Superquadric::sphere(r)}, {grain, steel}, box, 1e-4);
  for (std::uint32_t a = 0; a < 2; ++a) {
    for (std::uint32_t b = a; b < 2; ++b) {
      ContactModel model = world.defaultContactModel(a, b);
      model.curvatures = curvatures;
      world.setContactModel(a, b, model);
    }
  }
  Wall roller{.material = 1};
  const Vec3 axis(0.0, 0.0, r + R - squeeze);
  if (asMesh) {
    roller.surface = MeshWall{.mesh = world.addMesh(MeshFeatures(facetedCylinder(R, 64, 0.02))), .origin = axis};
  } else {
    roller.surface = CylinderWall{Cylinder{axis, Vec3::UnitY(), R}};
  }
  world.addWall(roller);
  world.addParticle(0, 0, Vec3::Zero(), Quat::Identity());
  world.setTimeStep(1e-8);
  world.computeForces();
  return world.walls()[0].force.z();
}

TEST(MeshWall, FacetedRollerForceInTheEngine) {
  const double meshPlain = rollerForce(true, false), exactPlain = rollerForce(false, false);
  const double meshCurved = rollerForce(true, true), exactCurved = rollerForce(false, true);
  EXPECT_GT(exactPlain, 0.0);
  EXPECT_NEAR(meshPlain / exactPlain - 1.0, 0.0, 1e-12);  // volume-equivalent spheres: the same force
  std::cout << "curvature-exact law: faceted " << meshCurved << " N, cylinder " << exactCurved << " N (ratio "
            << meshCurved / exactCurved << ": the facet is flat where the cylinder has 1/R)\n";
  EXPECT_LT(meshCurved, exactCurved * 1.2);
  EXPECT_GT(meshCurved, exactCurved);  // a flat counter-surface gives a larger contact: stiffer
}

TEST(MeshWall, TurntableDragsASphereUntilItRolls) {
  writeFloor(scratch("table.stl"), -0.02, 0.02, 1);  // two triangles, their shared edge along y = x
  const double Omega = 20.0, r = 1e-3;
  const Vec3 start(5e-3, -3e-3, r - 1.25e-7);  // resting (Hertz overlap under its weight), 5.7 mm from the edge
  const std::filesystem::path path = scratch("turntable.yaml");
  std::ofstream(path) << "seed: 1\n"
                         "domain: {lo: [-0.03, -0.03, -0.01], hi: [0.03, 0.03, 0.01]}\n"
                         "gravity: [0, 0, -9.81]\n"
                         "time_step: auto\n"
                         "materials:\n"
                         "  grain: {youngs_modulus: 1.0e8, poisson_ratio: 0.3, density: 2500, friction: 0.5, restitution: 0.5}\n"
                         "shapes:\n"
                         "  ball: {semi_axes: [1.0e-3, 1.0e-3, 1.0e-3]}\n"
                         "interactions:\n"
                         "  - {materials: [grain, grain], normal: elliptic_hertz, tangential: elliptic_mindlin}\n"
                         "walls:\n"
                         "  - {mesh: sqdem_test_table.stl, point: [0, 0, 0], angular_velocity: [0, 0, "
                      << Omega
                      << "], material: grain}\n"
                         "particles:\n"
                         "  - {shape: ball, material: grain, centre: ["
                      << start.x() << ", " << start.y() << ", " << start.z()
                      << "], allow_overlap: true}\n"
                         "stages:\n"
                         "  - {name: turn, duration: 0.02}\n";
  World world = buildWorld(loadScene(path.string()));
  ASSERT_EQ(world.walls()[0].angularVelocity, Vec3(0.0, 0.0, Omega));
  world.enableEnergyLedger();
  const auto onlyContact = [&] {
    std::optional<ContactView> found;
    for (const ContactView c : world.contacts()) {
      if (c.onWall() && c.overlap() > 0.0) {
        EXPECT_FALSE(found) << "one feature answers";
        found = c;
      }
    }
    EXPECT_TRUE(found);
    return *found;
  };
  const ParticleStore& p = world.particles();
  const int steps = static_cast<int>(0.02 / world.timeStep());
  double worstSlip = 0.0, worstResidual = 0.0;
  Vec3 halfwayVelocity = Vec3::Zero();
  for (int step = 1; step <= steps; ++step) {
    world.step();
    const ContactView c = onlyContact();
    const Wall& table = world.walls()[0];
    const Vec3 surface = Vec3(0.0, 0.0, Omega).cross(c.point());  // the table's velocity at the contact
    const Vec3 onSphere = -c.force();  // ContactView's force acts on B, the table
    const Vec3 tangential = onSphere - onSphere.dot(c.normal()) * c.normal();
    const Vec3 slip = p.velocity[0] + p.angularVelocity[0].cross(c.point() - p.position[0]) - surface;
    if (step == 10) {
      // Sliding: friction on the sphere along the table's motion relative to it, the sphere's
      // reaction braking the table.
      EXPECT_GT(tangential.normalized().dot(-slip.normalized()), 0.999) << "dragged along the table's motion";
      EXPECT_LT(table.torque.z() * Omega, 0.0) << "the sphere brakes the table";
    }
    if (step > steps / 2) worstSlip = std::max(worstSlip, slip.norm());
    if (step == steps / 2) halfwayVelocity = p.velocity[0];
    const EnergyLedger& ledger = *world.energyLedger();
    worstResidual = std::max(worstResidual, std::abs(ledger.residual(world.kineticEnergy())));
  }
  const EnergyLedger& ledger = *world.energyLedger();
  const double t = steps * world.timeStep();
  const Quat turned(Eigen::AngleAxisd(Omega * t, Vec3::UnitZ()));
  std::cout << "turntable: after " << t << " s the table turned " << Omega * t << " rad; the sphere's slip "
            << worstSlip << " m/s (surface speed " << Omega * start.head<2>().norm() << " m/s); table work "
            << ledger.bodies << " J, friction " << ledger.tangential << " J, worst residual " << worstResidual << " J\n";
  EXPECT_LT(std::abs(world.walls()[0].get<MeshWall>().orientation.angularDistance(turned)), 1e-12);
  EXPECT_LT(worstSlip, 1e-3 * Omega * start.head<2>().norm()) << "rolls without slipping in the second half";
  const Vec3 v0 = halfwayVelocity, v1 = p.velocity[0];
  const double turn = std::atan2(v0.cross(v1).z(), v0.dot(v1)), rolling = 2.0 / 7.0 * Omega * (steps - steps / 2) * world.timeStep();
  std::cout << "rolling: the velocity turned " << turn << " rad in the second half, 2 Omega / 7 t = " << rolling << " rad\n";
  EXPECT_NEAR(turn / rolling, 1.0, 1e-3);
  EXPECT_GT(ledger.bodies, 0.0);
  EXPECT_GT(ledger.tangential, 0.0);
  EXPECT_LT(worstResidual, 1e-3 * ledger.bodies);
  EXPECT_EQ(world.statistics().detectorFailures, 0);
}

}  // namespace
}  // namespace sqdem
