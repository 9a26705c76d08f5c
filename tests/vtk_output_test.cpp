// The ParaView output (io/vtk_writer.hpp) read back by VTK's own reader (vtkXMLPolyDataReader):
// every array of every file, its size and its values against the World that was written — the
// particles' state (Float64: exact), each particle's drawn surface (every vertex on its
// superquadric in its pose, g = 1 to Float32 precision, carrying its particle's values), the
// contact network (particle pairs and wall contacts: ids, wall, point, normal, forces, overlap,
// area, the line's ends) and the walls (polygons, index, force, torque, velocity). Frame 0 of a
// bed without contacts still carries the contact arrays (empty), for ParaView's colour menu. The
// bonds (docs/bonds.md): one line per intact bond with the loads World::bonds reports, a broken
// bond gone.

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sqdem/io/vtk_writer.hpp"
#include "sqdem/io/wall_surfaces.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem {
namespace {

constexpr int resolution = 5;

struct Frame {
  vtkSmartPointer<vtkPolyData> data;

  explicit Frame(const std::filesystem::path& path) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    EXPECT_EQ(reader->GetErrorCode(), 0) << path;
    data = reader->GetOutput();
  }
  vtkDataArray* point(const char* name) const { return checked(data->GetPointData()->GetArray(name), name); }
  vtkDataArray* cell(const char* name) const { return checked(data->GetCellData()->GetArray(name), name); }
  Vec3 vertex(vtkIdType i) const {
    double x[3];
    data->GetPoint(i, x);
    return {x[0], x[1], x[2]};
  }

 private:
  static vtkDataArray* checked(vtkDataArray* a, const char* name) {
    EXPECT_NE(a, nullptr) << "array " << name;
    return a;
  }
};

Vec3 tuple3(vtkDataArray* a, vtkIdType i) { return {a->GetComponent(i, 0), a->GetComponent(i, 1), a->GetComponent(i, 2)}; }

/// A sphere, an ellipsoid, an n = 6 block and a mixed-exponent particle, pressed into each other
/// and onto a floor, under a roller.
World smallScene() {
  Domain box;
  box.lo = Vec3(-3e-3, -3e-3, 0.0);
  box.hi = Vec3(3e-3, 3e-3, 4e-3);
  const Material m{1e7, 0.3, 2500.0, 0.4, 0.5};
  World world({Superquadric::sphere(0.5e-3), Superquadric::ellipsoid(0.6e-3, 0.4e-3, 0.3e-3),
               Superquadric(0.5e-3, 0.4e-3, 0.45e-3, 6.0, 6.0), Superquadric(0.5e-3, 0.45e-3, 0.4e-3, 2.0, 6.0)},
              {m}, box, 0.1e-3);
  world.setContactModel(0, 0, world.defaultContactModel(0, 0));
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
  Wall roller;
  roller.surface = CylinderWall{Cylinder{Vec3(0.0, 0.0, 2.5e-3), Vec3::UnitY(), 1e-3}};
  roller.angularVelocity = Vec3(0.0, 5.0, 0.0);
  roller.velocity = Vec3(0.01, 0.0, 0.0);
  world.addWall(roller);
  world.addParticle(0, 0, Vec3(-0.9e-3, 0.0, 0.49e-3), Quat::Identity());
  world.addParticle(1, 0, Vec3(0.05e-3, 0.0, 0.29e-3), Quat(Eigen::AngleAxisd(0.3, Vec3(0, 0, 1))));
  world.addParticle(2, 0, Vec3(0.0, 0.0, 1.05e-3), Quat(Eigen::AngleAxisd(0.2, Vec3(1, 1, 0).normalized())));
  world.addParticle(3, 0, Vec3(1.2e-3, 0.3e-3, 0.41e-3), Quat(Eigen::AngleAxisd(1.0, Vec3(0, 1, 1).normalized())));
  for (std::size_t i = 0; i < world.particles().size(); ++i) {
    world.particles().velocity[i] = Vec3(0.01 * i, -0.02, 0.003);
    world.particles().angularVelocity[i] = Vec3(1.0, 2.0 * i, -3.0);
  }
  world.setTimeStep(1e-7);
  world.computeForces();
  return world;
}

/// Every test for each compression (output.vtk_compression).
class VtkOutput : public testing::TestWithParam<VtkCompression> {
 protected:
  void SetUp() override {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    VtkSeries series(dir, "scene", {.contacts = true, .surfaceResolution = resolution, .compression = GetParam()});
    series.writeFrame(world);
  }
  std::filesystem::path file(const char* kind) const { return dir / (std::string("scene_") + kind + "_00000.vtp"); }

  std::filesystem::path dir = std::filesystem::temp_directory_path() / "sqdem_test_vtk_output";
  World world = smallScene();
};

TEST_P(VtkOutput, ParticlesCarryTheirWholeState) {
  const ParticleStore& p = world.particles();
  const Frame f(file("particles"));
  ASSERT_EQ(f.data->GetNumberOfPoints(), static_cast<vtkIdType>(p.size()));
  ASSERT_EQ(f.data->GetNumberOfVerts(), static_cast<vtkIdType>(p.size()));
  const std::vector<int> z = coordinationNumbers(world);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Superquadric& s = world.shapes()[p.shape[i]];
    const Quat& q = p.orientation[i];
    EXPECT_EQ(f.vertex(i), p.position[i]);
    EXPECT_EQ(f.point("id")->GetComponent(i, 0), p.id[i]);
    EXPECT_EQ(tuple3(f.point("velocity"), i), p.velocity[i]);
    EXPECT_EQ(tuple3(f.point("angular_velocity"), i), p.angularVelocity[i]);
    EXPECT_EQ(tuple3(f.point("force"), i), p.force[i]);
    EXPECT_EQ(tuple3(f.point("torque"), i), p.torque[i]);
    const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
    for (int c = 0; c < 4; ++c) EXPECT_EQ(f.point("quaternion")->GetComponent(i, c), wxyz[c]);
    EXPECT_EQ(tuple3(f.point("semi_axes"), i), s.halfExtents());
    EXPECT_EQ(f.point("exponents")->GetComponent(i, 0), s.n1());
    EXPECT_EQ(f.point("exponents")->GetComponent(i, 1), s.n2());
    EXPECT_EQ(f.point("volume_radius")->GetComponent(i, 0), s.volumeEquivalentRadius());
    EXPECT_EQ(f.point("coordination")->GetComponent(i, 0), z[i]);
    // shape_tensor: symmetric, eigenvalues the full axes 2a, 2b, 2c along the body axes.
    vtkDataArray* T = f.point("shape_tensor");
    Mat3 tensor;
    for (int k = 0; k < 9; ++k) tensor(k / 3, k % 3) = T->GetComponent(i, k);
    const Mat3 R = q.toRotationMatrix();
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_LT((tensor * R.col(axis) - 2.0 * s.halfExtents()[axis] * R.col(axis)).norm(), 1e-15);
    }
  }
  EXPECT_GT(*std::max_element(z.begin(), z.end()), 0);
  EXPECT_EQ(std::string(f.data->GetPointData()->GetScalars()->GetName()), "volume_radius");
}

TEST_P(VtkOutput, SurfacesLieOnEachParticleAndCarryItsValues) {
  const ParticleStore& p = world.particles();
  const Frame f(file("surfaces"));
  const vtkIdType perParticle = 6 * resolution * resolution + 2;
  ASSERT_EQ(f.data->GetNumberOfPoints(), static_cast<vtkIdType>(p.size()) * perParticle);
  ASSERT_EQ(f.data->GetNumberOfPolys(), static_cast<vtkIdType>(p.size()) * 6 * resolution * resolution);
  const std::vector<int> z = coordinationNumbers(world);
  for (vtkIdType v = 0; v < f.data->GetNumberOfPoints(); ++v) {
    const std::size_t i = static_cast<std::size_t>(v / perParticle);
    ASSERT_EQ(f.point("id")->GetComponent(v, 0), p.id[i]);
    const Superquadric& s = world.shapes()[p.shape[i]];
    const Vec3 body = Pose{p.position[i], p.orientation[i]}.toBody(f.vertex(v));
    EXPECT_NEAR(s.gauge(body), 1.0, 2e-6) << "vertex " << v;  // Float32 coordinates of a mm-sized body
    EXPECT_LT((tuple3(f.point("velocity"), v) - p.velocity[i]).norm(), 1e-6 * p.velocity[i].norm());
    EXPECT_LT((tuple3(f.point("angular_velocity"), v) - p.angularVelocity[i]).norm(), 1e-6 * p.angularVelocity[i].norm());
    EXPECT_LT((tuple3(f.point("force"), v) - p.force[i]).norm(), 1e-6 * p.force[i].norm());
    EXPECT_EQ(f.point("coordination")->GetComponent(v, 0), z[i]);
    EXPECT_FLOAT_EQ(f.point("volume_radius")->GetComponent(v, 0), s.volumeEquivalentRadius());
  }
  // Each polygon is a quad of one particle's vertices.
  vtkNew<vtkIdList> quad;
  for (vtkIdType c = 0; c < f.data->GetNumberOfCells(); ++c) {
    f.data->GetCellPoints(c, quad);
    ASSERT_EQ(quad->GetNumberOfIds(), 4);
    for (int k = 1; k < 4; ++k) EXPECT_EQ(quad->GetId(k) / perParticle, quad->GetId(0) / perParticle);
  }
}

TEST_P(VtkOutput, ContactNetworkHasPairsAndWallContacts) {
  const ParticleStore& p = world.particles();
  const Frame f(file("contacts"));
  std::vector<ContactView> contacts;
  for (const ContactView c : world.contacts()) contacts.push_back(c);
  ASSERT_EQ(f.data->GetNumberOfLines(), static_cast<vtkIdType>(contacts.size()));
  int onWalls = 0, pairs = 0;
  vtkNew<vtkIdList> line;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ContactView& c = contacts[k];
    f.data->GetCellPoints(static_cast<vtkIdType>(k), line);
    ASSERT_EQ(line->GetNumberOfIds(), 2);
    EXPECT_EQ(f.vertex(line->GetId(0)), p.position[c.a()]);
    EXPECT_EQ(f.cell("id_a")->GetComponent(k, 0), p.id[c.a()]);
    if (c.onWall()) {
      ++onWalls;
      EXPECT_EQ(f.cell("id_b")->GetComponent(k, 0), -1.0);
      EXPECT_EQ(f.cell("wall")->GetComponent(k, 0), c.wall());
      EXPECT_EQ(f.vertex(line->GetId(1)), c.point());
    } else {
      ++pairs;
      EXPECT_EQ(f.cell("id_b")->GetComponent(k, 0), p.id[c.b()]);
      EXPECT_EQ(f.cell("wall")->GetComponent(k, 0), -1.0);
      EXPECT_EQ(f.vertex(line->GetId(1)), p.position[c.b()]);  // B, or its image (a ghost)
    }
    EXPECT_EQ(tuple3(f.cell("point"), k), c.point());
    EXPECT_EQ(tuple3(f.cell("normal"), k), c.normal());
    EXPECT_EQ(f.cell("normal_force")->GetComponent(k, 0), c.normalLoad().force);
    const Vec3 normalPart = tuple3(f.cell("normal_force_vector"), k), tangential = tuple3(f.cell("tangential_force"), k);
    EXPECT_LT((normalPart + tangential - c.force()).norm(), 1e-15 * c.force().norm());
    EXPECT_LT(normalPart.cross(c.normal()).norm(), 1e-12 * normalPart.norm());
    EXPECT_LT(std::abs(tangential.dot(c.normal())), 1e-12 * c.force().norm());
    EXPECT_EQ(f.cell("overlap")->GetComponent(k, 0), c.overlap());
    EXPECT_EQ(f.cell("area")->GetComponent(k, 0), c.normalLoad().area);
  }
  EXPECT_GE(onWalls, 3);  // the floor under three particles, the roller on the block
  EXPECT_GE(pairs, 2);
}

TEST_P(VtkOutput, WallsAsTheirSurfaces) {
  const Frame f(file("walls"));
  const WallSurfaces s = wallSurfaces(world.walls(), world.meshes(), world.domain());
  ASSERT_EQ(f.data->GetNumberOfPolys(), static_cast<vtkIdType>(s.polygons.size()));
  ASSERT_EQ(f.data->GetNumberOfPoints(), static_cast<vtkIdType>(s.points.size()));
  for (std::size_t k = 0; k < s.polygons.size(); ++k) {
    const Wall& w = world.walls()[s.wall[k]];
    EXPECT_EQ(f.cell("wall")->GetComponent(k, 0), s.wall[k]);
    EXPECT_EQ(tuple3(f.cell("force"), k), w.force);
    EXPECT_EQ(tuple3(f.cell("torque"), k), w.torque);
    EXPECT_EQ(tuple3(f.cell("velocity"), k), w.velocity);
  }
  for (std::size_t v = 0; v < s.points.size(); ++v) EXPECT_EQ(f.vertex(v), s.points[v]);
  EXPECT_NE(world.walls()[1].torque.norm(), 0.0);
}

TEST_P(VtkOutput, CollectionsListTheFramesAndAnEmptyNetworkKeepsItsArrays) {
  World apart = smallScene();
  for (std::size_t i = 0; i < apart.particles().size(); ++i) apart.particles().position[i] = Vec3(0.0, -2.4e-3 + 1.6e-3 * i, 0.8e-3);
  apart.computeForces();
  VtkSeries series(dir, "apart", {.contacts = true, .surfaceResolution = 0});
  series.writeFrame(apart);
  series.writeFrame(apart);
  EXPECT_FALSE(std::filesystem::exists(dir / "apart_surfaces_00000.vtp"));  // resolution 0: none
  const Frame f(dir / "apart_contacts_00001.vtp");
  EXPECT_EQ(f.data->GetNumberOfCells(), 0);
  EXPECT_EQ(f.cell("normal_force")->GetNumberOfTuples(), 0);
  std::ifstream pvd(dir / "apart_particles.pvd");
  std::stringstream text;
  text << pvd.rdbuf();
  EXPECT_NE(text.str().find("file=\"apart_particles_00000.vtp\""), std::string::npos);
  EXPECT_NE(text.str().find("file=\"apart_particles_00001.vtp\""), std::string::npos);
}

// Three spheres in a row on a floor, bonded to each other and to the floor, then stretched,
// sheared and turned: the file holds each intact bond's line and loads; after one floor bond is
// pulled past its strength, its line is gone.
TEST(VtkBondOutput, IntactBondsWithTheirLoadsBrokenOnesGone) {
  constexpr double r = 5e-6;
  Domain box;
  box.lo = Vec3::Constant(-1e-4);
  box.hi = Vec3::Constant(1e-4);
  World world({Superquadric::sphere(r)}, {Material{2e11, 0.3, 4700.0, 0.0, 1.0}}, box, 0.2 * r);
  ContactModel model = world.defaultContactModel(0, 0);
  model.bond = ParallelBond{.radiusMultiplier = 0.5, .normalStiffness = 1e17, .shearStiffness = 4e16, .tensileStrength = 50e6,
                            .shearStrength = 80e6};
  world.setContactModel(0, 0, model);
  world.addWall(Wall{.surface = PlaneWall{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
  world.setTimeStep(1e-10);
  for (int i = 0; i < 3; ++i) world.addParticle(0, 0, Vec3(i * (2.0 * r + 1e-9), 0.0, r + 1e-9), Quat::Identity());
  world.computeForces();
  ASSERT_EQ(world.formBonds(0.01), 5u);  // 0-1, 1-2 and each on the floor
  ParticleStore& p = world.particles();
  p.position[0].z() += 1e-10;
  p.position[1] += Vec3(1e-10, 2e-10, 1e-10);
  p.orientation[2] = Quat(Eigen::AngleAxisd(1e-5, Vec3(1.0, 2.0, 3.0).normalized()));
  world.computeForces();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sqdem_test_vtk_bonds";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  VtkSeries series(dir, "bonded", {.contacts = true, .surfaceResolution = 0});
  series.writeFrame(world);
  const std::vector<BondReport> bonds = world.bonds();
  ASSERT_EQ(bonds.size(), 5u);
  const Frame f(dir / "bonded_bonds_00000.vtp");
  ASSERT_EQ(f.data->GetNumberOfLines(), 5);
  vtkNew<vtkIdList> line;
  int onWall = 0;
  for (std::size_t k = 0; k < bonds.size(); ++k) {
    const BondReport& b = bonds[k];
    const ContactView c(world.interactions().store(), b.contact);
    f.data->GetCellPoints(static_cast<vtkIdType>(k), line);
    EXPECT_EQ(f.vertex(line->GetId(0)), p.position[c.a()]);
    EXPECT_EQ(f.vertex(line->GetId(1)), c.onWall() ? b.centre : p.position[c.b()]);
    EXPECT_EQ(f.cell("id_a")->GetComponent(k, 0), p.id[c.a()]);
    EXPECT_EQ(f.cell("id_b")->GetComponent(k, 0), c.onWall() ? -1.0 : p.id[c.b()]);
    EXPECT_EQ(f.cell("wall")->GetComponent(k, 0), c.onWall() ? 0.0 : -1.0);
    onWall += c.onWall() ? 1 : 0;
    EXPECT_EQ(tuple3(f.cell("centre"), k), b.centre);
    EXPECT_EQ(f.cell("normal_force")->GetComponent(k, 0), b.loads.normalForce);
    EXPECT_EQ(tuple3(f.cell("shear_force"), k), b.loads.shearForce);
    EXPECT_EQ(tuple3(f.cell("moment"), k), b.loads.moment);
    EXPECT_EQ(f.cell("tensile_stress")->GetComponent(k, 0), b.loads.tensileStress);
    EXPECT_EQ(f.cell("shear_stress")->GetComponent(k, 0), b.loads.shearStress);
    EXPECT_EQ(f.cell("utilisation")->GetComponent(k, 0), b.utilisation);
    EXPECT_GT(b.utilisation, 0.0);
    EXPECT_LT(b.utilisation, 1.0);
  }
  EXPECT_EQ(onWall, 3);
  // Particle 0 lifted 1e-9 m more: its floor bond (u_c = sigma_c / k_n = 5e-10 m) breaks, its
  // bond to particle 1 holds (sheared by 1e-9 m: tau = k_s u_s = 40 MPa < 80 MPa).
  p.position[0].z() += 1e-9;
  world.computeForces();
  series.writeFrame(world);
  const Frame after(dir / "bonded_bonds_00001.vtp");
  ASSERT_EQ(after.data->GetNumberOfLines(), 4);
  for (vtkIdType k = 0; k < 4; ++k) EXPECT_FALSE(after.cell("id_a")->GetComponent(k, 0) == 0.0 && after.cell("wall")->GetComponent(k, 0) == 0.0) << k;
  EXPECT_EQ(world.totalStatistics().bondsBroken, 1);
}

INSTANTIATE_TEST_SUITE_P(Compressions, VtkOutput, testing::Values(VtkCompression::ZLib, VtkCompression::LZ4, VtkCompression::None),
                         [](const testing::TestParamInfo<VtkCompression>& info) {
                           return info.param == VtkCompression::ZLib ? "zlib" : info.param == VtkCompression::LZ4 ? "lz4" : "none";
                         });

}  // namespace
}  // namespace sqdem
