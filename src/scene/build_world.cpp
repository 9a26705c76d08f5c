#include "sqdem/scene/build_world.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <numbers>
#include <random>

#include "insertion_grid.hpp"
#include "sqdem/mechanics/damping.hpp"
#include "sqdem/scene/scene_loader.hpp"

namespace sqdem {
namespace {

/// Shoemake's uniform random rotation.
Quat randomRotation(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double u1 = u(rng), u2 = 2.0 * std::numbers::pi * u(rng), u3 = 2.0 * std::numbers::pi * u(rng);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  return Quat(a * std::sin(u2), a * std::cos(u2), b * std::sin(u3), b * std::cos(u3)).normalized();
}

double sample(std::mt19937_64& rng, const std::array<double, 2>& range) {
  return range[0] == range[1] ? range[0] : std::uniform_real_distribution<double>(range[0], range[1])(rng);
}

/// A superquadric of the family: its semi-axes as given, or the sampled volume-equivalent radius
/// and aspect ratios.
Superquadric sampleShape(std::mt19937_64& rng, const ShapeFamily& f) {
  if (f.semiAxes) return Superquadric(f.semiAxes->x(), f.semiAxes->y(), f.semiAxes->z(), f.n1, f.n2);
  const double radius = sample(rng, f.volumeRadius), b = sample(rng, f.aspectB), c = sample(rng, f.aspectC);
  const double unit = Superquadric(1.0, b, c, f.n1, f.n2).volumeEquivalentRadius();
  const double s = radius / unit;
  return Superquadric(s, s * b, s * c, f.n1, f.n2);
}

/// Explicit particles may not start overlapping another particle or a wall unless their entry
/// allows it: the contacts of a copy of the world at its initial state name the first offender.
void refuseOverlaps(const Scene& scene, const World& world) {
  // Particle ids are the order of addition: the explicit particles are ids 0 .. n-1.
  const auto allows = [&](std::uint32_t id) { return id >= scene.particles.size() || scene.particles[id].allowOverlap; };
  const auto name = [&](std::uint32_t id) { return id < scene.particles.size() ? scene.particles[id].origin : "an inserted particle"; };
  bool check = false;
  for (std::uint32_t i = 0; i < scene.particles.size(); ++i) check = check || !allows(i);
  if (!check) return;
  World probe = world;  // the world itself starts without history
  probe.computeForces();
  const std::vector<std::uint32_t>& id = probe.particles().id;  // slots may have been re-ordered
  for (const ContactView c : probe.contacts()) {
    if (c.overlap() <= 0.0 || (allows(id[c.a()]) && (c.onWall() || allows(id[c.b()])))) continue;
    const std::uint32_t first = c.onWall() ? id[c.a()] : std::min(id[c.a()], id[c.b()]);
    throw SceneError(scene.path + ": " + name(first) + " overlaps " +
                     (c.onWall() ? "walls[" + std::to_string(c.wall()) + "]" : name(std::max(id[c.a()], id[c.b()]))) +
                     " by " + shortNumber(c.overlap()) + " m at the start; move it, or set allow_overlap: true on its entry");
  }
}

}  // namespace

World buildWorld(const Scene& scene) {
  std::mt19937_64 rng(scene.seed);
  std::vector<Superquadric> shapes;
  std::vector<std::uint32_t> materialOf;
  std::vector<Vec3> centres;
  std::vector<Quat> orientations;
  std::vector<double> radii;
  for (const ParticleSpec& p : scene.particles) {  // explicit particles first
    shapes.push_back(p.shape ? sampleShape(rng, scene.shapes[*p.shape])  // a fixed family: no draw
                             : Superquadric(p.semiAxes.x(), p.semiAxes.y(), p.semiAxes.z(), p.n1, p.n2));
    if (const int d = scene.domain.outsideAlong(p.centre); d >= 0) {
      throw SceneError(scene.path + ": " + p.origin + ": the centre lies outside the domain along " + "xyz"[d]);
    }
    materialOf.push_back(p.material);
    centres.push_back(scene.domain.wrap(p.centre));
    orientations.push_back(p.orientation);
    radii.push_back(shapes.back().boundingRadius());
  }
  // Random insertions keep their bounding spheres clear of the walls (a mesh's: of its triangles).
  std::vector<std::optional<MeshTree>> meshTrees;
  for (const WallSpec& w : scene.walls) meshTrees.push_back(w.mesh ? std::optional(MeshTree(w.mesh->mesh())) : std::nullopt);
  const auto clearOfWalls = [&](const Vec3& x, double r) {
    for (std::size_t w = 0; w < scene.walls.size(); ++w) {
      // (a mesh wall starts unturned: its body frame is the world's, shifted to its origin)
      const bool clear = std::visit(PerShape{[&](const MeshWall& m) { return meshTrees[w]->trianglesNear(x - m.origin, r).empty(); },
                                             [&](const auto& surface) { return surface.distance(x) > r; }},
                                    scene.walls[w].wall.surface);
      if (!clear) return false;
    }
    return true;
  };
  for (std::size_t k = 0; k < scene.insertions.size(); ++k) {
    const InsertionSpec& in = scene.insertions[k];
    std::uniform_real_distribution<double> ux(in.lo.x(), in.hi.x()), uy(in.lo.y(), in.hi.y()), uz(in.lo.z(), in.hi.z());
    // Sample every shape first and place the largest first (random sequential addition then
    // reaches much higher loose fractions for polydisperse sets). Species by species: the first
    // a count, or shapes until their volume reaches its share of solidFraction x the region's
    // volume; the others until their volume reaches their share (of that, or of the total the
    // first's volume implies).
    struct Drawn {
      Superquadric shape;
      Quat orientation;
      std::uint32_t material;
    };
    std::vector<Drawn> batch;
    const double region = (in.hi - in.lo).prod();
    double firstVolume = 0.0;
    for (std::size_t s = 0; s < in.species.size(); ++s) {
      const InsertedSpecies& species = in.species[s];
      const bool counted = s == 0 && in.solidFraction == 0.0;
      const double target = in.solidFraction > 0.0 ? species.volumeFraction * in.solidFraction * region
                                                   : species.volumeFraction / in.species[0].volumeFraction * firstVolume;
      double volume = 0.0;
      for (std::size_t drawn = 0; counted ? drawn < in.count : volume < target; ++drawn) {
        const Superquadric shape = sampleShape(rng, scene.shapes[species.shape]);
        volume += shape.volume();
        batch.push_back({shape, in.randomOrientation ? randomRotation(rng) : Quat::Identity(), species.material});
        if (batch.size() > 10'000'000) {
          throw SceneError(scene.path + ": insert[" + std::to_string(k) + "]: asks for more than 1e7 particles");
        }
      }
      if (s == 0) firstVolume = volume;
    }
    std::stable_sort(batch.begin(), batch.end(), [](const Drawn& x, const Drawn& y) { return x.shape.boundingRadius() > y.shape.boundingRadius(); });
    if (!batch.empty()) {  // the largest must fit the box at all (a unit slip between shapes and domain?)
      const double diameter = 2.0 * batch.front().shape.boundingRadius();
      for (int d = 0; d < 3; ++d) {
        if (diameter >= scene.domain.length()(d)) {
          throw SceneError(scene.path + ": insert[" + std::to_string(k) + "]: a particle of bounding diameter " +
                           shortNumber(diameter) + " m does not fit the domain, " + shortNumber(scene.domain.length()(d)) +
                           " m along " + "xyz"[d] + " (are shapes and domain both in m?)");
        }
      }
    }
    // Every centre so far (explicit, from files, of earlier entries) binned in cells wider than
    // any r + radii[j] this batch can test: its largest (the first) plus the largest of all.
    const double rBatch = batch.empty() ? 0.0 : batch.front().shape.boundingRadius();
    const double rPlaced = radii.empty() ? 0.0 : *std::max_element(radii.begin(), radii.end());
    detail::InsertionGrid grid(scene.domain, rBatch + std::max(rBatch, rPlaced), centres.size() + batch.size());
    for (std::size_t j = 0; j < centres.size(); ++j) grid.add(static_cast<std::uint32_t>(j), centres[j]);
    for (std::size_t n = 0; n < batch.size(); ++n) {
      const auto& [shape, q, material] = batch[n];
      const double r = shape.boundingRadius();
      bool placed = false;
      for (int attempt = 0; attempt < 10000 && !placed; ++attempt) {
        const Vec3 x = scene.domain.wrap(Vec3(ux(rng), uy(rng), uz(rng)));
        // The grid skips only centres that pass this test (insertion_grid.hpp).
        placed = clearOfWalls(x, r) && grid.allOf(x, [&](std::uint32_t j) {
          return scene.domain.minimumImage(x - centres[j]).norm() > r + radii[j];
        });
        if (placed) {
          grid.add(static_cast<std::uint32_t>(centres.size()), x);
          shapes.push_back(shape);
          materialOf.push_back(material);
          centres.push_back(x);
          orientations.push_back(q);
          radii.push_back(r);
        }
      }
      if (!placed) {
        throw SceneError(scene.path + ": insert[" + std::to_string(k) + "]: placed only " + std::to_string(n) + " of " +
                         std::to_string(batch.size()) + " particles without overlap; enlarge the region or lower the count / solid_fraction");
      }
    }
  }

  std::vector<Material> materials;
  for (const NamedMaterial& m : scene.materials) materials.push_back(m.material);
  const double smallest = shapes.empty() ? 0.0 : std::min_element(shapes.begin(), shapes.end(), [](const auto& a, const auto& b) {
                                                   return a.volumeEquivalentRadius() < b.volumeEquivalentRadius();
                                                 })->volumeEquivalentRadius();
  const double skin = scene.skin > 0.0 ? scene.skin : 0.2 * smallest;
  // Minimum image: a particle may reach at most one image of another along a periodic
  // direction, so the period must exceed twice the largest reach (diameter + skin).
  double largest = 0.0;
  for (const double r : radii) largest = std::max(largest, r);
  for (int d = 0; d < 3; ++d) {
    const double reach = 2.0 * largest + skin;
    if (scene.domain.periodic[d] && scene.domain.length()(d) < 2.0 * reach) {
      throw SceneError(scene.path + ": domain: the periodic length along " + std::string(1, "xyz"[d]) + ", " +
                       shortNumber(scene.domain.length()(d)) + " m, must be at least twice the largest bounding diameter " +
                       "plus the skin (" + shortNumber(2.0 * reach) + " m here), or a particle would meet two images of another");
    }
  }
  // A cylinder acts through its image nearest each particle: the images' spacing normal to the
  // axis must exceed what one particle can reach of two of them.
  for (std::size_t k = 0; k < scene.walls.size(); ++k) {
    const CylinderWall* roller = scene.walls[k].wall.as<CylinderWall>();
    if (roller == nullptr) continue;
    const Cylinder& w = roller->cylinder;
    for (int d = 0; d < 3; ++d) {
      const double spacing = scene.domain.length()(d) * Vec3::Unit(d).cross(w.axis).norm();
      const double reach = 2.0 * (w.radius + largest + skin);
      if (scene.domain.periodic[d] && spacing > 0.0 && spacing < reach) {
        throw SceneError(scene.path + ": walls[" + std::to_string(k) + "]: a cylinder of radius " + shortNumber(w.radius) +
                         " m needs its periodic images along " + std::string(1, "xyz"[d]) + " at least " + shortNumber(reach) +
                         " m apart (2 x (radius + largest bounding radius + skin)); they are " + shortNumber(spacing) +
                         " m apart: a particle would meet two of them");
      }
    }
  }
  // Bonds form where the detector finds the gap, within the skin.
  double largestVolumeRadius = 0.0;
  for (const Superquadric& s : shapes) largestVolumeRadius = std::max(largestVolumeRadius, s.volumeEquivalentRadius());
  for (std::size_t k = 0; k < scene.stages.size(); ++k) {
    const double gap = scene.stages[k].bondGap.value_or(0.0) * largestVolumeRadius;
    if (gap > skin) {
      throw SceneError(scene.path + ": stages[" + std::to_string(k) + "].form_bonds.gap: " + shortNumber(*scene.stages[k].bondGap) +
                       " x the largest volume radius, " + shortNumber(gap) + " m, is beyond the skin " + shortNumber(skin) +
                       " m: raise 'skin' to at least that or give a smaller gap");
    }
  }
  World world(shapes, materials, scene.domain, skin, scene.broadPhase.value_or(automaticBroadPhase(radii, skin)));
  world.setReorderInterval(scene.reorderEvery);
  world.setSphereOrientations(scene.output.sphereOrientation);
  if (scene.output.energy) world.enableEnergyLedger();
  if (scene.detectorTolerance > 0.0) world.setDetectorControl({.tolerance = scene.detectorTolerance});
  for (const InteractionSpec& in : scene.interactions) {
    ContactModel model = world.defaultContactModel(in.materialA, in.materialB);
    model.normal = in.normal;
    model.curvatures = in.curvatures;
    model.tangential.elliptic = in.ellipticTangential;
    model.eccentricity = in.eccentricity;
    model.capFactor = in.capFactor;
    model.curvatureTolerance = in.curvatureTolerance;
    if (in.restitution > 0.0) model.damping.ratio = restitutionDampingRatio(in.restitution);  // 0 for e = 1
    if (in.friction >= 0.0) model.tangential.friction = in.friction;
    // F_C and xi_crit of the rolling resistance use the real material.
    if (in.rollingHysteresis > 0.0) model.rolling = HaervigRollingResistance{in.rollingHysteresis, model.effectiveModulus};
    model.bond = in.bond;
    model.deepOverlapsExpected = in.deepOverlapsExpected;
    model.effectiveModulus *= in.stiffnessScale;
    model.tangential.effectiveShear *= in.stiffnessScale;
    const std::string where = scene.path + ": interactions[" + std::to_string(&in - scene.interactions.data()) + "]";
    try {
      world.setContactModel(in.materialA, in.materialB, model);
    } catch (const std::invalid_argument& e) {
      throw SceneError(where + ": " + in.normalName + " admits no contact of the scene's largest particles: " + e.what());
    }
    const double reach = world.contactModel(in.materialA, in.materialB).reach;
    if (reach > world.neighbourList().skin()) {  // the detector solves gaps up to the skin
      throw SceneError(where + ": " + in.normalName + " acts across gaps up to " + shortNumber(reach) +
                       " m, beyond the skin " + shortNumber(world.neighbourList().skin()) + " m: raise 'skin' to at least that");
    }
  }
  for (const WallSpec& spec : scene.walls) {
    Wall w = spec.wall;
    if (spec.mesh) std::get<MeshWall>(w.surface).mesh = world.addMesh(*spec.mesh);
    world.addWall(w);
  }
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    world.addParticle(static_cast<std::uint32_t>(i), materialOf[i], centres[i], orientations[i]);
  }
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    world.particles().velocity[i] = scene.particles[i].velocity;
    world.particles().setAngularVelocity(i, scene.particles[i].angularVelocity);
  }
  refuseOverlaps(scene, world);
  world.setGravity(scene.gravity);
  world.setTimeStep(scene.timeStep ? *scene.timeStep : automaticTimeStep(scene, world, scene.timeStepFraction));
  return world;
}

namespace {

/// The smallest reduced_stiffness E_mod / E of the scene: the Rayleigh time scales as E^-1/2.
double smallestStiffnessScale(const Scene& scene) {
  double minScale = 1.0;
  for (const InteractionSpec& in : scene.interactions) minScale = std::min(minScale, in.stiffnessScale);
  return minScale;
}

}  // namespace

double rayleighTime(const Scene& scene, const World& world) {
  return world.rayleighTimeStep() / std::sqrt(smallestStiffnessScale(scene));
}

double automaticTimeStep(const Scene& scene, const World& world, double fraction) {
  double dt = std::min(fraction * world.rayleighTimeStep() / std::sqrt(smallestStiffnessScale(scene)), fraction * world.bondTimeStep());
  if (scene.impactVelocity > 0.0) dt = std::min(dt, world.hertzTimeStep(scene.impactVelocity, scene.stepsPerCollision));
  return dt;
}

}  // namespace sqdem
