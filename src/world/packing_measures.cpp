#include "sqdem/world/packing_measures.hpp"

#include <algorithm>
#include <cmath>

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
  std::vector<int> z(world.particles().size(), 0);
  for (const ContactView c : world.contacts()) {
    if (c.onWall()) continue;
    ++z[c.a()];
    ++z[c.b()];
  }
  return z;
}

const Wall* floorWall(const World& world) {
  for (const Wall& w : world.walls()) {
    if (w.shape == WallShape::Plane && w.plane.normal.z() > 0.999) return &w;
  }
  return nullptr;
}

double solidVolume(const World& world) {
  double v = 0.0;
  for (const std::uint32_t s : world.particles().shape) v += world.shapes()[s].volume();
  return v;
}

PlateMeasures measurePlate(const World& world, std::size_t plate) {
  const Wall* floor = floorWall(world);
  PlateMeasures m;
  m.gap = world.walls().at(plate).plane.point.z() - (floor ? floor->plane.point.z() : world.domain().lo.z());
  m.pressure = world.wallPressure(plate);
  m.porosity = 1.0 - solidVolume(world) / (world.wallArea(plate) * m.gap);
  return m;
}

PackingMeasures measurePacking(const World& world) {
  const ParticleStore& p = world.particles();
  PackingMeasures m;
  if (p.size() == 0) return m;
  const Domain& d = world.domain();
  const double bottom = d.lo.z();
  double top = bottom, meanRadius = 0.0, volumeTotal = 0.0, volumeHeight = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Superquadric& s = world.shapes()[p.shape[i]];
    top = std::max(top, p.position[i].z() + s.boundingRadius());
    meanRadius += s.volumeEquivalentRadius() / static_cast<double>(p.size());
    volumeTotal += s.volume();
    volumeHeight += s.volume() * (p.position[i].z() - bottom);
  }
  m.bedHeight = top - bottom;
  // A uniform bed of height H has its volume centroid at H/2.
  const double equivalentHeight = 2.0 * volumeHeight / volumeTotal;
  double lo = bottom + 2.0 * meanRadius, hi = bottom + equivalentHeight - 2.0 * meanRadius;
  if (hi - lo < 2.0 * meanRadius) lo = bottom, hi = top;
  double volume = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    volume += volumeInSlab(world.shapes()[p.shape[i]], Pose{p.position[i], p.orientation[i]}, lo, hi);
  }
  m.slabHeight = hi - lo;
  m.solidFraction = volume / (d.length().x() * d.length().y() * m.slabHeight);

  const Wall* floor = nullptr;
  const Wall* ceiling = nullptr;
  for (const Wall& w : world.walls()) {
    if (w.shape != WallShape::Plane) continue;
    if (w.plane.normal.z() > 0.999) floor = &w;
    if (w.plane.normal.z() < -0.999) ceiling = &w;
  }
  const double base = d.length().x() * d.length().y();
  m.stressVolume = base * equivalentHeight;
  if (floor && ceiling) {
    m.stressVolume = base * (ceiling->plane.point.z() - floor->plane.point.z());
    m.betweenWallsFraction = volumeTotal / m.stressVolume;
  }
  const auto radius = [&](std::uint32_t i) { return world.shapes()[p.shape[i]].volumeEquivalentRadius(); };
  std::size_t yielded = 0;
  for (const ContactView c : world.contacts()) {
    const Vec3 branch = c.onWall() ? Vec3(c.point() - p.position[c.a()]) : Vec3(p.position[c.b()] + c.shift() - p.position[c.a()]);
    m.stress += branch * c.force().transpose();
    yielded += c.normalLoad().yielded;
    const double smaller = c.onWall() ? radius(c.a()) : std::min(radius(c.a()), radius(c.b()));
    m.largestOverlapRatio = std::max(m.largestOverlapRatio, c.overlap() / smaller);
  }
  const auto acting = static_cast<double>(world.contacts().size());
  m.yieldedFraction = acting > 0.0 ? static_cast<double>(yielded) / acting : 0.0;
  // Symmetrised from a copy: assigning m.stress from an expression that reads its transpose
  // aliases in Eigen (each off-diagonal would read its already-overwritten twin).
  const Mat3 sum = m.stress;
  m.stress = 0.5 * (sum + sum.transpose()) / m.stressVolume;

  const std::vector<int> z = coordinationNumbers(world);
  long total = 0, nonRattlerTotal = 0, nonRattlers = 0;
  for (const int zi : z) {
    total += zi;
    if (zi >= 2) {
      nonRattlerTotal += zi;
      ++nonRattlers;
    }
  }
  m.meanCoordination = static_cast<double>(total) / static_cast<double>(z.size());
  m.meanCoordinationNonRattlers = nonRattlers ? static_cast<double>(nonRattlerTotal) / nonRattlers : 0.0;
  return m;
}

}  // namespace sqdem
