#include "sqdem/scene/electrode_analysis.hpp"

#include <algorithm>
#include <limits>

#include "sqdem/scene/build_world.hpp"

namespace sqdem {
namespace {

bool givesConductivities(const Scene& scene) {
  return std::ranges::any_of(scene.materials, [](const NamedMaterial& m) { return m.electronicConductivity.has_value(); });
}

}  // namespace

std::vector<double> electronicConductivities(const Scene& scene, const std::vector<ParticleSpec>& particles) {
  std::vector<std::uint8_t> ofParticles(scene.materials.size(), 0);
  for (const ParticleSpec& p : particles) ofParticles[p.material] = 1;
  const bool given = givesConductivities(scene);
  std::vector<double> out(scene.materials.size(), std::numeric_limits<double>::infinity());  // walls' materials: ideal
  for (std::size_t m = 0; m < out.size(); ++m) {
    const NamedMaterial& material = scene.materials[m];
    if (material.electronicConductivity) {
      out[m] = *material.electronicConductivity;
    } else if (ofParticles[m] && given) {
      throw SceneError(scene.path + ": 'materials." + material.name + ".electronic_conductivity': missing (S/m), as other materials give one");
    } else if (ofParticles[m]) {
      out[m] = 1.0;  // none given: every particle alike, the ratios alone known
    }
  }
  return out;
}

AnalysedBed analyseParticles(Scene scene, std::vector<ParticleSpec> particles, const std::vector<Wall>& walls,
                             const AnalysisSpec& spec) {
  for (ParticleSpec& p : particles) p.allowOverlap = true;
  BedAnalysisOptions options;
  options.zLow = spec.zLow;
  options.zHigh = spec.zHigh;
  options.voxels = spec.voxels;
  options.conductivity = electronicConductivities(scene, particles);
  const bool given = givesConductivities(scene);
  scene.particles = std::move(particles);
  scene.insertions.clear();
  for (std::size_t w = 0; w < walls.size() && w < scene.walls.size(); ++w) scene.walls[w].wall = walls[w];
  World world = buildWorld(scene);
  world.computeForces();
  BedAnalysis analysis = analyseBed(world, options);
  return {std::move(world), std::move(analysis), given};
}

}  // namespace sqdem
