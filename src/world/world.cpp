#include "sqdem/world/world.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "sqdem/dynamics/integrator.hpp"
#include "sqdem/dynamics/rayleigh_time.hpp"
#include "sqdem/mechanics/collision_time.hpp"
#include "sqdem/mechanics/damping.hpp"

namespace sqdem {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

/// A fresh candidate (no geometry, no history): b seen at its position + shift from a.
Contact candidate(std::uint32_t a, std::uint32_t b, const Vec3& shift = Vec3::Zero()) {
  Contact c;
  c.a = a;
  c.b = b;
  c.shift = shift;
  return c;
}

}  // namespace

World::World(std::vector<Superquadric> shapes, std::vector<Material> materials, const Domain& domain, double skin,
             BroadPhase search)
    : shapes_(std::move(shapes)),
      materials_(std::move(materials)),
      models_(materials_.size() * materials_.size()),
      modelSet_(models_.size(), false),
      domain_(domain),
      neighbours_(domain, skin, search) {}

ContactModel World::defaultContactModel(std::uint32_t ma, std::uint32_t mb) const {
  const Material &A = materials_.at(ma), &B = materials_.at(mb);
  ContactModel m;
  m.effectiveModulus = effectiveModulus(A.youngsModulus, A.poissonRatio, B.youngsModulus, B.poissonRatio);
  m.tangential.effectiveShear = effectiveShearModulus(A.youngsModulus, A.poissonRatio, B.youngsModulus, B.poissonRatio);
  m.tangential.poissonRatio = 0.5 * (A.poissonRatio + B.poissonRatio);
  m.tangential.friction = std::min(A.friction, B.friction);
  const double e = std::min(A.restitution, B.restitution);
  m.damping.ratio = restitutionDampingRatio(e);  // 0 for e = 1
  return m;
}

void World::setContactModel(std::uint32_t ma, std::uint32_t mb, const ContactModel& model) {
  const std::size_t n = materials_.size();
  double largest = 0.0;
  for (const Superquadric& s : shapes_) largest = std::max(largest, s.volumeEquivalentRadius());
  ContactModel m = model;
  m.reach = normalReach(m.normal, m.effectiveModulus, m.capFactor * largest);
  m.tangential.elliptic = m.tangential.elliptic && m.curvatures;  // the ellipse needs the curvatures
  models_.at(ma * n + mb) = models_.at(mb * n + ma) = m;
  modelSet_[ma * n + mb] = modelSet_[mb * n + ma] = true;
}

std::size_t World::addParticle(std::uint32_t shape, std::uint32_t material, const Vec3& centre, const Quat& q) {
  const Superquadric& s = shapes_.at(shape);
  const double density = materials_.at(material).density;
  boundingRadius_.push_back(s.boundingRadius());
  forcesCurrent_ = false;
  return particles_.add(shape, material, centre, q, s.mass(density), s.principalMomentsOfInertia(density));
}

void World::detect(Contact& c) const {
  const ParticleStore& p = particles_;
  const Superquadric& A = shapes_[p.shape[c.a]];
  const Pose poseA{p.position[c.a], p.orientation[c.a]};
  const bool curvatures = lawOf(c).usesCurvatures();  // a law that does not use them does not pay for them
  if (c.onWall()) {  // gaps within the skin too: rough contacts act across a gap
    c.geometry = detectContact(A, poseA, walls_[c.b & ~wallFlag].plane, {.cutoff = neighbours_.skin(), .curvatures = curvatures});
    return;
  }
  // A pair found separated stays so until the particles could have moved by its gap.
  if (c.separation > 0.0) {
    c.separation -= dt_ * (p.velocity[c.a].norm() + p.velocity[c.b].norm() +
                           p.angularVelocity[c.a].norm() * boundingRadius_[c.a] +
                           p.angularVelocity[c.b].norm() * boundingRadius_[c.b]);
    if (c.separation > lawOf(c).reach) {  // rough and adhesive contacts act across gaps up to reach
      c.geometry = ContactGeometry{};  // status Separated, no iterations
      return;
    }
  }
  const Superquadric& B = shapes_[p.shape[c.b]];
  const Pose poseB{p.position[c.b] + c.shift, p.orientation[c.b]};
  // Gaps within the skin are solved too, so that every candidate is warm-started next step.
  const DetectorSettings settings{.cutoff = neighbours_.skin(), .curvatures = curvatures};
  c.geometry = c.geometry.converged() ? detectContact(A, poseA, B, poseB, settings, c.geometry)
                                      : detectContact(A, poseA, B, poseB, settings);
  c.separation = c.geometry.status == ContactStatus::Separated ? -c.geometry.overlap : 0.0;
}

void World::applyLaw(Contact& c) const {
  const ParticleStore& p = particles_;
  const Vec3 point = 0.5 * (c.geometry.pointA + c.geometry.pointB);
  ContactKinematics motion;
  motion.volumeRadiusA = shapes_[p.shape[c.a]].volumeEquivalentRadius();
  motion.angularVelocityA = p.angularVelocity[c.a];
  const Vec3 velocityA = p.velocity[c.a] + p.angularVelocity[c.a].cross(point - p.position[c.a]);
  if (c.onWall()) {
    const Wall& wall = walls_[c.b & ~wallFlag];
    motion.relativeVelocity = wall.velocity - velocityA;
    motion.effectiveMass = p.mass[c.a];
  } else {
    const Vec3 centreB = p.position[c.b] + c.shift;
    motion.relativeVelocity = p.velocity[c.b] + p.angularVelocity[c.b].cross(point - centreB) - velocityA;
    motion.volumeRadiusB = shapes_[p.shape[c.b]].volumeEquivalentRadius();
    motion.angularVelocityB = p.angularVelocity[c.b];
    motion.effectiveMass = p.mass[c.a] * p.mass[c.b] / (p.mass[c.a] + p.mass[c.b]);
  }
  c.force = contactForce(lawOf(c), c.geometry, motion, c.history, dt_);
}

void World::buildCandidates() {
  // Candidates in key order (a, then b with walls after particles): for each particle its pairs
  // from the neighbour list (sorted by (a, b)), then the walls within reach.
  const ParticleStore& p = particles_;
  std::vector<Contact> next;
  next.reserve(neighbours_.pairs().size() + pairs_.size());
  const double skin = neighbours_.skin(), range = largestRange();
  auto pair = neighbours_.pairs().begin();
  const auto pairsEnd = neighbours_.pairs().end();
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    for (; pair != pairsEnd && pair->a == i; ++pair) next.push_back(candidate(i, pair->b, pair->shift));
    for (std::uint32_t w = 0; w < walls_.size(); ++w) {
      const Plane& plane = walls_[w].plane;
      if ((p.position[i] - plane.point).dot(plane.normal) < boundingRadius_[i] + range + skin) {
        next.push_back(candidate(i, wallFlag | w));
      }
    }
  }
  // Carry the history of pairs that persist (both lists are sorted by key).
  auto previous = pairs_.begin();
  for (Contact& c : next) {
    while (previous != pairs_.end() && previous->key() < c.key()) ++previous;
    if (previous != pairs_.end() && previous->key() == c.key()) {
      c.geometry = previous->geometry;
      c.history = previous->history;
      c.separation = previous->separation;
    }
  }
  pairs_ = std::move(next);
  indexInvolvement();
  wallReference_.clear();
  for (const Wall& w : walls_) wallReference_.push_back(w.plane.point);
}

void World::indexInvolvement() {
  // Counting sort of the contacts by particle, in key order within each particle.
  if (pairs_.size() >= bodyBFlag) throw std::length_error("World: more than 2^31 candidate contacts");
  involvementStart_.assign(particles_.size() + 1, 0);
  for (const Contact& c : pairs_) {
    ++involvementStart_[c.a + 1];
    if (!c.onWall()) ++involvementStart_[c.b + 1];
  }
  for (std::size_t i = 1; i < involvementStart_.size(); ++i) involvementStart_[i] += involvementStart_[i - 1];
  involvement_.resize(involvementStart_.back());
  std::vector<std::uint32_t> fill(involvementStart_.begin(), involvementStart_.end() - 1);
  for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
    involvement_[fill[pairs_[k].a]++] = k;
    if (!pairs_[k].onWall()) involvement_[fill[pairs_[k].b]++] = k | bodyBFlag;
  }
}

double World::largestRange() const {
  double range = 0.0;
  for (const ContactModel& m : models_) range = std::max(range, m.reach);
  return range;
}

bool World::wallsMovedHalfSkin() const {
  if (wallReference_.size() != walls_.size()) return true;
  const double limit = 0.25 * neighbours_.skin() * neighbours_.skin();
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if ((walls_[w].plane.point - wallReference_[w]).squaredNorm() > limit) return true;
  }
  return false;
}

void World::computeForces() {
  for (std::size_t k = 0; k < models_.size(); ++k) {
    if (!modelSet_[k]) throw std::logic_error("World: a material pair has no contact model");
  }
  const auto start = Clock::now();
  ParticleStore& p = particles_;
  if (neighbours_.needsRebuild(p) || wallsMovedHalfSkin()) {
    if (reorderInterval_ > 0 && neighbours_.builds() % reorderInterval_ == 0) reorderAlongHilbertCurve();
    // Laws acting across a gap (roughness) widen every candidate's reach by their range.
    const double range = largestRange();
    if (range > 0.0) {
      std::vector<double> reach(boundingRadius_);
      for (double& r : reach) r += 0.5 * range;
      neighbours_.rebuild(p, reach);
    } else {
      neighbours_.rebuild(p, boundingRadius_);
    }
    buildCandidates();
  }

  const auto detected = Clock::now();
  timing_.broadPhase += seconds(detected - start);
  const auto count = static_cast<std::ptrdiff_t>(pairs_.size());
#pragma omp parallel for schedule(dynamic, 64)
  for (std::ptrdiff_t k = 0; k < count; ++k) detect(pairs_[k]);
  const auto lawStart = Clock::now();
  timing_.detection += seconds(lawStart - detected);
  // Laws, and per contact the step's statistics and whether it carries force.
  long long calls = 0, iterations = 0, failures = 0, deep = 0, lost = 0, invalid = 0;
  long long byStatus[contactStatusCount] = {};
  acting_.resize(pairs_.size());
  loads_.resize(pairs_.size());
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : calls, iterations, failures, deep, lost, invalid, byStatus[:contactStatusCount])
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    Contact& c = pairs_[k];
    // Out of its law's range a pair is a gap, kept as the next step's warm start or cull, and
    // its history ends; within range the law acts, or keeps its history without acting (a
    // detached contact inside a plastic dent).
    const bool inRange = interacting(c);
    if (inRange) {
      applyLaw(c);
      invalid += !c.force.valid;
    } else {
      lost += std::isinf(c.history.range(lawOf(c)));  // an adhesive contact its law still held
      c.force = {.acting = false};
      c.history = {};
    }
    const bool acting = c.force.acting;
    const ContactGeometry& g = c.geometry;
    if (!c.onWall()) {
      ++calls;
      iterations += g.iterations;
    }
    if (g.status != ContactStatus::Converged && g.status != ContactStatus::Separated) {
      ++failures;
      ++byStatus[static_cast<int>(g.status)];
    }
    if (!g.converged() && c.separation <= 0.0) c = candidate(c.a, c.b, c.shift);  // nothing to warm-start or cull
    acting_[k] = acting;
    if (!acting) continue;
    if (g.overlap > 0.5 * shapes_[p.shape[c.a]].volumeEquivalentRadius()) ++deep;
    loads_[k] = {c.force.onB, 0.5 * (g.pointA + g.pointB), c.force.momentOnB, c.shift};
  }
  statistics_.detectorCalls += calls;
  statistics_.detectorIterations += iterations;
  statistics_.detectorFailures += failures;
  for (int k = 0; k < contactStatusCount; ++k) statistics_.failuresByStatus[k] += byStatus[k];
  statistics_.deepOverlaps += deep;
  statistics_.lostAdhesions += lost;
  statistics_.lawFailures += invalid;
  const auto reduction = Clock::now();
  timing_.law += seconds(reduction - lawStart);

  // Reduction. Each particle sums its contacts in their key order (the order of a serial sweep
  // over the key-ordered list), so the result does not depend on the thread count.
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    p.force[i] = p.mass[i] * (gravity_ - viscousDamping_ * p.velocity[i]);
    p.torque[i].setZero();
    for (std::uint32_t m = involvementStart_[i]; m < involvementStart_[i + 1]; ++m) {
      const std::uint32_t k = involvement_[m] & ~bodyBFlag;
      if (!acting_[k]) continue;
      const ContactLoad& load = loads_[k];
      if ((involvement_[m] & bodyBFlag) == 0) {  // i is body A
        p.force[i] -= load.force;
        p.torque[i] -= (load.point - p.position[i]).cross(load.force) + load.moment;
      } else {
        p.force[i] += load.force;
        p.torque[i] += (load.point - (p.position[i] + load.shift)).cross(load.force) + load.moment;
      }
    }
  }
  for (Wall& w : walls_) {
    w.force.setZero();
    w.elasticForce.setZero();
    w.stiffness = 0.0;
  }
  interacting_.clear();
  for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
    if (!acting_[k]) continue;
    const Contact& c = pairs_[k];
    if (c.onWall()) {
      Wall& w = walls_[c.b & ~wallFlag];
      w.force += c.force.onB;
      w.elasticForce += c.force.onB - c.force.normalDamping * c.geometry.normal;
      w.stiffness += c.force.normalStiffness;
    }
    interacting_.push_back(k);
  }
  forcesCurrent_ = true;
  timing_.reduction += seconds(Clock::now() - reduction);
}

void World::step() {
  if (!(dt_ > 0.0)) throw std::logic_error("World: time step not set");
  if (!forcesCurrent_) computeForces();
  const double h = dt_;
  ParticleStore& p = particles_;
  const auto start = Clock::now();
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    kick(p, i, 0.5 * h);
    drift(p, i, h);
  }
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    Wall& w = walls_[k];
    if (w.servo) w.velocity = servoVelocity(k) * w.plane.normal;
    w.plane.point += h * w.velocity;
  }
  time_ += h;
  timing_.integration += seconds(Clock::now() - start);
  computeForces();
  const auto kickStart = Clock::now();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) kick(p, i, 0.5 * h);
  timing_.integration += seconds(Clock::now() - kickStart);
}

double World::wallArea(std::size_t w) const {
  int axis;
  walls_.at(w).plane.normal.cwiseAbs().maxCoeff(&axis);
  const Vec3 L = domain_.length();
  return L.prod() / L(axis);
}

double World::wallPressure(std::size_t w) const {
  const Wall& wall = walls_.at(w);
  return std::abs(wall.force.dot(wall.plane.normal)) / wallArea(w);
}

double World::servoVelocity(std::size_t w) const {
  const Wall& wall = walls_[w];
  const double target = wall.servo->pressure * wallArea(w);
  const double error = target - std::abs(wall.elasticForce.dot(wall.plane.normal));  // N
  double speed = wall.servo->maxSpeed * std::clamp(error / target, -1.0, 1.0);
  if (wall.stiffness > 0.0) {
    const double limit = std::abs(error) / (2.0 * wall.stiffness * dt_);
    speed = std::clamp(speed, -limit, limit);
  }
  return speed;
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

double World::hertzTimeStep(double speed, double stepsPerCollision) const {
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const double R = shapes_[particles_.shape[i]].volumeEquivalentRadius(), m = particles_.mass[i];
    const double Estar = model(particles_.material[i], particles_.material[i]).effectiveModulus;
    dt = std::min(dt, hertzCollisionTime(0.5 * m, 0.5 * R, Estar, speed) / stepsPerCollision);
  }
  return dt;
}

}  // namespace sqdem
