// The scene's `particles:` and `insert:` (scene_sections.hpp).

#include <limits>
#include <string>
#include <tuple>

#include "sqdem/geometry/superquadric.hpp"
#include "sqdem/scene/particle_file.hpp"

#include "scene_sections.hpp"

namespace sqdem::detail {
namespace {

/// An entry of `particles:`: a fixed-size shape family, a material and the initial state.
ParticleSpec readParticle(const Reader& r, const YAML::Node& node, const std::string& where, const Scene& scene) {
  r.allowOnly(node, where, {"shape", "material", "centre", "quaternion", "velocity", "angular_velocity", "allow_overlap"});
  ParticleSpec p;
  p.origin = where;
  if (!node["shape"]) r.fail(node, where + ".shape", "missing");
  if (!node["material"]) r.fail(node, where + ".material", "missing");
  p.shape = r.lookup(node["shape"], where + ".shape", scene.shapes, "shape");
  const ShapeFamily& f = scene.shapes[*p.shape];
  if (f.volumeRadius[0] != f.volumeRadius[1] || f.aspectB[0] != f.aspectB[1] || f.aspectC[0] != f.aspectC[1]) {
    r.fail(node["shape"], where + ".shape", "shape '" + f.name + "' is a distribution; an explicit particle needs a shape of fixed size (semi_axes)");
  }
  p.material = r.lookup(node["material"], where + ".material", scene.materials, "material");
  p.centre = r.vector(node, "centre", where);
  if (const YAML::Node q = node["quaternion"]) {
    if (!q.IsSequence() || q.size() != 4) r.fail(q, where + ".quaternion", "must be [w, x, y, z]");
    p.orientation = Quat(r.asNumber(q[0], where + ".quaternion"), r.asNumber(q[1], where + ".quaternion"),
                         r.asNumber(q[2], where + ".quaternion"), r.asNumber(q[3], where + ".quaternion"));
    if (std::abs(p.orientation.norm() - 1.0) > 1e-6) r.fail(q, where + ".quaternion", "must be a unit quaternion [w, x, y, z]");
    p.orientation.normalize();
  }
  if (node["velocity"]) p.velocity = r.vector(node, "velocity", where);
  if (node["angular_velocity"]) p.angularVelocity = r.vector(node, "angular_velocity", where);
  p.allowOverlap = r.flag(node, "allow_overlap", where, false);
  return p;
}

/// A box {lo: [x, y, z], hi: [x, y, z]} (m), hi > lo.
std::pair<Vec3, Vec3> readRegion(const Reader& r, const YAML::Node& region, const std::string& where) {
  r.allowOnly(region, where, {"lo", "hi"});
  const Vec3 lo = r.vector(region, "lo", where), hi = r.vector(region, "hi", where);
  if (!((hi - lo).minCoeff() > 0.0)) r.fail(region, where, "needs hi > lo");
  return {lo, hi};
}

/// A species' shape and material (`where` an insert entry or a recipe's).
InsertedSpecies readSpecies(const Reader& r, const YAML::Node& in, const std::string& where, const Scene& scene) {
  if (!in["shape"]) r.fail(in, where + ".shape", "missing");
  if (!in["material"]) r.fail(in, where + ".material", "missing");
  return {r.lookup(in["shape"], where + ".shape", scene.shapes, "shape"),
          r.lookup(in["material"], where + ".material", scene.materials, "material")};
}

/// `recipe: [{shape, material, fraction}, ...]` with `by: mass | volume` (default mass): each
/// species' share of the particle volume (a mass fraction w_i becomes (w_i / rho_i) / sum_j w_j / rho_j).
std::vector<InsertedSpecies> readRecipe(const Reader& r, const YAML::Node& in, const std::string& where, const Scene& scene) {
  for (const char* key : {"shape", "material"}) {
    if (in[key]) r.fail(in[key], where + "." + key, "belongs to each entry of the recipe");
  }
  const YAML::Node recipe = in["recipe"];
  if (!recipe.IsSequence() || recipe.size() < 2) {
    r.fail(recipe, where + ".recipe", "must be a list of at least two {shape, material, fraction}");
  }
  const bool byMass = r.choice(in, "by", where, {{"mass", true}, {"volume", false}}, true);
  std::vector<InsertedSpecies> species;
  double sum = 0.0, volumeSum = 0.0;
  for (std::size_t k = 0; k < recipe.size(); ++k) {
    const std::string entry = where + ".recipe[" + std::to_string(k) + "]";
    r.allowOnly(recipe[k], entry, {"shape", "material", "fraction"});
    InsertedSpecies s = readSpecies(r, recipe[k], entry, scene);
    const double fraction = r.number(recipe[k], "fraction", entry);
    if (!(fraction > 0.0 && fraction <= 1.0)) r.fail(recipe[k]["fraction"], entry + ".fraction", "must be in (0, 1]");
    sum += fraction;
    s.volumeFraction = byMass ? fraction / scene.materials[s.material].material.density : fraction;
    volumeSum += s.volumeFraction;
    species.push_back(s);
  }
  if (std::abs(sum - 1.0) > 1e-9) {
    r.fail(recipe, where + ".recipe", "the fractions sum to " + shortNumber(sum) + "; they must sum to 1 (of the " +
                                          (byMass ? "mass" : "volume") + ")");
  }
  if (byMass) {
    for (InsertedSpecies& s : species) s.volumeFraction /= volumeSum;
  }
  return species;
}

}  // namespace

void readParticles(const Reader& r, const YAML::Node& root, Scene& scene) {
  // Explicit particles: the list, then the files of `insert`; random insertions avoid them.
  if (const YAML::Node list = root["particles"]) {
    if (!list.IsSequence() || list.size() == 0) r.fail(list, "particles", "must be a non-empty list of {shape, material, centre, ...}");
    for (std::size_t k = 0; k < list.size(); ++k) scene.particles.push_back(readParticle(r, list[k], "particles[" + std::to_string(k) + "]", scene));
  }
  const YAML::Node insert = root["insert"];
  if (insert && (!insert.IsSequence() || insert.size() == 0)) r.fail(insert, "insert", "must be a non-empty list");
  if (!insert && scene.particles.empty()) r.fail(root, "insert", "missing: give particles by 'insert' (a list of {count, shape, material, region} or {file}) or 'particles'");
  for (std::size_t k = 0; insert && k < insert.size(); ++k) {
    const std::string where = "insert[" + std::to_string(k) + "]";
    const YAML::Node in = insert[k];
    if (in.IsMap() && in["file"]) {
      r.allowOnly(in, where, {"file", "allow_overlap", "offset", "region"});
      const std::filesystem::path file = r.relative(r.text(in, "file", where));
      if (!std::filesystem::is_regular_file(file)) {
        r.fail(in["file"], where + ".file", "cannot open '" + file.string() + "' (paths are relative to the scene file)");
      }
      const bool allowOverlap = r.flag(in, "allow_overlap", where, false);
      const Vec3 offset = in["offset"] ? r.vector(in, "offset", where) : Vec3::Zero();  // e.g. tiling a periodic bed
      std::vector<ParticleSpec> particles;
      try {
        particles = readParticleFile(file, scene.materials);
      } catch (const SceneError& e) {
        r.fail(in["file"], where + ".file", e.what());
      }
      // region: only the particles whose bounding spheres lie within it (cutting a strip out of
      // a periodic bed, whose particles cross its faces).
      Vec3 keepLo = Vec3::Constant(-std::numeric_limits<double>::infinity()), keepHi = -keepLo;
      if (in["region"]) std::tie(keepLo, keepHi) = readRegion(r, in["region"], where + ".region");
      for (ParticleSpec& p : particles) {
        p.allowOverlap = allowOverlap;
        p.centre += offset;
        const double reach = Superquadric(p.semiAxes.x(), p.semiAxes.y(), p.semiAxes.z(), p.n1, p.n2).boundingRadius();
        if (((p.centre.array() - reach) < keepLo.array()).any() || ((p.centre.array() + reach) > keepHi.array()).any()) continue;
        scene.particles.push_back(std::move(p));
      }
      continue;
    }
    r.allowOnly(in, where, {"count", "solid_fraction", "shape", "material", "recipe", "by", "region", "random_orientation"});
    InsertionSpec spec;
    if (in["count"].IsDefined() == in["solid_fraction"].IsDefined()) {
      r.fail(in, where, "needs exactly one of count (particles" + std::string(in["recipe"] ? " of the recipe's first entry" : "") +
                            ") or solid_fraction (of the region's volume)");
    }
    if (in["count"]) spec.count = static_cast<std::size_t>(r.integer(in, "count", where, 1.0, 1e7));
    if (in["solid_fraction"]) {
      spec.solidFraction = r.number(in, "solid_fraction", where);
      if (!(spec.solidFraction > 0.0 && spec.solidFraction <= 0.4)) {
        r.fail(in["solid_fraction"], where + ".solid_fraction", "must be in (0, 0.4] (random sequential addition jams near 0.38)");
      }
    }
    if (in["by"] && !in["recipe"]) r.fail(in["by"], where + ".by", "belongs to a recipe (recipe: [{shape, material, fraction}, ...])");
    spec.species = in["recipe"] ? readRecipe(r, in, where, scene) : std::vector{readSpecies(r, in, where, scene)};
    const YAML::Node region = in["region"];
    if (!region) r.fail(in, where + ".region", "missing ({lo: [x,y,z], hi: [x,y,z]})");
    std::tie(spec.lo, spec.hi) = readRegion(r, region, where + ".region");
    for (int d = 0; d < 3; ++d) {
      if (!scene.domain.periodic[d] && (spec.lo(d) < scene.domain.lo(d) || spec.hi(d) > scene.domain.hi(d))) {
        r.fail(region, where + ".region", std::string("reaches outside the domain along ") + "xyz"[d] +
                                              " (the region holds particle centres and must lie within domain.lo, domain.hi)");
      }
    }
    spec.randomOrientation = r.flag(in, "random_orientation", where, true);
    scene.insertions.push_back(spec);
  }
}

}  // namespace sqdem::detail
