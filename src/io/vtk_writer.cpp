#include "sqdem/io/vtk_writer.hpp"

#include <cstdio>
#include <sstream>
#include <utility>

#include "sqdem/geometry/superquadric_tessellation.hpp"
#include "sqdem/archive/atomic_file.hpp"
#include "sqdem/io/paraview_script.hpp"
#include "sqdem/io/poly_data.hpp"
#include "sqdem/io/vtk_xml.hpp"
#include "sqdem/io/wall_surfaces.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem {
namespace {

DataArray float64(const char* name, int components) { return {name, components, std::vector<double>{}}; }
DataArray float32(const char* name, int components) { return {name, components, std::vector<float>{}}; }
DataArray int64(const char* name) { return {name, 1, std::vector<std::int64_t>{}}; }
DataArray int32(const char* name) { return {name, 1, std::vector<std::int32_t>{}}; }

/// Moves the filled arrays into a frame's point or cell data (a frame of 10^5 surfaces holds
/// arrays of 10^7 values: not to be copied).
template <typename... Arrays>
void keep(std::vector<DataArray>& data, Arrays&&... arrays) {
  (data.push_back(std::move(arrays)), ...);
}

/// The particles' state, one vertex each.
PolyData particleFrame(const World& world, const std::vector<int>& coordination) {
  const ParticleStore& p = world.particles();
  const auto& shapes = world.shapes();
  PolyData d;
  d.cells = PolyData::Cells::Vertices;
  DataArray id = int64("id"), velocity = float64("velocity", 3), spin = float64("angular_velocity", 3),
            force = float64("force", 3), torque = float64("torque", 3), quaternion = float64("quaternion", 4),
            semiAxes = float64("semi_axes", 3), exponents = float64("exponents", 2), radius = float64("volume_radius", 1),
            z = int32("coordination"), tensor = float64("shape_tensor", 9);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Superquadric& s = shapes[p.shape[i]];
    const Quat& q = p.orientation[i];
    d.points.push(p.position[i]);
    d.connectivity.push_back(static_cast<std::int64_t>(i));
    d.endCell();
    id.push(static_cast<double>(p.id[i]));
    velocity.push(p.velocity[i]);
    spin.push(p.angularVelocity[i]);
    force.push(p.force[i]);
    torque.push(p.torque[i]);
    for (const double c : {q.w(), q.x(), q.y(), q.z()}) quaternion.push(c);
    semiAxes.push(s.halfExtents());
    exponents.push(s.n1());
    exponents.push(s.n2());
    radius.push(s.volumeEquivalentRadius());
    z.push(coordination[i]);
    const Mat3 R = q.toRotationMatrix();
    const Mat3 T = R * (2.0 * s.halfExtents()).asDiagonal() * R.transpose();
    for (int k = 0; k < 9; ++k) tensor.push(T(k / 3, k % 3));
  }
  keep(d.pointData, id, velocity, spin, force, torque, quaternion, semiAxes, exponents, radius, z, tensor);
  d.pointScalars = "volume_radius";
  return d;
}

/// Every particle's surface in its pose, its values copied to its vertices. A shape's vertices are
/// drawn once for a run of particles of equal shapes (a fixed family: once for all of them).
PolyData surfaceFrame(const World& world, const std::vector<int>& coordination, int resolution) {
  const ParticleStore& p = world.particles();
  const SurfaceGrid grid = surfaceGrid(resolution);
  PolyData d;
  d.cells = PolyData::Cells::Polygons;
  d.points = float32("Points", 3);
  DataArray id = int64("id"), velocity = float32("velocity", 3), spin = float32("angular_velocity", 3),
            force = float32("force", 3), z = int32("coordination"), radius = float32("volume_radius", 1);
  const std::size_t vertices = p.size() * grid.angles.size(), quads = p.size() * grid.quads.size();
  for (DataArray* array : {&d.points, &id, &velocity, &spin, &force, &z, &radius}) array->reserve(vertices);
  d.connectivity.reserve(4 * quads);
  d.offsets.reserve(quads);
  auto& points = std::get<std::vector<float>>(d.points.values);  // 10^7 of them: no visit per vertex
  std::vector<Vec3> body;  // the vertices of `drawn` in its body frame
  const Superquadric* drawn = nullptr;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Superquadric& shape = world.shapes()[p.shape[i]];
    if (drawn == nullptr || shape.halfExtents() != drawn->halfExtents() || shape.n1() != drawn->n1() || shape.n2() != drawn->n2()) {
      body.clear();
      for (const auto& [eta, omega] : grid.angles) body.push_back(shape.surfacePoint(eta, omega));
      drawn = &shape;
    }
    const auto first = static_cast<std::int64_t>(d.pointCount());
    const Pose pose{p.position[i], p.orientation[i]};
    for (const Vec3& x : body) {
      const Vec3 y = pose.toWorld(x);
      points.insert(points.end(), {static_cast<float>(y.x()), static_cast<float>(y.y()), static_cast<float>(y.z())});
    }
    id.push(static_cast<double>(p.id[i]), body.size());
    velocity.push(p.velocity[i], body.size());
    spin.push(p.angularVelocity[i], body.size());
    force.push(p.force[i], body.size());
    z.push(coordination[i], body.size());
    radius.push(shape.volumeEquivalentRadius(), body.size());
    for (const auto& quad : grid.quads) {
      for (const std::uint32_t v : quad) d.connectivity.push_back(first + v);
      d.endCell();
    }
  }
  keep(d.pointData, id, velocity, spin, force, z, radius);
  d.pointScalars = "volume_radius";
  return d;
}

/// One line per contact: between the centres, or from the centre to the point on a wall.
PolyData contactFrame(const World& world) {
  const ParticleStore& p = world.particles();
  PolyData d;
  d.cells = PolyData::Cells::Lines;
  DataArray idA = int64("id_a"), idB = int64("id_b"), wall = int32("wall"), point = float64("point", 3),
            normal = float64("normal", 3), normalForce = float64("normal_force", 1), normalVector = float64("normal_force_vector", 3), tangential = float64("tangential_force", 3),
            overlap = float64("overlap", 1), area = float64("area", 1);
  for (const ContactView c : world.contacts()) {
    d.points.push(p.position[c.a()]);
    d.points.push(c.onWall() ? c.point() : p.position[c.b()]);
    const auto n = static_cast<std::int64_t>(d.pointCount());
    d.connectivity.insert(d.connectivity.end(), {n - 2, n - 1});
    d.endCell();
    idA.push(static_cast<double>(p.id[c.a()]));
    idB.push(c.onWall() ? -1.0 : static_cast<double>(p.id[c.b()]));
    wall.push(c.onWall() ? static_cast<double>(c.wall()) : -1.0);
    point.push(c.point());
    normal.push(c.normal());
    normalForce.push(c.normalLoad().force);
    const Vec3 along = c.force().dot(c.normal()) * c.normal();
    normalVector.push(along);
    tangential.push(c.force() - along);
    overlap.push(c.overlap());
    area.push(c.normalLoad().area);
  }
  keep(d.cellData, idA, idB, wall, point, normal, normalForce, normalVector, tangential, overlap, area);
  d.cellScalars = "normal_force";
  return d;
}

/// One line per intact bond (docs/bonds.md): between the centres, or from the centre to the
/// bond's centre on a wall; broken bonds are gone.
PolyData bondFrame(const World& world) {
  const ParticleStore& p = world.particles();
  const ContactStore& s = world.interactions().store();
  PolyData d;
  d.cells = PolyData::Cells::Lines;
  DataArray idA = int64("id_a"), idB = int64("id_b"), wall = int32("wall"), centre = float64("centre", 3),
            normalForce = float64("normal_force", 1), shearForce = float64("shear_force", 3), moment = float64("moment", 3),
            tensile = float64("tensile_stress", 1), shear = float64("shear_stress", 1), utilisation = float64("utilisation", 1);
  for (const BondReport& r : world.bonds()) {
    const ContactView c(s, r.contact);
    d.points.push(p.position[c.a()]);
    d.points.push(c.onWall() ? r.centre : p.position[c.b()]);
    const auto n = static_cast<std::int64_t>(d.pointCount());
    d.connectivity.insert(d.connectivity.end(), {n - 2, n - 1});
    d.endCell();
    idA.push(static_cast<double>(p.id[c.a()]));
    idB.push(c.onWall() ? -1.0 : static_cast<double>(p.id[c.b()]));
    wall.push(c.onWall() ? static_cast<double>(c.wall()) : -1.0);
    centre.push(r.centre);
    normalForce.push(r.loads.normalForce);
    shearForce.push(r.loads.shearForce);
    moment.push(r.loads.moment);
    tensile.push(r.loads.tensileStress);
    shear.push(r.loads.shearStress);
    utilisation.push(r.utilisation);
  }
  keep(d.cellData, idA, idB, wall, centre, normalForce, shearForce, moment, tensile, shear, utilisation);
  d.cellScalars = "utilisation";
  return d;
}

/// The walls' surfaces within the box.
PolyData wallFrame(const World& world) {
  const WallSurfaces s = wallSurfaces(world.walls(), world.meshes(), world.domain());
  PolyData d;
  d.cells = PolyData::Cells::Polygons;
  for (const Vec3& x : s.points) d.points.push(x);
  DataArray wall = int32("wall"), force = float64("force", 3), torque = float64("torque", 3), velocity = float64("velocity", 3);
  for (std::size_t k = 0; k < s.polygons.size(); ++k) {
    for (const std::uint32_t v : s.polygons[k]) d.connectivity.push_back(v);
    d.endCell();
    const Wall& w = world.walls()[s.wall[k]];
    wall.push(s.wall[k]);
    force.push(w.force);
    torque.push(w.torque);
    velocity.push(w.velocity);
  }
  keep(d.cellData, wall, force, torque, velocity);
  d.cellScalars = "wall";
  return d;
}

}  // namespace

VtkSeries::VtkSeries(std::filesystem::path directory, std::string name, VtkOutputOptions options)
    : directory_(std::move(directory)), name_(std::move(name)), options_(options) {}

void VtkSeries::writeFrame(const World& world) {
  const std::vector<int> z = coordinationNumbers(world);
  const double t = world.time();
  const Communicator& ranks = world.communicator();
  const bool bonded = world.interactions().store().withBonds;
  if (particles_.frames.empty() && ranks.rank() == 0) {
    writeParaViewScript(directory_, name_, {options_.surfaceResolution > 0, options_.contacts, !world.walls().empty(), bonded});
  }
  write(particles_, t, particleFrame(world, z), ranks);
  if (options_.surfaceResolution > 0) write(surfaces_, t, surfaceFrame(world, z, options_.surfaceResolution), ranks);
  if (options_.contacts) write(contacts_, t, contactFrame(world), ranks);
  if (bonded) write(bonds_, t, bondFrame(world), ranks);
  if (!world.walls().empty() && ranks.rank() == 0) write(walls_, t, wallFrame(world), SerialCommunicator());  // global bodies
}

void VtkSeries::write(Series& series, double time, const PolyData& frame, const Communicator& ranks) const {
  char number[32];
  std::snprintf(number, sizeof number, "_%05zu", series.frames.size());
  const std::string stem = name_ + "_" + series.kind + number;
  const std::string file = stem + (ranks.size() > 1 ? ".pvtp" : ".vtp");
  series.frames.emplace_back(time, file);
  if (ranks.size() > 1) {
    writeVtkPiece(frame, directory_ / file, ranks.rank(), ranks.size(), options_.compression);
  } else if (ranks.rank() == 0) {
    writeVtp(frame, directory_ / file, options_.compression);
  }
  if (ranks.rank() != 0) return;
  // The collection, by hand: VTK has no .pvd writer outside ParaView.
  std::ostringstream out;
  out.precision(12);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [at, name] : series.frames) out << "    <DataSet timestep=\"" << at << "\" part=\"0\" file=\"" << name << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
  writeFileAtomically(directory_ / (name_ + "_" + series.kind + ".pvd"), out.str());
}

}  // namespace sqdem
