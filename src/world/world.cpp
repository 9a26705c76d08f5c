#include "sqdem/world/world.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "sqdem/distributed/migration.hpp"
#include "sqdem/dynamics/integrator.hpp"
#include "sqdem/dynamics/rayleigh_time.hpp"
#include "sqdem/mechanics/collision_time.hpp"
#include "sqdem/mechanics/damping.hpp"
#include "sqdem/mechanics/elliptic.hpp"
#include "sqdem/math/permutation.hpp"
#include "team.hpp"

namespace sqdem {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

/// The energy ledger tells stored from dissipated work only for laws that state their stored energy.
void requireLedgerModel(const ContactModel& model) {
  if (!storesEnergy(model.normal)) {
    throw std::invalid_argument("World: the energy ledger needs laws that state their stored energy (StoredEnergyLaw)");
  }
}

}  // namespace

World::World(std::vector<Superquadric> shapes, std::vector<Material> materials, const Domain& domain, double skin,
             BroadPhase search)
    : shapes_(std::move(shapes)),
      materials_(std::move(materials)),
      models_(materials_.size() * materials_.size()),
      modelSet_(models_.size(), false),
      domain_(domain),
      neighbours_(skin, search),
      parts_{wholeBox(domain)} {
  setSphereOrientations(false);
}

void World::setSphereOrientations(bool advanced) {
  sphereOrientations_ = advanced;
  fitTurns();
}

void World::fitTurns() {
  // A bond is fixed in its bodies' frames (bond_frame.hpp): with bonds, a sphere's turn matters.
  const bool bonded = std::ranges::any_of(models_, [](const ContactModel& m) { return m.bond.has_value(); });
  turns_.clear();
  for (const Superquadric& s : shapes_) turns_.push_back(sphereOrientations_ || bonded || !s.isSphere());
}

void World::setCommunicator(std::shared_ptr<const Communicator> communicator) {
  communicator_ = std::move(communicator);
  ParticleStore& p = particles_;
  ghosts_.drop(p);
  neighbours_.restore({}, neighbours_.builds());  // built again at the next step
  const int ranks = communicator_->size();
  if (ranks == 1) {
    parts_ = {wholeBox(domain_)};
    return;
  }
  // Every rank holds the same particles: each cuts the same sub-domains, by particle counts.
  for (std::size_t i = 0; i < p.size(); ++i) p.position[i] = domain_.wrap(p.position[i]);
  parts_ = bisect(domain_, p.position, std::vector<double>(p.size(), 1.0), ranks, SerialCommunicator());
  std::vector<std::uint32_t> mine;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    if (ownerOf(parts_, p.position[i]) == communicator_->rank()) mine.push_back(i);
  }
  ParticleStore::forEachArray(p, [&](auto& array) { permute(array, mine); });
  interactions_.setCandidates({}, interactionScene(), ghosts_.localOwners());
}

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
  if (ledger_) requireLedgerModel(model);
  if (model.bond) model.bond->check();
  ContactModel m = model;
  m.reach = normalReach(m.normal, m.effectiveModulus, m.capFactor * largest);
  m.tangential.elliptic = m.tangential.elliptic && m.curvatures;  // the ellipse needs the curvatures
  models_.at(ma * n + mb) = models_.at(mb * n + ma) = m;
  modelSet_[ma * n + mb] = modelSet_[mb * n + ma] = true;
  fitTurns();
  interactions_.fitStore(interactionScene());
}

std::size_t World::addParticle(std::uint32_t shape, std::uint32_t material, const Vec3& centre, const Quat& q) {
  const Superquadric& s = shapes_.at(shape);
  const double density = materials_.at(material).density;
  forcesCurrent_ = false;
  ghosts_.drop(particles_);
  return particles_.add(shape, material, centre, q, s.mass(density), s.principalMomentsOfInertia(density),
                        s.boundingRadius());
}

void World::buildCandidates() {
  // Candidates in slot order: for each particle its pairs from the neighbour list (sorted by
  // slots, oriented by ids), then the walls within reach; of a mesh wall, the features of the
  // triangles within reach (the tree's, in the mesh's body frame; meshes are not periodic).
  const ParticleStore& p = particles_;
  std::vector<CandidateKey> next;
  next.reserve(neighbours_.pairs().size() + interactions_.store().size());
  const double skin = neighbours_.skin(), range = largestRange();
  auto pair = neighbours_.pairs().begin();
  const auto pairsEnd = neighbours_.pairs().end();
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    for (; pair != pairsEnd && pair->a == i; ++pair) next.push_back({i, pair->b});
    for (std::uint32_t w = 0; w < walls_.size(); ++w) {
      // A cylinder across a periodic direction acts through its image nearest the particle
      // (the contact's wall image); planes are parallel to the periodic directions.
      const double reach = p.boundingRadius[i] + range + skin;
      std::visit(PerShape{[&](const PlaneWall& plane) {
                            if (plane.distance(p.position[i]) < reach) next.push_back({i, wallFlag | w});
                          },
                          [&](const CylinderWall& cylinder) {
                            const Vec3 r = p.position[i] - cylinder.reference();
                            const Vec3 shift = r - domain_.minimumImage(r);
                            if (cylinder.distance(p.position[i] - shift) < reach) next.push_back({i, wallFlag | w, shift});
                          },
                          [&](const MeshWall& mesh) { addMeshCandidates(i, w, mesh, reach, next); }},
                 walls_[w].surface);
    }
  }
  statistics_.lostBonds += static_cast<long long>(interactions_.setCandidates(next, interactionScene(), ghosts_.localOwners()));
  if (communicator_->size() > 1) remoteLoads_.build(interactions_, p, ghosts_, *communicator_);
  wallReference_.clear();
  for (const Wall& w : walls_) wallReference_.push_back(w.reference());
}

void World::addMeshCandidates(std::uint32_t i, std::uint32_t w, const MeshWall& wall, double reach,
                              std::vector<CandidateKey>& next) const {
  const MeshFeatures& mesh = meshes_[wall.mesh];
  std::vector<std::uint32_t> features;
  for (std::uint32_t t : meshTrees_[wall.mesh].trianglesNear(wall.pose().toBody(particles_.position[i]), reach)) {
    features.push_back(t);
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t e = mesh.faceEdges(t)[c], v = mesh.mesh().triangles[t][c];
      if (mesh.edge(e).feature) features.push_back(mesh.edgeFeature(e));
      if (mesh.vertexIsFeature(v)) features.push_back(mesh.vertexFeature(v));
    }
  }
  std::sort(features.begin(), features.end());
  features.erase(std::unique(features.begin(), features.end()), features.end());
  for (std::uint32_t f : features) next.push_back({i, wallFlag | w, Vec3::Zero(), f});
}

std::uint32_t World::addMesh(MeshFeatures mesh) {
  meshTrees_.emplace_back(mesh.mesh());
  meshes_.emplace_back(std::move(mesh));
  return static_cast<std::uint32_t>(meshes_.size() - 1);
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
    if ((walls_[w].reference() - wallReference_[w]).squaredNorm() > limit) return true;
  }
  return false;
}

void World::setWallLoad(std::size_t w) {
  const std::array<ExactSum, 10>& part = wallLoads_[w].part;
  Wall& wall = walls_[w];
  for (int d = 0; d < 3; ++d) {
    wall.force(d) = part[WallLoadSum::force + d].value();
    wall.torque(d) = part[WallLoadSum::torque + d].value();
    wall.elasticForce(d) = part[WallLoadSum::elasticForce + d].value();
  }
  wall.stiffness = part[WallLoadSum::stiffness].value();
}

double World::ghostCutoff(const ParticleStore& p) const {
  double largest = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) largest = std::max(largest, p.boundingRadius[i]);
  return 2.0 * communicator_->max(largest) + largestRange() + neighbours_.skin();
}

void World::rebuildNeighbours() {
  ParticleStore& p = particles_;
  ghosts_.drop(p);
  for (std::size_t i = 0; i < p.size(); ++i) p.position[i] = domain_.wrap(p.position[i]);
  const auto exchangeStart = Clock::now();
  if (communicator_->size() > 1) rebalance();
  migrate(p, interactions_, parts_, *communicator_);
  timing_.ghosts += seconds(Clock::now() - exchangeStart);
  if (reorderInterval_ > 0 && neighbours_.builds() % reorderInterval_ == 0) reorderAlongHilbertCurve();
  const auto ghostStart = Clock::now();
  ghosts_.build(p, p.position, domain_, ghostCutoff(p), parts_, *communicator_);
  timing_.ghosts += seconds(Clock::now() - ghostStart);
  // Laws acting across a gap (roughness) widen every candidate's reach by their range.
  const double range = largestRange();
  if (range > 0.0) {
    std::vector<double> reach(p.boundingRadius);
    for (double& r : reach) r += 0.5 * range;
    neighbours_.rebuild(p, reach);
  } else {
    neighbours_.rebuild(p, p.boundingRadius);
  }
}

void World::rebalance() {
  const ParticleStore& p = particles_;
  std::vector<double> cost(p.size(), 1.0);
  const ContactStore& s = interactions_.store();
  for (std::size_t k = 0; k < s.size(); ++k) cost[s.a[k]] += 1.0;  // the store's slots: of the last build
  const long long mine = static_cast<long long>(p.size() + s.size());
  const double mean = static_cast<double>(communicator_->sum(mine)) / communicator_->size();
  imbalance_ = mean > 0.0 ? communicator_->max(static_cast<double>(mine)) / mean : 1.0;
  if (imbalance_ <= rebalanceThreshold_) return;
  parts_ = bisect(domain_, p.position, cost, communicator_->size(), *communicator_);
  ++rebalances_;
}

void World::requireModels() const {
  for (std::size_t k = 0; k < models_.size(); ++k) {
    if (!modelSet_[k]) throw std::logic_error("World: a material pair has no contact model");
  }
}

template <typename Body>
void World::inTeam(Body&& body) {
  Team team(threads());
  team.run([&] { body(team); });
  team.rethrow();
  timing_.barrierWait += team.meanWait();
  split_.rebalance(team.work());  // the next computation's runs
}

void World::computeForces() {
  requireModels();
  inTeam([&](Team& team) {
    team.master([&] { prepareForces(neighbours_.needsRebuild(particles_)); });
    team.barrier();
    if (!team.failed()) forcePhases(team, 0.0);
  });
}

void World::prepareForces(bool moved) {
  const auto start = Clock::now();
  const double ghostsBefore = timing_.ghosts;
  if (communicator_->any(moved) || wallsMovedHalfSkin()) {
    rebuildNeighbours();
    buildCandidates();
  } else {
    ghosts_.refresh(particles_, *communicator_);
    timing_.ghosts += seconds(Clock::now() - start);
  }
  wallLoads_.resize(walls_.size());
  for (WallLoadSum& load : wallLoads_) load.clear();
  interactions_.beginCompute(interactionScene());
  timing_.broadPhase += seconds(Clock::now() - start) - (timing_.ghosts - ghostsBefore);
}

void World::forcePhases(Team& team, double halfStep) {
  ParticleStore& p = particles_;
  Clock::time_point phase;  // the master's clock
  team.master([&] { phase = Clock::now(); });
  if (interactions_.cullsBySpeed()) {  // every slot's bound (ghosts too) before a group culls by it
    const Share slots = threadShare(static_cast<std::ptrdiff_t>(p.slots()));  // (ghosts too: a plain even share)
    for (std::ptrdiff_t i = slots.begin; i < slots.end; ++i) {
      p.speedBound[i] = p.velocity[i].norm() + p.angularVelocity[i].norm() * p.boundingRadius[i];
    }
    team.barrier();
  }
  const InteractionScene scene = interactionScene();
  auto computing = Clock::now();
  interactions_.compute(scene, statistics_);
  double work = seconds(Clock::now() - computing);
  if (interactions_.defersLaws(scene)) {  // the rungs solved by the whole team, outside the threads' shares of work
    team.barrier();
    interactions_.solveDeferredRungs(scene);
    team.barrier();
  }
  computing = Clock::now();
  interactions_.finishCompute(scene, statistics_);
  team.addWork(work + seconds(Clock::now() - computing));
  team.barrier();
  const bool ranks = communicator_->size() > 1;
  team.master([&] {
    const auto now = Clock::now();
    timing_.contacts += seconds(now - phase);
    phase = now;
    if (!ranks) return;
    remoteLoadsNow_ = remoteLoads_.exchange(interactions_, p, *communicator_);
    const auto exchanged = Clock::now();
    timing_.ghosts += seconds(exchanged - phase);
    phase = exchanged;
  });
  if (ranks) {  // the other ranks' loads are read by every thread
    team.barrier();
    if (team.failed()) return;
  }
  interactions_.reduce(p, gravity_, viscousDamping_, walls_, wallLoads_, remoteLoadsNow_, halfStep, split_);
  team.barrier();
  if (ranks) {  // the walls' shares summed over the ranks
    team.master([&] {
      for (WallLoadSum& load : wallLoads_) communicator_->sum(load.part);
    });
    team.barrier();
    if (team.failed()) return;
  }
  const Share walls = threadShare(static_cast<std::ptrdiff_t>(walls_.size()));
  for (std::ptrdiff_t w = walls.begin; w < walls.end; ++w) setWallLoad(w);
  team.barrier();
  team.master([&] {
    forcesCurrent_ = true;
    if (ledger_ && !ledger_->started) ledger_->start(*this);
    timing_.reduction += seconds(Clock::now() - phase);
  });
}

void World::step() {
  if (!(dt_ > 0.0)) throw std::logic_error("World: time step not set");
  if (!forcesCurrent_) computeForces();
  requireModels();
  const double h = dt_;
  ParticleStore& p = particles_;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  std::vector<Wall> wallsBefore;  // the ledger accounts the step between the forces and the closing kick
  std::atomic<bool> moved = false;  // some particle moved more than half the skin since the last build
  Clock::time_point phase = Clock::now();  // the master's clock
  inTeam([&](Team& team) {
    bool mineMoved = false;
    const Share particles = split_.share(n);
    for (std::ptrdiff_t i = particles.begin; i < particles.end; ++i) {
      kick(p, i, 0.5 * h);
      drift(p, i, h, turns_[p.shape[i]] != 0);
      mineMoved = mineMoved || neighbours_.outOfSkin(i, p.position[i]);
    }
    if (mineMoved) moved.store(true, std::memory_order_relaxed);
    team.barrier();
    team.master([&] {
      for (std::size_t k = 0; k < walls_.size(); ++k) {
        Wall& w = walls_[k];
        if (w.servo) w.velocity = servoVelocity(k) * w.get<PlaneWall>().plane.normal;
        w.advance(h);
      }
      time_ += h;
      timing_.integration += seconds(Clock::now() - phase);
      if (ledger_) wallsBefore = walls_;
      prepareForces(moved.load(std::memory_order_relaxed) || !neighbours_.covers(p.size()));
    });
    team.barrier();
    if (!team.failed()) forcePhases(team, ledger_ ? 0.0 : 0.5 * h);  // without the ledger, the closing kick in the reduction's pass
    if (ledger_) {  // (forcePhases ended with a barrier: the master's serial parts follow each other)
      team.master([&] {
        ledger_->addStep(*this, wallsBefore);
        phase = Clock::now();
      });
      team.barrier();
      const auto owned = static_cast<std::ptrdiff_t>(p.size());  // particles may have migrated
      if (!team.failed()) {
        const Share mine = split_.share(owned);
        for (std::ptrdiff_t i = mine.begin; i < mine.end; ++i) kick(p, i, 0.5 * h);
      }
      team.barrier();
      team.master([&] { timing_.integration += seconds(Clock::now() - phase); });
    }
  });
}

void World::enableEnergyLedger() {
  if (forcesCurrent_) throw std::logic_error("World: the energy ledger starts before the first force computation");
  for (std::size_t k = 0; k < models_.size(); ++k) {
    if (modelSet_[k]) requireLedgerModel(models_[k]);
  }
  ledger_.emplace();
  interactions_.fitStore(interactionScene());
}

std::size_t World::formBonds(double gapRatio) {
  if (!(gapRatio >= 0.0)) throw std::invalid_argument("World: a bond's gap ratio must be >= 0");
  if (!forcesCurrent_) computeForces();  // the candidates bonds form among
  const std::size_t formed = interactions_.formBonds(interactionScene(), gapRatio);
  return static_cast<std::size_t>(communicator_->sum(static_cast<long long>(formed)));
}

std::size_t World::bondCount() const {
  return static_cast<std::size_t>(communicator_->sum(static_cast<long long>(interactions_.bondCount())));
}

double World::particlesEdited(double kineticBefore) {
  interactions_.forgetSeparations();
  const double given = kineticEnergy() - kineticBefore;
  if (ledger_) ledger_->edits += given;
  return given;
}

void World::setThreads(int threads) {
  if (threads < 0 || threads > mostThreads) {
    throw std::invalid_argument("threads: " + std::to_string(threads) + " is not a count in [0, " + std::to_string(mostThreads) +
                                "] (0: OpenMP's default)");
  }
  threads_ = threads;
}

int World::threads() const { return threads_ > 0 ? threads_ : omp_get_max_threads(); }

void World::setSimdPath(SimdPath path) {
  if (!runsHere(path)) {
    throw std::invalid_argument("World: this CPU cannot run the '" + std::string(simdPathName(path)) + "' kernels");
  }
  simd_ = path;
}

const Vec3& World::planeNormal(std::size_t w) const {
  const PlaneWall* plane = walls_.at(w).as<PlaneWall>();
  if (plane == nullptr) throw std::invalid_argument("World: wall " + std::to_string(w) + " is " + walls_[w].kind() + ", not a plane");
  return plane->plane.normal;
}

double World::wallArea(std::size_t w) const {
  int axis;
  planeNormal(w).cwiseAbs().maxCoeff(&axis);
  const Vec3 L = domain_.length();
  return L.prod() / L(axis);
}

double World::wallPressure(std::size_t w) const {
  const Wall& wall = walls_.at(w);
  return std::abs(wall.force.dot(planeNormal(w))) / wallArea(w);
}

double World::servoVelocity(std::size_t w) const {
  const Wall& wall = walls_[w];
  const double target = wall.servo->pressure * wallArea(w);
  const double error = target - std::abs(wall.elasticForce.dot(planeNormal(w)));  // N
  double speed = wall.servo->maxSpeed * std::clamp(error / target, -1.0, 1.0);
  if (wall.stiffness > 0.0) {
    const double limit = std::abs(error) / (2.0 * wall.stiffness * dt_);
    speed = std::clamp(speed, -limit, limit);
  }
  return speed;
}

double World::kineticEnergy() const {
  ExactSum e;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    e.add(particles_.translationalEnergy(i));
    e.add(particles_.rotationalEnergy(i));
  }
  return communicator_->sum(e);
}

double World::rayleighTimeStep() const {
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const Material& m = materials_[particles_.material[i]];
    const double G = m.youngsModulus / (2.0 * (1.0 + m.poissonRatio));
    const Vec3 h = shapes_[particles_.shape[i]].halfExtents();
    dt = std::min(dt, sqdem::rayleighTimeStep(h.minCoeff(), m.density, G, m.poissonRatio));
  }
  return communicator_->min(dt);
}

double World::bondTimeStep() const {
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const Superquadric& shape = shapes_[particles_.shape[i]];
    for (std::uint32_t other = 0; other < materials_.size(); ++other) {
      const std::optional<ParallelBond>& bond = model(particles_.material[i], other).bond;
      if (!bond) continue;
      const BondSection section(bond->radiusMultiplier * shape.volumeEquivalentRadius());
      const double omega = bondAngularFrequency(*bond, section, particles_.mass[i], particles_.inertia[i].minCoeff(),
                                                shape.halfExtents().maxCoeff());
      dt = std::min(dt, 1.0 / omega);
    }
  }
  return communicator_->min(dt);
}

double World::hertzTimeStep(double speed, double stepsPerCollision) const {
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const double R = shapes_[particles_.shape[i]].volumeEquivalentRadius(), m = particles_.mass[i];
    const double Estar = model(particles_.material[i], particles_.material[i]).effectiveModulus;
    dt = std::min(dt, hertzCollisionTime(0.5 * m, 0.5 * R, Estar, speed) / stepsPerCollision);
  }
  return communicator_->min(dt);
}

}  // namespace sqdem
