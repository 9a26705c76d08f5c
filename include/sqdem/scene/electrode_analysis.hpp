#pragma once
// The electrode analysis of a particle set with a scene's materials, laws and walls
// (docs/electrode_analysis.md): what `sqdem analyse` and a stage's `analyse` run. The bed is built
// again in this process from the particles (a world of its own: the engine's state is not
// touched), its contacts computed once, and analysed (analysis/bed_analysis.hpp); its files are
// written by writeAnalysis.

#include <filesystem>
#include <string>
#include <vector>

#include "sqdem/analysis/bed_analysis.hpp"
#include "sqdem/scene/scene.hpp"

namespace sqdem {

/// Per material its conductivity (S/m): `electronic_conductivity`; when no material gives one, 1
/// for every particle material (only the ratios are known); a material of no particle (a wall's)
/// without one conducts ideally (infinite). Throws SceneError naming the scene and the key for a
/// particle material without one when another material gives one.
std::vector<double> electronicConductivities(const Scene& scene, const std::vector<ParticleSpec>& particles);

struct AnalysedBed {
  World world;
  BedAnalysis analysis;
  bool conductivitiesGiven = false;  ///< the scene gives electronic_conductivity (S/m are known)
};

/// The scene's bed made of `particles` (its own particles and insertions dropped; overlaps
/// allowed) with `walls` in place of the scene's (their current state; empty: the scene's), its
/// contacts computed, analysed. Throws SceneError, std::invalid_argument (analyseBed).
AnalysedBed analyseParticles(Scene scene, std::vector<ParticleSpec> particles, const std::vector<Wall>& walls,
                             const AnalysisSpec& spec);

/// Writes into `directory` (created) analysis.json, pores.vti, network.vtp, profile.csv and
/// profile.png (analysis_files.cpp; docs/electrode_analysis.md lists their content); `source`
/// names the particles analysed. Returns the JSON object's text. Throws std::runtime_error.
std::string writeAnalysis(const AnalysedBed& bed, const std::string& scenePath, const std::string& source,
                          const std::filesystem::path& directory);

}  // namespace sqdem
