#include "sqdem/world/packing_measures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sqdem {

double volumeInSlab(const Superquadric& s, const Pose& pose, double lo, double hi) {
  const double zc = pose.position.z();
  if (!s.isEllipsoid()) return zc >= lo && zc < hi ? s.volume() : 0.0;
  const Vec3 axisZ = pose.orientation.conjugate() * Vec3::UnitZ();
  const double h = std::sqrt(axisZ.cwiseProduct(s.halfExtents()).squaredNorm());
  const auto primitive = [&](double t) {
    t = std::clamp(t, -h, h);
    return t - t * t * t / (3.0 * h * h);
  };
  return 3.0 * s.volume() / (4.0 * h) * (primitive(hi - zc) - primitive(lo - zc));
}

std::vector<int> coordinationNumbers(const World& world) {
  std::vector<int> z(world.particles().slots(), 0);  // a ghost's count goes to its owner
  for (const ContactView c : world.contacts()) {
    if (c.onWall()) continue;
    ++z[c.a()];
    ++z[c.b()];
  }
  world.ghosts().fold(world.particles(), z);
  // The contacts other ranks computed whose B is owned here, acting as their loads said.
  const std::vector<RemoteContact>& remote = world.interactions().remoteContacts();
  for (std::size_t m = 0; m < world.remoteLoads().size(); ++m) z[remote[m].slot] += world.remoteLoads()[m].acting;
  return z;
}

const PlaneWall* floorWall(const World& world) {
  for (const Wall& w : world.walls()) {
    if (const PlaneWall* plane = w.as<PlaneWall>(); plane != nullptr && plane->facesUp()) return plane;
  }
  return nullptr;
}

double solidVolume(const World& world) {
  ExactSum v;
  const ParticleStore& p = world.particles();
  for (std::size_t i = 0; i < p.size(); ++i) v.add(world.shapes()[p.shape[i]].volume());
  return world.communicator().sum(v);
}

PlateMeasures measurePlate(const World& world, std::size_t plate) {
  const PlaneWall* floor = floorWall(world);
  const PlaneWall* top = plate < world.walls().size() ? world.walls()[plate].as<PlaneWall>() : nullptr;
  if (top == nullptr || !top->facesDown() || floor == nullptr) {
    throw std::invalid_argument("walls[" + std::to_string(plate) + "] is not a plate: a plate is a plane wall facing -z "
                                "(normal [0, 0, -1]) in a scene with a floor, a plane wall facing +z");
  }
  PlateMeasures m;
  m.gap = top->plane.point.z() - floor->plane.point.z();
  m.pressure = world.wallPressure(plate);
  m.porosity = 1.0 - solidVolume(world) / (world.wallArea(plate) * m.gap);
  return m;
}

namespace {

/// The particles' volume (m^3) and equivalentBedHeight, from one pass of exact sums reduced
/// over the ranks.
struct BedVolume {
  double volume = 0.0, equivalentHeight = 0.0;
};

BedVolume bedVolume(const World& world, double bottom) {
  // A uniform bed of height H has its volume centroid at H/2.
  const ParticleStore& p = world.particles();
  std::array<ExactSum, 2> sums;  // volumes, volume x height
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double v = world.shapes()[p.shape[i]].volume();
    sums[0].add(v);
    sums[1].add(v * (p.position[i].z() - bottom));
  }
  world.communicator().sum(sums);
  return {sums[0].value(), 2.0 * sums[1].value() / sums[0].value()};
}

}  // namespace

double equivalentBedHeight(const World& world, double bottom) { return bedVolume(world, bottom).equivalentHeight; }

PackingMeasures measurePacking(const World& world) {
  // Every sum exact and reduced over the ranks (communicator.hpp): the same bits at any
  // decomposition.
  const Communicator& ranks = world.communicator();
  const ParticleStore& p = world.particles();
  PackingMeasures m;
  const long long count = ranks.sum(static_cast<long long>(p.size()));
  if (count == 0) return m;
  const Domain& d = world.domain();
  const double bottom = d.lo.z();
  double top = bottom;
  ExactSum radii;  // volume-equivalent
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Superquadric& s = world.shapes()[p.shape[i]];
    top = std::max(top, p.position[i].z() + s.boundingRadius());
    radii.add(s.volumeEquivalentRadius());
  }
  const double meanRadius = ranks.sum(radii) / static_cast<double>(count);
  top = ranks.max(top);
  m.bedHeight = top - bottom;
  const auto [volumeTotal, equivalentHeight] = bedVolume(world, bottom);
  double lo = bottom + 2.0 * meanRadius, hi = bottom + equivalentHeight - 2.0 * meanRadius;
  if (hi - lo < 2.0 * meanRadius) lo = bottom, hi = top;
  ExactSum volume;
  for (std::size_t i = 0; i < p.size(); ++i) {
    volume.add(volumeInSlab(world.shapes()[p.shape[i]], Pose{p.position[i], p.orientation[i]}, lo, hi));
  }
  m.slabHeight = hi - lo;
  m.solidFraction = ranks.sum(volume) / (d.length().x() * d.length().y() * m.slabHeight);

  const PlaneWall* floor = nullptr;
  const PlaneWall* ceiling = nullptr;
  for (const Wall& w : world.walls()) {
    const PlaneWall* plane = w.as<PlaneWall>();
    if (plane != nullptr && plane->facesUp()) floor = plane;
    if (plane != nullptr && plane->facesDown()) ceiling = plane;
  }
  const double base = d.length().x() * d.length().y();
  m.stressVolume = base * equivalentHeight;
  if (floor && ceiling) {
    m.stressVolume = base * (ceiling->plane.point.z() - floor->plane.point.z());
    m.betweenWallsFraction = volumeTotal / m.stressVolume;
  }
  const auto radius = [&](std::uint32_t i) { return world.shapes()[p.shape[i]].volumeEquivalentRadius(); };
  std::array<ExactSum, 9> stress;  // l (x) f, row-major
  std::array<long long, 2> counted{0, 0};  // yielded, acting
  for (const ContactView c : world.contacts()) {
    const Vec3 branch = c.onWall() ? Vec3(c.point() - p.position[c.a()]) : Vec3(p.position[c.b()] - p.position[c.a()]);
    const Mat3 lf = branch * c.force().transpose();
    for (int r = 0; r < 3; ++r) {
      for (int col = 0; col < 3; ++col) stress[3 * r + col].add(lf(r, col));
    }
    counted[0] += c.normalLoad().yielded;
    ++counted[1];
    const double smaller = c.onWall() ? radius(c.a()) : std::min(radius(c.a()), radius(c.b()));
    m.largestOverlapRatio = std::max(m.largestOverlapRatio, c.overlap() / smaller);
  }
  ranks.sum(stress);
  ranks.sum(counted);
  m.largestOverlapRatio = ranks.max(m.largestOverlapRatio);
  m.yieldedFraction = counted[1] > 0 ? static_cast<double>(counted[0]) / static_cast<double>(counted[1]) : 0.0;
  Mat3 sum;
  for (int r = 0; r < 3; ++r) {
    for (int col = 0; col < 3; ++col) sum(r, col) = stress[3 * r + col].value();
  }
  m.stress = 0.5 * (sum + sum.transpose()) / m.stressVolume;

  std::array<long long, 3> z{0, 0, 0};  // contact ends, those of non-rattlers, non-rattlers
  for (const int zi : coordinationNumbers(world)) {
    z[0] += zi;
    if (zi >= 2) {
      z[1] += zi;
      ++z[2];
    }
  }
  ranks.sum(z);
  m.meanCoordination = static_cast<double>(z[0]) / static_cast<double>(count);
  m.meanCoordinationNonRattlers = z[2] ? static_cast<double>(z[1]) / static_cast<double>(z[2]) : 0.0;
  return m;
}

}  // namespace sqdem
