// `sqdem analyse <scene.yaml> --particles FILE [--out DIR] [--region ZLO ZHI] [--voxels N]`: the
// electrode analysis of a particle file with the scene's materials, laws and walls
// (scene/electrode_analysis.hpp; docs/electrode_analysis.md): one JSON object on stdout, and in
// DIR its files.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <variant>

#include "commands.hpp"
#include "sqdem/scene/electrode_analysis.hpp"
#include "sqdem/scene/particle_file.hpp"
#include "sqdem/scene/scene_loader.hpp"

namespace sqdem::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* usage = "usage: sqdem analyse <scene.yaml> --particles FILE [--out DIR] [--region ZLO ZHI] [--voxels N]\n";

struct AnalyseArguments {
  std::string scene;
  fs::path particles, out;
  std::optional<double> zLow, zHigh;
  int voxels = 64;
};

/// The decimal number that is the whole of `text` (no hexadecimal, infinity or NaN); nullopt otherwise.
std::optional<double> numberIn(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  std::size_t used = 0;
  try {
    const double x = std::stod(text, &used);
    if (used == text.size() && std::isfinite(x)) return x;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

/// The arguments, or the message that refuses them.
std::variant<AnalyseArguments, std::string> parse(const Arguments& args) {
  AnalyseArguments a;
  std::vector<std::string> given;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& key = args[i];
    const auto values = [&](std::size_t n) { return i + n < args.size(); };
    if (key.rfind("--", 0) == 0) {
      if (std::find(given.begin(), given.end(), key) != given.end()) return "'" + key + "' is given twice";
      given.push_back(key);
    }
    if (key == "--particles" && values(1)) {
      a.particles = args[++i];
    } else if (key == "--out" && values(1)) {
      a.out = args[++i];
    } else if (key == "--region" && values(2)) {
      a.zLow = numberIn(args[i + 1]);
      a.zHigh = numberIn(args[i + 2]);
      if (!a.zLow || !a.zHigh || !(*a.zHigh > *a.zLow)) return "'--region' takes two numbers ZLO < ZHI (m), not '" + args[i + 1] + " " + args[i + 2] + "'";
      i += 2;
    } else if (key == "--voxels" && values(1)) {
      const std::optional<double> n = numberIn(args[++i]);
      if (!n || *n != std::floor(*n) || *n < 4 || *n > 256) return "'--voxels' takes a whole number in [4, 256], not '" + args[i] + "'";
      a.voxels = static_cast<int>(*n);
    } else if (a.scene.empty() && key.rfind("--", 0) != 0) {
      a.scene = key;
    } else {
      return "unexpected argument '" + key + "' (or a value missing after it)";
    }
  }
  if (a.scene.empty() || a.particles.empty()) return "a scene and --particles FILE are needed";
  if (a.out.empty()) a.out = a.particles.parent_path() / (a.particles.stem().string() + "_analysis");
  return a;
}

}  // namespace

int analyseCommand(const Arguments& args) {
  const auto parsed = parse(args);
  if (const auto* message = std::get_if<std::string>(&parsed)) {
    std::cerr << "sqdem analyse: " << *message << "\n" << usage;
    return 2;
  }
  const AnalyseArguments& a = std::get<AnalyseArguments>(parsed);
  try {
    const Scene scene = loadScene(a.scene);
    std::vector<ParticleSpec> particles = readParticleFile(a.particles, scene.materials);
    const AnalysedBed bed = analyseParticles(scene, std::move(particles), {}, {a.zLow, a.zHigh, a.voxels});
    std::cout << writeAnalysis(bed, a.scene, a.particles.string(), a.out);
  } catch (const std::exception& e) {
    std::cerr << "sqdem analyse: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace sqdem::cli
