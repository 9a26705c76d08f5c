// sceneFingerprint (scene_fingerprint.hpp): every field of the validated scene but its path and output
// settings (except the energy ledger, part of the world's state), part by part, fed in declaration
// order to a CRC-64 each. A new Scene field must be added here.

#include "sqdem/scene/scene_fingerprint.hpp"
#include "sqdem/archive/checkpoint_file.hpp"

namespace sqdem {
namespace {

struct SceneHasher {
  Fingerprint f;

  void operator()(double v) { f(v); }
  void operator()(std::uint64_t v) { f(v); }
  void operator()(const std::string& s) { f(s); }
  void operator()(const Vec3& v) { f(v.x())(v.y())(v.z()); }
  void operator()(const Quat& q) { f(q.w())(q.x())(q.y())(q.z()); }
  void operator()(bool b) { f(n(b)); }
  void operator()(std::uint32_t i) { f(n(i)); }
  template <typename... T>
  void all(const T&... values) { ((*this)(values), ...); }
  /// Integers, enums and flags as one 64-bit value each.
  template <typename T>
  static std::uint64_t n(T v) { return static_cast<std::uint64_t>(v); }
};

}  // namespace

SceneFingerprint sceneFingerprint(const Scene& scene) {
  SceneFingerprint out;
  std::size_t part = 0;
  SceneHasher h;
  const auto next = [&] {  // closes the part being hashed
    out.parts[part++] = h.f.value();
    h = SceneHasher();
  };
  const Domain& d = scene.domain;
  h.all(scene.seed);
  next();
  h.all(d.lo, d.hi, h.n(d.periodic[0]), h.n(d.periodic[1]), h.n(d.periodic[2]));
  next();
  h.all(scene.gravity);
  next();
  h.all(scene.timeStep.value_or(0.0), scene.timeStepFraction, scene.impactVelocity, scene.stepsPerCollision);
  next();
  h.all(scene.skin, h.n(scene.broadPhase ? static_cast<int>(*scene.broadPhase) + 1 : 0), h.n(scene.reorderEvery));
  next();
  for (const NamedMaterial& m : scene.materials) {
    const Material& x = m.material;
    h.all(m.name, x.youngsModulus, x.poissonRatio, x.density, x.friction, x.restitution, x.yieldStrength);
  }
  next();
  for (const ShapeFamily& s : scene.shapes) {
    h.all(s.name, s.volumeRadius[0], s.volumeRadius[1], s.aspectB[0], s.aspectB[1], s.aspectC[0], s.aspectC[1], s.n1, s.n2);
    if (s.semiAxes) h(*s.semiAxes);  // (the particles' shapes: before, the ranges' round-off of them)
  }
  next();
  for (const InteractionSpec& i : scene.interactions) {
    h.all(h.n(i.materialA), h.n(i.materialB), i.normalName, h.n(i.curvatures), h.n(i.ellipticTangential), h.n(i.eccentricity), i.capFactor,
          i.curvatureTolerance, i.restitution, i.friction, i.stiffnessScale, i.rollingHysteresis);
    for (const auto& [key, value] : i.lawParameters) h.all(key, value);
    if (const std::optional<ParallelBond>& b = i.bond) {
      h.all(b->radiusMultiplier, b->normalStiffness, b->shearStiffness, b->tensileStrength, b->shearStrength, b->dampingRatio);
    }
  }
  next();
  for (const WallSpec& w : scene.walls) {
    h.all(h.n(static_cast<std::uint32_t>(w.wall.surface.index())), w.wall.velocity, w.wall.angularVelocity, h.n(w.wall.material));
    std::visit([&](const auto& surface) { surface.fields([&](const auto&... field) { h.all(field...); }); }, w.wall.surface);
    if (!w.mesh) continue;
    for (const Vec3& v : w.mesh->mesh().vertices) h(v);  // the mesh as read, repaired and scaled
    for (const auto& t : w.mesh->mesh().triangles) h.all(h.n(t[0]), h.n(t[1]), h.n(t[2]));
  }
  next();
  for (const ParticleSpec& p : scene.particles) {
    const Quat& q = p.orientation;
    h.all(p.origin, h.n(p.shape.value_or(~std::uint32_t{0})), p.semiAxes, p.n1, p.n2, h.n(p.material), p.centre, q.w(), q.x(),
          q.y(), q.z(), p.velocity, p.angularVelocity, h.n(p.allowOverlap));
  }
  for (const InsertionSpec& in : scene.insertions) {
    h.all(h.n(in.count), in.solidFraction, h.n(in.species[0].shape), h.n(in.species[0].material), in.lo, in.hi,
          h.n(in.randomOrientation));
    for (std::size_t k = 1; k < in.species.size(); ++k) {
      h.all(h.n(in.species[k].shape), h.n(in.species[k].material), in.species[k].volumeFraction);
    }
    if (in.species.size() > 1) h.all(in.species[0].volumeFraction);
  }
  next();
  h.all(h.n(scene.output.energy));
  next();
  for (const StageSpec& st : scene.stages) {
    h = SceneHasher();
    h.all(st.name, st.duration, st.kineticEnergyRatio, st.wallPressure, st.porosity, h.n(st.pressureWall), st.minimumDuration, st.velocityScale,
          st.viscousDamping, h.n(st.wall.value_or(~std::size_t{0})), st.wallVelocity,
          h.n(st.servoWall.value_or(~std::size_t{0})), st.servo.pressure, st.servo.maxSpeed, st.bondGap.value_or(-1.0));
    for (const auto& [t, x] : st.wallPath.points) h.all(t, x);
    out.stages.push_back(h.f.value());
  }
  return out;
}

std::uint64_t SceneFingerprint::state() const {
  Fingerprint f;
  for (const std::uint64_t p : parts) f(p);
  return f.value();
}

std::string SceneFingerprint::differences(const SceneFingerprint& other) const {
  std::string keys;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (parts[k] != other.parts[k]) keys += (keys.empty() ? "'" : ", '") + std::string(partKeys[k]) + "'";
  }
  return keys;
}

}  // namespace sqdem
