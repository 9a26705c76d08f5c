// Re-ordering the particle slots along a Hilbert curve (spatial_order.hpp) so that neighbours
// in space are neighbours in memory. Contact records follow their particles: keys are remapped,
// and a pair whose slots change order is rewritten from the other body's point of view.

#include <algorithm>

#include "sqdem/world/spatial_order.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {
namespace {

template <typename T>
void permute(std::vector<T>& values, const std::vector<std::uint32_t>& order) {
  std::vector<T> out;
  out.reserve(values.size());
  for (const std::uint32_t old : order) out.push_back(values[old]);
  values = std::move(out);
}

/// The same contact with A and B exchanged (b's periodic image offset s moves to the new b).
void exchangeBodies(Contact& c) {
  std::swap(c.a, c.b);
  const Vec3 s = c.shift;
  c.shift = -s;
  ContactGeometry& g = c.geometry;
  std::swap(g.pointA, g.pointB);
  g.pointA -= s;
  g.pointB -= s;
  g.normal = -g.normal;
  std::swap(g.curvatureA, g.curvatureB);
  std::swap(g.localPointA, g.localPointB);
  c.history.spring = -c.history.spring;  // the rolling displacement is symmetric in A and B (Eq. 20)
  c.force.onB = -c.force.onB;
  c.force.momentOnB = -c.force.momentOnB;
}

}  // namespace

void World::reorderAlongHilbertCurve() {
  const std::vector<std::uint32_t> order = hilbertOrder(particles_.position);  // new slot k <- old order[k]
  std::vector<std::uint32_t> slotOf(order.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) slotOf[order[k]] = k;

  ParticleStore::forEachArray(particles_, [&](auto& array) { permute(array, order); });
  permute(boundingRadius_, order);

  for (Contact& c : pairs_) {
    c.a = slotOf[c.a];
    if (c.onWall()) continue;
    c.b = slotOf[c.b];
    if (c.a > c.b) exchangeBodies(c);
  }
  std::sort(pairs_.begin(), pairs_.end(), [](const Contact& x, const Contact& y) { return x.key() < y.key(); });
  interacting_.clear();
  for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
    if (interacting(pairs_[k])) interacting_.push_back(k);
  }
  neighbours_.invalidate();
}

}  // namespace sqdem
