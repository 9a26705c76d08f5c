#include "sqdem/world/world.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sqdem/dynamics/integrator.hpp"
#include "sqdem/mechanics/damping.hpp"
#include "sqdem/mechanics/nan_adhesive.hpp"

namespace sqdem {

World::World(std::vector<Superquadric> shapes, std::vector<Material> materials, const Domain& domain, double skin)
    : shapes_(std::move(shapes)),
      materials_(std::move(materials)),
      models_(materials_.size() * materials_.size()),
      modelSet_(models_.size(), false),
      domain_(domain),
      cellList_(domain, skin) {}

ContactModel World::defaultContactModel(std::uint32_t ma, std::uint32_t mb) const {
  const Material &A = materials_.at(ma), &B = materials_.at(mb);
  ContactModel m;
  m.effectiveModulus = effectiveModulus(A.youngsModulus, A.poissonRatio, B.youngsModulus, B.poissonRatio);
  const double GA = A.youngsModulus / (2.0 * (1.0 + A.poissonRatio));
  const double GB = B.youngsModulus / (2.0 * (1.0 + B.poissonRatio));
  m.effectiveShear = 1.0 / ((2.0 - A.poissonRatio) / GA + (2.0 - B.poissonRatio) / GB);
  m.friction = std::min(A.friction, B.friction);
  const double e = std::min(A.restitution, B.restitution);
  m.dampingRatio = e >= 1.0 ? 0.0 : restitutionDampingRatio(e);
  return m;
}

void World::setContactModel(std::uint32_t ma, std::uint32_t mb, const ContactModel& model) {
  const std::size_t n = materials_.size();
  models_.at(ma * n + mb) = models_.at(mb * n + ma) = model;
  modelSet_[ma * n + mb] = modelSet_[mb * n + ma] = true;
}

std::size_t World::addParticle(std::uint32_t shape, std::uint32_t material, const Vec3& centre, const Quat& q) {
  const Superquadric& s = shapes_.at(shape);
  const double density = materials_.at(material).density;
  boundingRadius_.push_back(s.boundingRadius());
  forcesCurrent_ = false;
  return particles_.add(shape, material, centre, q, s.mass(density), s.principalMomentsOfInertia(density));
}

void World::solveContact(Contact& c) const {
  const ParticleStore& p = particles_;
  const Superquadric& A = shapes_[p.shape[c.a]];
  const Pose poseA{p.position[c.a], p.orientation[c.a]};
  const bool warm = c.geometry.converged();
  ContactKinematics motion;
  motion.volumeRadiusA = A.volumeEquivalentRadius();
  const ContactModel* law;
  Vec3 velocityB = Vec3::Zero(), omegaB = Vec3::Zero(), centreB;
  if (c.onWall()) {
    const Wall& wall = walls_[c.b & ~wallFlag];
    c.geometry = detectContact(A, poseA, wall.plane);
    velocityB = wall.velocity;
    centreB = c.geometry.pointB;
    motion.effectiveMass = p.mass[c.a];
    law = &model(p.material[c.a], wall.material);
  } else {
    const Superquadric& B = shapes_[p.shape[c.b]];
    const Pose poseB{p.position[c.b] + c.shift, p.orientation[c.b]};
    c.geometry = warm ? detectContact(A, poseA, B, poseB, {}, c.geometry) : detectContact(A, poseA, B, poseB);
    velocityB = p.velocity[c.b];
    omegaB = p.angularVelocity[c.b];
    centreB = poseB.position;
    motion.volumeRadiusB = B.volumeEquivalentRadius();
    motion.effectiveMass = p.mass[c.a] * p.mass[c.b] / (p.mass[c.a] + p.mass[c.b]);
    law = &model(p.material[c.a], p.material[c.b]);
  }
  if (!c.geometry.touching()) {
    c.force = {};
    return;
  }
  const Vec3 point = 0.5 * (c.geometry.pointA + c.geometry.pointB);
  motion.relativeVelocity = velocityB + omegaB.cross(point - centreB) -
                            (p.velocity[c.a] + p.angularVelocity[c.a].cross(point - poseA.position));
  c.force = contactForce(*law, c.geometry, motion, c.spring, dt_);
}

void World::computeForces() {
  for (std::size_t k = 0; k < models_.size(); ++k) {
    if (!modelSet_[k]) throw std::logic_error("World: a material pair has no contact model");
  }
  ParticleStore& p = particles_;
  if (cellList_.needsRebuild(p)) cellList_.rebuild(p, boundingRadius_);

  // Candidates in key order: particle pairs from the cell list, walls within reach.
  std::vector<Contact> next;
  next.reserve(cellList_.pairs().size() + contacts_.size());
  const double skin = cellList_.skin();
  for (const CandidatePair& pair : cellList_.pairs()) {
    Contact c;
    c.a = pair.a;
    c.b = pair.b;
    c.shift = pair.shift;
    next.push_back(c);
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      const Plane& plane = walls_[w].plane;
      if ((p.position[i] - plane.point).dot(plane.normal) < boundingRadius_[i] + skin) {
        Contact c;
        c.a = static_cast<std::uint32_t>(i);
        c.b = wallFlag | static_cast<std::uint32_t>(w);
        next.push_back(c);
      }
    }
  }
  std::sort(next.begin(), next.end(), [](const Contact& x, const Contact& y) { return x.key() < y.key(); });

  // Carry the history of contacts that persist (both lists are sorted by key).
  auto previous = contacts_.begin();
  for (Contact& c : next) {
    while (previous != contacts_.end() && previous->key() < c.key()) ++previous;
    if (previous != contacts_.end() && previous->key() == c.key()) {
      c.geometry = previous->geometry;
      c.spring = previous->spring;
    }
  }

#pragma omp parallel for schedule(dynamic, 64)
  for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(next.size()); ++k) solveContact(next[k]);

  // Serial reduction in key order: independent of the thread count.
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.force[i] = p.mass[i] * (gravity_ - viscousDamping_ * p.velocity[i]);
    p.torque[i].setZero();
  }
  for (Wall& w : walls_) w.force.setZero();
  contacts_.clear();
  for (Contact& c : next) {
    const ContactGeometry& g = c.geometry;
    if (!c.onWall()) {
      ++statistics_.detectorCalls;
      statistics_.detectorIterations += g.iterations;
    }
    if (g.status != ContactStatus::Converged && g.status != ContactStatus::Separated) ++statistics_.detectorFailures;
    if (!g.touching()) continue;
    if (g.overlap > 0.5 * shapes_[p.shape[c.a]].volumeEquivalentRadius()) ++statistics_.deepOverlaps;
    const Vec3 point = 0.5 * (g.pointA + g.pointB);
    const Vec3& F = c.force.onB;
    p.force[c.a] -= F;
    p.torque[c.a] -= (point - p.position[c.a]).cross(F);
    if (c.onWall()) {
      walls_[c.b & ~wallFlag].force += F;
    } else {
      p.force[c.b] += F;
      p.torque[c.b] += (point - (p.position[c.b] + c.shift)).cross(F);
    }
    contacts_.push_back(std::move(c));
  }
  forcesCurrent_ = true;
}

void World::step() {
  if (!(dt_ > 0.0)) throw std::logic_error("World: time step not set");
  if (!forcesCurrent_) computeForces();
  const double h = dt_;
  ParticleStore& p = particles_;
  for (std::size_t i = 0; i < p.size(); ++i) {
    kick(p, i, 0.5 * h);
    drift(p, i, h);
  }
  for (Wall& w : walls_) w.plane.point += h * w.velocity;
  time_ += h;
  computeForces();
  for (std::size_t i = 0; i < p.size(); ++i) kick(p, i, 0.5 * h);
}

double World::kineticEnergy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    e += particles_.translationalEnergy(i) + particles_.rotationalEnergy(i);
  }
  return e;
}

double World::rayleighTimeStep() const {
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const Material& m = materials_[particles_.material[i]];
    const double G = m.youngsModulus / (2.0 * (1.0 + m.poissonRatio));
    const Vec3 h = shapes_[particles_.shape[i]].halfExtents();
    dt = std::min(dt, sqdem::rayleighTimeStep(h.minCoeff(), m.density, G, m.poissonRatio));
  }
  return dt;
}

}  // namespace sqdem
