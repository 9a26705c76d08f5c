#include "sqdem/io/vtk_writer.hpp"

#include <cstdio>
#include <sstream>

#include "sqdem/io/atomic_file.hpp"
#include "sqdem/io/wall_surfaces.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem {
namespace {

template <typename Get>
void dataArray(std::ostringstream& out, const char* type, const char* name, int components, std::size_t n, Get get) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
      << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    out << "         ";
    get(out, i);
    out << "\n";
  }
  out << "        </DataArray>\n";
}

void put(std::ostringstream& out, const Vec3& v) { out << ' ' << v.x() << ' ' << v.y() << ' ' << v.z(); }

std::string frameName(const std::string& name, const char* kind, std::size_t frame, const char* extension) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "_%05zu", frame);
  return name + "_" + kind + buffer + extension;
}

}  // namespace

VtkSeries::VtkSeries(std::filesystem::path directory, std::string name, bool contacts)
    : directory_(std::move(directory)), name_(std::move(name)), contacts_(contacts) {}

void VtkSeries::writeFrame(const World& world) {
  const ParticleStore& p = world.particles();
  const std::size_t n = p.size();
  const std::vector<int> z = coordinationNumbers(world);
  std::ostringstream out;
  out.precision(9);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
      << "      <Points>\n";
  dataArray(out, "Float64", "position", 3, n, [&](auto& o, std::size_t i) { put(o, p.position[i]); });
  out << "      </Points>\n      <Cells>\n";
  dataArray(out, "Int64", "connectivity", 1, n, [](auto& o, std::size_t i) { o << i; });
  dataArray(out, "Int64", "offsets", 1, n, [](auto& o, std::size_t i) { o << i + 1; });
  dataArray(out, "UInt8", "types", 1, n, [](auto& o, std::size_t) { o << 1; });  // VTK_VERTEX
  out << "      </Cells>\n      <PointData Vectors=\"velocity\" Tensors=\"shape_tensor\">\n";
  const auto& shapes = world.shapes();
  dataArray(out, "Int64", "id", 1, n, [&](auto& o, std::size_t i) { o << p.id[i]; });
  dataArray(out, "Float64", "velocity", 3, n, [&](auto& o, std::size_t i) { put(o, p.velocity[i]); });
  dataArray(out, "Float64", "angular_velocity", 3, n, [&](auto& o, std::size_t i) { put(o, p.angularVelocity[i]); });
  dataArray(out, "Float64", "force", 3, n, [&](auto& o, std::size_t i) { put(o, p.force[i]); });
  dataArray(out, "Float64", "torque", 3, n, [&](auto& o, std::size_t i) { put(o, p.torque[i]); });
  dataArray(out, "Float64", "quaternion", 4, n, [&](auto& o, std::size_t i) {
    const Quat& q = p.orientation[i];
    o << ' ' << q.w() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z();
  });
  dataArray(out, "Float64", "semi_axes", 3, n, [&](auto& o, std::size_t i) { put(o, shapes[p.shape[i]].halfExtents()); });
  dataArray(out, "Float64", "exponents", 2, n, [&](auto& o, std::size_t i) {
    o << ' ' << shapes[p.shape[i]].n1() << ' ' << shapes[p.shape[i]].n2();
  });
  dataArray(out, "Float64", "volume_radius", 1, n, [&](auto& o, std::size_t i) { o << shapes[p.shape[i]].volumeEquivalentRadius(); });
  dataArray(out, "Int32", "coordination", 1, n, [&](auto& o, std::size_t i) { o << z[i]; });
  dataArray(out, "Float64", "shape_tensor", 9, n, [&](auto& o, std::size_t i) {
    const Mat3 R = p.orientation[i].toRotationMatrix();
    const Mat3 T = R * (2.0 * shapes[p.shape[i]].halfExtents()).asDiagonal() * R.transpose();
    for (int k = 0; k < 9; ++k) o << ' ' << T(k / 3, k % 3);
  });
  out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  const std::string particleFile = frameName(name_, "particles", particleFrames_.size(), ".vtu");
  writeFileAtomically(directory_ / particleFile, out.str());
  particleFrames_.emplace_back(world.time(), particleFile);
  writeCollection("particles", particleFrames_);
  if (!world.walls().empty()) writeWalls(world);
  if (!contacts_) return;

  std::vector<ContactView> pairs;
  for (const ContactView c : world.contacts()) {
    if (!c.onWall()) pairs.push_back(c);
  }
  const std::size_t m = pairs.size();
  std::ostringstream net;
  net.precision(9);
  net << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n    <Piece NumberOfPoints=\"" << 2 * m << "\" NumberOfLines=\"" << m << "\">\n      <Points>\n";
  dataArray(net, "Float64", "position", 3, 2 * m, [&](auto& o, std::size_t k) {
    const ContactView& c = pairs[k / 2];
    put(o, k % 2 == 0 ? p.position[c.a()] : Vec3(p.position[c.b()] + c.shift()));
  });
  net << "      </Points>\n      <Lines>\n";
  dataArray(net, "Int64", "connectivity", 1, 2 * m, [](auto& o, std::size_t k) { o << k; });
  dataArray(net, "Int64", "offsets", 1, m, [](auto& o, std::size_t k) { o << 2 * (k + 1); });
  net << "      </Lines>\n      <CellData Scalars=\"normal_force\">\n";
  dataArray(net, "Float64", "normal_force", 1, m, [&](auto& o, std::size_t k) { o << pairs[k].normalLoad().force; });
  dataArray(net, "Float64", "overlap", 1, m, [&](auto& o, std::size_t k) { o << pairs[k].overlap(); });
  dataArray(net, "Float64", "area", 1, m, [&](auto& o, std::size_t k) { o << pairs[k].normalLoad().area; });
  net << "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  const std::string contactFile = frameName(name_, "contacts", contactFrames_.size(), ".vtp");
  writeFileAtomically(directory_ / contactFile, net.str());
  contactFrames_.emplace_back(world.time(), contactFile);
  writeCollection("contacts", contactFrames_);
}

void VtkSeries::writeWalls(const World& world) {
  const WallSurfaces s = wallSurfaces(world.walls(), world.meshes(), world.domain());
  const std::size_t n = s.points.size(), m = s.polygons.size();
  std::vector<std::uint32_t> connectivity, offsets;
  for (const auto& polygon : s.polygons) {
    connectivity.insert(connectivity.end(), polygon.begin(), polygon.end());
    offsets.push_back(static_cast<std::uint32_t>(connectivity.size()));
  }
  std::ostringstream out;
  out.precision(9);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n    <Piece NumberOfPoints=\"" << n << "\" NumberOfPolys=\"" << m << "\">\n      <Points>\n";
  dataArray(out, "Float64", "position", 3, n, [&](auto& o, std::size_t k) { put(o, s.points[k]); });
  out << "      </Points>\n      <Polys>\n";
  dataArray(out, "Int64", "connectivity", 1, connectivity.size(), [&](auto& o, std::size_t k) { o << connectivity[k]; });
  dataArray(out, "Int64", "offsets", 1, m, [&](auto& o, std::size_t k) { o << offsets[k]; });
  out << "      </Polys>\n      <CellData Scalars=\"wall\">\n";
  dataArray(out, "Int32", "wall", 1, m, [&](auto& o, std::size_t k) { o << s.wall[k]; });
  dataArray(out, "Float64", "force", 3, m, [&](auto& o, std::size_t k) { put(o, world.walls()[s.wall[k]].force); });
  out << "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  const std::string file = frameName(name_, "walls", wallFrames_.size(), ".vtp");
  writeFileAtomically(directory_ / file, out.str());
  wallFrames_.emplace_back(world.time(), file);
  writeCollection("walls", wallFrames_);
}

void VtkSeries::writeCollection(const std::string& kind, const std::vector<std::pair<double, std::string>>& entries) const {
  std::ostringstream out;
  out.precision(12);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [time, file] : entries) {
    out << "    <DataSet timestep=\"" << time << "\" part=\"0\" file=\"" << file << "\"/>\n";
  }
  out << "  </Collection>\n</VTKFile>\n";
  writeFileAtomically(directory_ / (name_ + "_" + kind + ".pvd"), out.str());
}

}  // namespace sqdem
