#include "sqdem/world/packing_measures.hpp"

#include <algorithm>


namespace sqdem {

std::vector<int> coordinationNumbers(const World& world) {
  std::vector<int> z(world.particles().size(), 0);
  for (const Contact& c : world.contacts()) {
    if (c.onWall()) continue;
    ++z[c.a];
    ++z[c.b];
  }
  return z;
}

PackingMeasures measurePacking(const World& world) {
  const ParticleStore& p = world.particles();
  PackingMeasures m;
  if (p.size() == 0) return m;
  const Domain& d = world.domain();
  const double bottom = d.lo.z();
  double top = bottom, rMax = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = world.shapes()[p.shape[i]].boundingRadius();
    top = std::max(top, p.position[i].z() + r);
    rMax = std::max(rMax, r);
  }
  m.bedHeight = top - bottom;
  double lo = bottom + 2.0 * rMax, hi = top - 2.0 * rMax;
  if (hi - lo < 2.0 * rMax) lo = bottom, hi = top;
  double volume = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.position[i].z() >= lo && p.position[i].z() < hi) volume += world.shapes()[p.shape[i]].volume();
  }
  m.slabHeight = hi - lo;
  m.solidFraction = volume / (d.length().x() * d.length().y() * m.slabHeight);

  const Wall* floor = nullptr;
  const Wall* ceiling = nullptr;
  for (const Wall& w : world.walls()) {
    if (w.plane.normal.z() > 0.999) floor = &w;
    if (w.plane.normal.z() < -0.999) ceiling = &w;
  }
  if (floor && ceiling) {
    double total = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) total += world.shapes()[p.shape[i]].volume();
    m.betweenWallsFraction = total / (d.length().x() * d.length().y() * (ceiling->plane.point.z() - floor->plane.point.z()));
  }

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

double wallPressure(const World& world, std::size_t w) {
  const Wall& wall = world.walls().at(w);
  int axis;
  wall.plane.normal.cwiseAbs().maxCoeff(&axis);
  const Vec3 L = world.domain().length();
  const double area = L.prod() / L(axis);
  return std::abs(wall.force.dot(wall.plane.normal)) / area;
}

}  // namespace sqdem
