#include "sqdem/scene/particle_file.hpp"

#include "sqdem/distributed/whole_state.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <algorithm>
#include <sstream>

#include "sqdem/archive/atomic_file.hpp"

namespace sqdem {
namespace {

constexpr std::array<const char*, 19> columns{"material", "a",  "b",  "c",  "n1", "n2", "x",  "y",  "z", "qw",
                                              "qx",       "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz"};

std::string header() {
  std::string h;
  for (const char* c : columns) h += std::string(h.empty() ? "" : ",") + c;
  return h;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream s(line);
  for (std::string field; std::getline(s, field, ',');) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

std::vector<ParticleSpec> readParticleFile(const std::filesystem::path& path, const std::vector<NamedMaterial>& materials) {
  std::ifstream file(path);
  if (!file) throw SceneError(path.string() + ": cannot open the particle file");
  std::string line;
  std::size_t lineNumber = 1;
  if (!std::getline(file, line) || line != header()) {
    throw SceneError(path.string() + ":1: the first line must be the header '" + header() + "'");
  }
  std::vector<ParticleSpec> particles;
  while (std::getline(file, line)) {
    ++lineNumber;
    const std::string at = path.string() + ":" + std::to_string(lineNumber);
    if (line.empty()) continue;
    const std::vector<std::string> fields = split(line);
    if (fields.size() != columns.size()) {
      throw SceneError(at + ": " + std::to_string(fields.size()) + " fields, the header has " + std::to_string(columns.size()));
    }
    std::array<double, columns.size()> x{};
    for (std::size_t k = 1; k < columns.size(); ++k) {
      const std::string& f = fields[k];
      const auto [end, error] = std::from_chars(f.data(), f.data() + f.size(), x[k]);
      if (error != std::errc() || end != f.data() + f.size() || !std::isfinite(x[k])) {
        throw SceneError(at + ": '" + columns[k] + "': '" + f + "' is not a finite number");
      }
    }
    ParticleSpec p;
    p.origin = path.filename().string() + ":" + std::to_string(lineNumber);
    const auto material = std::find_if(materials.begin(), materials.end(), [&](const auto& m) { return m.name == fields[0]; });
    if (material == materials.end()) throw SceneError(at + ": 'material': '" + fields[0] + "' is not a material of the scene");
    p.material = static_cast<std::uint32_t>(material - materials.begin());
    p.semiAxes = {x[1], x[2], x[3]};
    p.n1 = x[4];
    p.n2 = x[5];
    if (!(p.semiAxes.minCoeff() > 0.0)) throw SceneError(at + ": 'a', 'b', 'c': semi-axes must be > 0 (m)");
    if (!(p.n1 >= 2.0 && p.n1 <= 50.0 && p.n2 >= 2.0 && p.n2 <= 50.0)) throw SceneError(at + ": 'n1', 'n2': must be in [2, 50]");
    p.centre = {x[6], x[7], x[8]};
    p.orientation = Quat(x[9], x[10], x[11], x[12]);
    if (std::abs(p.orientation.norm() - 1.0) > 1e-6) throw SceneError(at + ": 'qw'..'qz': not a unit quaternion (|q| - 1 > 1e-6)");
    p.orientation.normalize();
    p.velocity = {x[13], x[14], x[15]};
    p.angularVelocity = {x[16], x[17], x[18]};
    particles.push_back(p);
  }
  if (particles.empty()) throw SceneError(path.string() + ": the particle file has no particles");
  return particles;
}

void writeParticleFile(const std::filesystem::path& path, const World& world, const std::vector<NamedMaterial>& materials) {
  const ParticleStore p = gatherWhole(world.particles(), {}, {}, {}, world.communicator()).particles;  // in id order
  if (world.communicator().rank() != 0) return;
  std::string out = header() + "\n";
  char number[32];
  const auto put = [&](double v) {
    std::snprintf(number, sizeof number, ",%.17g", v);
    out += number;
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Superquadric& s = world.shapes()[p.shape[i]];
    const Quat& q = p.orientation[i];
    out += materials[p.material[i]].name;
    for (double v : {s.a(), s.b(), s.c(), s.n1(), s.n2()}) put(v);
    for (int k = 0; k < 3; ++k) put(p.position[i](k));
    for (double v : {q.w(), q.x(), q.y(), q.z()}) put(v);
    for (int k = 0; k < 3; ++k) put(p.velocity[i](k));
    for (int k = 0; k < 3; ++k) put(p.angularVelocity[i](k));
    out += "\n";
  }
  writeFileAtomically(path, out);
}

}  // namespace sqdem
