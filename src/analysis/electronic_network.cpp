#include "sqdem/analysis/electronic_network.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "sqdem/mechanics/elliptic_integrals.hpp"
#include "sqdem/world/packing_measures.hpp"

namespace sqdem {

double spreadingResistance(double major, double minor, double conductivity) {
  if (std::isinf(conductivity)) return 0.0;
  const double ratio = minor / major;
  const double K = ellipticIntegrals(1.0 - ratio * ratio, ratio * ratio).K;
  return K / (2.0 * std::numbers::pi * conductivity * major);
}

ConductorNetwork electronicNetwork(const World& world, std::span<const ContactEllipse> spots, std::span<const double> conductivity,
                                   double zLow, double zHigh) {
  const ParticleStore& p = world.particles();
  const Domain& domain = world.domain();
  if (world.communicator().size() != 1) throw std::invalid_argument("electronicNetwork: the world must be in one process");
  if (!(zHigh > zLow)) throw std::invalid_argument("electronicNetwork: zHigh must be above zLow");
  if (conductivity.size() != world.materials().size()) throw std::invalid_argument("electronicNetwork: one conductivity per material");
  for (const double s : conductivity) {
    if (!(s > 0.0)) throw std::invalid_argument("electronicNetwork: conductivities must be > 0 (S/m)");
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (std::isinf(conductivity[p.material[i]])) throw std::invalid_argument("electronicNetwork: a particle's material must have a finite conductivity");
  }
  Vec3 lo = domain.lo, hi = domain.hi;
  lo.z() = zLow;
  hi.z() = zHigh;
  ConductorNetwork network;
  network.nodes = p.size();
  network.box = hi - lo;
  network.periodic = {domain.periodic[0], domain.periodic[1], false};

  // Each particle's extent along the axes (centrally symmetric shapes: the support point's
  // projection each way); those whose centre lies outside [zLow, zHigh) are left out.
  std::vector<Vec3> reach(p.size());
  std::vector<std::uint8_t> inside(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Mat3 R = p.orientation[i].toRotationMatrix();
    const Superquadric& shape = world.shapes()[p.shape[i]];
    for (int d = 0; d < 3; ++d) reach[i][d] = R.row(d).dot(shape.supportPoint(R.row(d).transpose()));
    inside[i] = p.position[i].z() >= zLow && p.position[i].z() < zHigh;
  }
  // The floor, when it lies at zLow.
  const PlaneWall* floor = floorWall(world);
  if (floor && std::abs(floor->plane.point.z() - zLow) > 1e-9 * (zHigh - zLow)) floor = nullptr;
  std::uint32_t floorIndex = 0;
  while (floor && world.walls()[floorIndex].as<PlaneWall>() != floor) ++floorIndex;
  // Cut electrodes: the box's faces along axes that are not periodic (z's low face: the floor's
  // contacts when it lies there).
  constexpr double ideal = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    if (!inside[i]) continue;
    for (int d = 0; d < 3; ++d) {
      if (network.periodic[d]) continue;
      const bool low = p.position[i][d] - reach[i][d] < lo[d] && !(d == 2 && floor), high = p.position[i][d] + reach[i][d] > hi[d];
      if (low && high) {
        throw std::invalid_argument("particle " + std::to_string(p.id[i]) + " reaches through the whole box along " + "xyz"[d] +
                                    " and would join both electrodes: the box must be thicker (--region, a stage's analyse.region)");
      }
      if (low) network.low[d].push_back({p.id[i], ideal});
      if (high) network.high[d].push_back({p.id[i], ideal});
    }
  }

  const Vec3 period = domain.length();
  for (const ContactView c : world.contacts()) {
    const std::uint32_t k = c.slot();
    const ContactEllipse& spot = spots[k];
    if (!(spot.minor > 0.0) || !inside[c.a()]) continue;  // a spot the detector no longer finds is zero
    const double resistanceA = spreadingResistance(spot.major, spot.minor, conductivity[p.material[c.a()]]);
    if (c.onWall()) {
      if (floor && c.wall() == floorIndex) {
        const double resistanceWall = spreadingResistance(spot.major, spot.minor, conductivity[world.walls()[floorIndex].material]);
        network.low[2].push_back({p.id[c.a()], 1.0 / (resistanceA + resistanceWall)});
      }
      continue;
    }
    const std::uint32_t b = world.ownedSlot(c.b());
    if (!inside[b]) continue;
    ConductorNetwork::Link link;
    link.a = p.id[c.a()];
    link.b = p.id[b];
    link.conductance = 1.0 / (resistanceA + spreadingResistance(spot.major, spot.minor, conductivity[p.material[b]]));
    link.branch = p.position[c.b()] - p.position[c.a()];
    const Vec3 offset = p.position[c.b()] - p.position[b];
    for (int d = 0; d < 3; ++d) link.shift[d] = static_cast<std::int8_t>(std::lround(offset[d] / period[d]));
    if (link.shift[2] != 0) continue;  // across a periodic z: the electrodes cut the box there
    network.links.push_back(link);
  }
  return network;
}

}  // namespace sqdem
